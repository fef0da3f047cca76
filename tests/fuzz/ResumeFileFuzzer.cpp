// libFuzzer target: the reader of resume files (--resume). A damaged or foreign file must be an
// InputError; anything else is a finding. The input is a resume file without its final checksum,
// which the target appends (a mutation would otherwise be refused at the checksum, never reaching
// the tiles), and the file is read for the render its header names when that is a sensible one
// (as lancer would, whose image sizes are checked before), else for a fixed small render.

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

#include "FuzzFolder.h"
#include "io/Fingerprint.h"
#include "io/ResumeFile.h"
#include "scene/InputError.h"

namespace {

// The header's fields the render is named by, at their offsets after the 16 bytes of magic.
struct NamedRender {
    std::uint64_t fingerprint = 1;
    std::int32_t width = 40, height = 24;
    lancer::PixelWindow window{0, 0, 40, 24};
    std::uint32_t aovCount = 1;
};

NamedRender renderNamedBy(const std::string& bytes) {
    NamedRender named;
    constexpr std::size_t kMagic = 16, kFields = 8 + 6 * 4 + 4;
    if (bytes.size() < kMagic + kFields) return named;
    NamedRender read;
    const char* at = bytes.data() + kMagic;
    std::memcpy(&read.fingerprint, at, 8);
    std::memcpy(&read.width, at + 8, 4);
    std::memcpy(&read.height, at + 12, 4);
    std::memcpy(&read.window.x0, at + 16, 4);
    std::memcpy(&read.window.y0, at + 20, 4);
    std::memcpy(&read.window.x1, at + 24, 4);
    std::memcpy(&read.window.y1, at + 28, 4);
    std::memcpy(&read.aovCount, at + 32, 4);
    const lancer::PixelWindow& w = read.window;
    const bool sensible = read.width >= 1 && read.width <= 256 && read.height >= 1 &&
                          read.height <= 256 && w.x0 >= 0 && w.y0 >= 0 && w.x0 < w.x1 &&
                          w.y0 < w.y1 && w.x1 <= read.width && w.y1 <= read.height &&
                          read.aovCount <= 3;
    return sensible ? read : named;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::string bytes(lancer::fuzz::asText(data, size));
    const std::uint64_t checksum = lancer::Fingerprint().addText(bytes).value();
    bytes.append(reinterpret_cast<const char*>(&checksum), sizeof checksum);
    const NamedRender named = renderNamedBy(bytes);
    const auto path = lancer::fuzz::FuzzFolder::write("out.pfm.resume", bytes);
    try {
        lancer::ResumeFile::read(path, named.fingerprint, named.width, named.height, named.window,
                                 named.aovCount);
    } catch (const lancer::InputError&) {
    }
    return 0;
}
