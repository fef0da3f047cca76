#include "radiosity/RadiositySolution.h"

#include <cmath>
#include <cstring>
#include <fstream>
#include <stdexcept>

#include "geometry/Triangle.h"
#include "scene/InputError.h"
#include "util/ByteReader.h"

namespace lancer {

namespace {

constexpr char kMagic[16] = {'l', 'a', 'n', 'c', 'e', 'r', ' ', 'r',
                             'a', 'd', 'i', 'o', 's', 'i', 't', 'y'};
// 2: the statistics count the links; 3: the vertices' direct part.
constexpr std::uint32_t kVersion = 3;

template <typename T>
void write(std::ostream& out, const T& value) {
    out.write(reinterpret_cast<const char*>(&value), sizeof(T));
}

}  // namespace

RadiositySolution::RadiositySolution(std::vector<std::array<Vec3, 3>> faces,
                                     std::vector<std::array<std::uint32_t, 3>> faceVertices,
                                     std::vector<std::array<Color, 2>> vertexIrradiance,
                                     std::vector<std::array<Color, 2>> vertexDirect,
                                     float lookupDistance, std::uint64_t fingerprint,
                                     const RadiosityStatistics& statistics)
    : faces_(std::move(faces)),
      faceVertices_(std::move(faceVertices)),
      vertexIrradiance_(std::move(vertexIrradiance)),
      vertexDirect_(std::move(vertexDirect)),
      lookupDistance_(lookupDistance),
      fingerprint_(fingerprint),
      statistics_(statistics) {
    buildLookup();
}

void RadiositySolution::buildLookup() {
    std::vector<Bounds3> bounds;
    bounds.reserve(faces_.size());
    for (const auto& f : faces_)
        bounds.push_back(merge(Bounds3(f[0], f[1]), f[2]));
    lookup_ = Bvh(bounds);
    std::vector<std::array<Vec3, 3>> faces;
    std::vector<std::array<std::uint32_t, 3>> vertices;
    for (std::uint32_t i : lookup_.primitiveOrder()) {
        faces.push_back(faces_[i]);
        vertices.push_back(faceVertices_[i]);
    }
    faces_ = std::move(faces);
    faceVertices_ = std::move(vertices);
}

std::optional<Color> RadiositySolution::irradiance(const Vec3& p, const Vec3& ng,
                                                   const Vec3& towardsViewer, Part part) const {
    // A short ray through p along the normal finds the element under p; of several (surfaces
    // closer together than the lookup distance), the one nearest p that faces the same way.
    const Ray probe{p + lookupDistance_ * ng, -ng};
    float tMax = 2 * lookupDistance_;
    std::optional<std::uint32_t> best;
    TriangleIntersection bestAt{};
    float bestGap = kInfinity;
    lookup_.intersect(probe, tMax, [&](std::uint32_t k, const Ray& ray, float& limit) {
        const auto& f = faces_[k];
        const auto at = Triangle::intersect(f[0], f[1], f[2], ray, limit);
        if (!at) return false;
        const Vec3 n = normalize(cross(f[1] - f[0], f[2] - f[0]));
        if (std::abs(dot(n, ng)) < 0.5f) return false;
        const float gap = std::abs(at->t - lookupDistance_);
        if (gap < bestGap) {
            bestGap = gap;
            best = k;
            bestAt = *at;
        }
        return false;  // keep looking: the nearest to p wins, not the first along the probe
    });
    if (!best) return std::nullopt;
    const auto& f = faces_[*best];
    // The side is the true surface's (ng): seen at a grazing angle, a curved surface's viewer may
    // be on the other side of the flat element under it.
    const bool elementFacesAsNg = dot(cross(f[1] - f[0], f[2] - f[0]), ng) >= 0;
    const std::size_t side = (dot(ng, towardsViewer) >= 0) == elementFacesAsNg ? 0 : 1;
    const auto& v = faceVertices_[*best];
    const auto at = [&](std::uint32_t vertex) {
        const Color& total = vertexIrradiance_[vertex][side];
        return part == Part::All ? total : total - vertexDirect_[vertex][side];
    };
    return bestAt.b0 * at(v[0]) + bestAt.b1 * at(v[1]) + bestAt.b2 * at(v[2]);
}

void RadiositySolution::save(const std::filesystem::path& path) const {
    std::filesystem::path temporary = path;
    temporary += ".tmp";
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        if (!out) throw std::runtime_error(path.string() + ": cannot write the radiosity file");
        out.write(kMagic, sizeof kMagic);
        write(out, kVersion);
        write(out, fingerprint_);
        write(out, statistics_);
        write(out, lookupDistance_);
        write(out, static_cast<std::uint64_t>(vertexIrradiance_.size()));
        for (std::size_t v = 0; v < vertexIrradiance_.size(); ++v)
            for (const auto* sides : {&vertexIrradiance_[v], &vertexDirect_[v]})
                for (const Color& c : *sides)
                    for (float channel : {c.r, c.g, c.b})
                        write(out, channel);
        write(out, static_cast<std::uint64_t>(faces_.size()));
        for (std::size_t i = 0; i < faces_.size(); ++i) {
            for (const Vec3& p : faces_[i])
                for (int axis = 0; axis < 3; ++axis)
                    write(out, p[axis]);
            for (std::uint32_t v : faceVertices_[i])
                write(out, v);
        }
        if (!out.flush())
            throw std::runtime_error(path.string() + ": cannot write the radiosity file");
    }
    std::error_code error;
    std::filesystem::rename(temporary, path, error);
    if (error) {
        std::filesystem::remove(temporary, error);
        throw std::runtime_error(path.string() + ": cannot write the radiosity file");
    }
}

