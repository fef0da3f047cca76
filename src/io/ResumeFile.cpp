#include "io/ResumeFile.h"

#include <cstring>
#include <stdexcept>
#include <string>
#include <string_view>

#include "io/AtomicFile.h"
#include "io/Fingerprint.h"
#include "io/InputFile.h"
#include "render/Renderer.h"
#include "scene/InputError.h"
#include "util/ByteAppend.h"
#include "util/ByteReader.h"

namespace lancer {

namespace {

constexpr char kMagic[16] = {'l', 'a', 'n', 'c', 'e', 'r', ' ', 'r',
                             'e', 's', 'u', 'm', 'e', ' ', '1', '\n'};

// The header after the magic: what the file was made for, and the counts of its render.
struct Header {
    std::uint64_t fingerprint;
    std::int32_t width, height;
    std::int32_t x0, y0, x1, y1;  // the window rendered
    std::uint32_t aovCount, tileCount;
    std::uint64_t rays, samples, pixels, nonFiniteSamples;
};
static_assert(sizeof(Header) == 72, "no padding: every byte of the file is checksummed");

std::uint64_t checksum(std::string_view bytes) {
    return Fingerprint().addText(bytes).value();
}

}  // namespace

std::filesystem::path ResumeFile::pathBeside(const std::filesystem::path& output) {
    std::filesystem::path path = output;
    path += ".resume";
    return path;
}

std::uintmax_t ResumeFile::maxBytes(int width, int height, std::size_t aovCount) {
    const std::uintmax_t pixels =
        static_cast<std::uintmax_t>(width) * static_cast<std::uintmax_t>(height);
    const std::uintmax_t tiles = pixels;  // at least a pixel each
    return sizeof kMagic + sizeof(Header) + tiles + pixels * 3 * sizeof(float) * (1 + aovCount) +
           sizeof(std::uint64_t);
}

void ResumeFile::write(const std::filesystem::path& path, std::uint64_t fingerprint,
                       const PixelWindow& window, const RenderResult& partial) {
    const std::vector<PixelWindow> tiles = Renderer::tiles(window);
    if (partial.finishedTiles.size() != tiles.size())
        throw std::invalid_argument("the render to save is not of this window");
    const RenderCounters& c = partial.counters;
    const Header header{fingerprint,
                        partial.film.width(),
                        partial.film.height(),
                        window.x0,
                        window.y0,
                        window.x1,
                        window.y1,
                        static_cast<std::uint32_t>(partial.aovFilms.size()),
                        static_cast<std::uint32_t>(tiles.size()),
                        c.rays,
                        c.samples,
                        c.pixels,
                        c.nonFiniteSamples};
    std::string bytes(kMagic, sizeof kMagic);
    appendBytes(bytes, header);
    for (const bool finished : partial.finishedTiles)
        appendBytes(bytes, static_cast<std::uint8_t>(finished));
    for (std::size_t t = 0; t < tiles.size(); ++t) {
        if (!partial.finishedTiles[t]) continue;
        const auto appendTile = [&](const Image& film) {
            for (int y = tiles[t].y0; y < tiles[t].y1; ++y)
                for (int x = tiles[t].x0; x < tiles[t].x1; ++x)
                    for (const float channel : {film.at(x, y).r, film.at(x, y).g, film.at(x, y).b})
                        appendBytes(bytes, channel);
        };
        appendTile(partial.film);
        for (const Image& aov : partial.aovFilms)
            appendTile(aov);
    }
    appendBytes(bytes, checksum(bytes));

    AtomicFile::write(path, bytes.data(), bytes.size(), "resume file");
}

RenderResult ResumeFile::read(const std::filesystem::path& path, std::uint64_t fingerprint,
                              int width, int height, const PixelWindow& window,
                              std::size_t aovCount) {
    const std::string bytes =
        InputFile::read(path, "a resume file", "resume files", maxBytes(width, height, aovCount));
    const auto refuse = [&](const std::string& why) {
        throw InputError(path.string(), why + "; delete it to render the whole image again");
    };
    if (bytes.size() < sizeof kMagic || std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0)
        refuse("not a lancer resume file");
    ByteReader reader(
        bytes, [&](const std::string& what) { refuse("the resume file " + what + " (damaged?)"); });
    reader.readBytes(sizeof kMagic);
    const auto header = reader.read<Header>();
    // The checksum first: a damaged file says so, not that it belongs to another render.
    if (bytes.size() < sizeof kMagic + sizeof(Header) + sizeof(std::uint64_t))
        reader.fail("is truncated");
    const std::string_view content(bytes.data(), bytes.size() - sizeof(std::uint64_t));
    std::uint64_t stored;
    std::memcpy(&stored, bytes.data() + content.size(), sizeof stored);
    if (stored != checksum(content)) refuse("the resume file is damaged (truncated or altered)");
    const std::vector<PixelWindow> tiles = Renderer::tiles(window);
    if (header.fingerprint != fingerprint || header.width != width || header.height != height ||
        header.x0 != window.x0 || header.y0 != window.y0 || header.x1 != window.x1 ||
        header.y1 != window.y1 || header.aovCount != aovCount || header.tileCount != tiles.size())
        refuse(
            "the resume file was made for another render (the program, the scene, one of its "
            "files or an option that changes the image is not the same)");

    RenderResult partial{Image(width, height)};
    for (std::size_t i = 0; i < aovCount; ++i)
        partial.aovFilms.emplace_back(width, height);
    partial.counters = {header.rays, header.samples, header.pixels, header.nonFiniteSamples};
    partial.finishedTiles.resize(tiles.size());
    for (std::size_t t = 0; t < tiles.size(); ++t) {
        const auto flag = reader.read<std::uint8_t>();
        if (flag > 1) reader.fail("holds a tile that is neither finished nor not");
        partial.finishedTiles[t] = flag == 1;
    }
    for (std::size_t t = 0; t < tiles.size(); ++t) {
        if (!partial.finishedTiles[t]) continue;
        const auto readTile = [&](Image& film) {
            for (int y = tiles[t].y0; y < tiles[t].y1; ++y)
                for (int x = tiles[t].x0; x < tiles[t].x1; ++x) {
                    Color& c = film.at(x, y);
                    c.r = reader.readFinite();
                    c.g = reader.readFinite();
                    c.b = reader.readFinite();
                }
        };
        readTile(partial.film);
        for (Image& aov : partial.aovFilms)
            readTile(aov);
    }
    reader.read<std::uint64_t>();  // the checksum, checked above
    if (!reader.atEnd()) reader.fail("has bytes after its end");
    return partial;
}

}  // namespace lancer