RadiositySolution RadiositySolution::load(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in || std::filesystem::is_directory(path))
        throw InputError(path.string(), "cannot open the radiosity file (does it exist?)");
    // In blocks, so that a pipe that never ends stops at the limit.
    std::string bytes;
    std::string block(1 << 16, '\0');
    while (in.read(block.data(), static_cast<std::streamsize>(block.size())) || in.gcount() > 0) {
        bytes.append(block.data(), static_cast<std::size_t>(in.gcount()));
        if (bytes.size() > kMaxFileBytes)
            throw InputError(path.string(), "is larger than the " +
                                                std::to_string(kMaxFileBytes >> 30) +
                                                " GiB limit for radiosity files");
    }
    ByteReader reader(bytes, [&](const std::string& what) {
        throw InputError(path.string(), "the radiosity file " + what + " (damaged?)");
    });
    if (bytes.size() < sizeof kMagic || std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0)
        throw InputError(path.string(), "not a lancer radiosity file");
    for (std::size_t i = 0; i < sizeof kMagic; ++i)
        reader.read<char>();
    if (reader.read<std::uint32_t>() != kVersion)
        throw InputError(path.string(), "a radiosity file of another version of lancer");
    RadiositySolution s;
    s.fingerprint_ = reader.read<std::uint64_t>();
    s.statistics_ = reader.read<RadiosityStatistics>();
    s.lookupDistance_ = reader.readFinite();
    const std::uint64_t vertexCount = reader.readCount(12 * sizeof(float));
    s.vertexIrradiance_.resize(vertexCount);
    s.vertexDirect_.resize(vertexCount);
    for (std::size_t v = 0; v < vertexCount; ++v)
        for (auto* sides : {&s.vertexIrradiance_[v], &s.vertexDirect_[v]})
            for (Color& c : *sides) {
                c.r = reader.readFinite();
                c.g = reader.readFinite();
                c.b = reader.readFinite();
            }
    const std::uint64_t faceCount = reader.readCount(9 * sizeof(float) + 3 * sizeof(std::uint32_t));
    s.faces_.resize(faceCount);
    s.faceVertices_.resize(faceCount);
    for (std::size_t i = 0; i < faceCount; ++i) {
        for (Vec3& p : s.faces_[i])
            for (int axis = 0; axis < 3; ++axis)
                p[axis] = reader.readFinite();
        for (std::uint32_t& v : s.faceVertices_[i]) {
            v = reader.read<std::uint32_t>();
            if (v >= vertexCount) reader.fail("names a vertex it does not hold");
        }
    }
    if (!reader.atEnd()) reader.fail("has bytes after its end");
    if (!(s.lookupDistance_ >= 0)) reader.fail("holds a negative distance");
    s.buildLookup();
    return s;
}

}  // namespace lancer
