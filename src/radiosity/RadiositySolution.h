#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <vector>

#include "accel/Bvh.h"
#include "math/Color.h"
#include "math/Vec3.h"
#include "radiosity/RadiosityStatistics.h"

namespace lancer {

// A solved radiosity solution, independent of the view: the leaf elements with, at each of their
// corners, the irradiance on both sides, for smooth (Gouraud) interpolation, and the part of it
// straight from the sampled emitters (SplitIrradiance), so that a render may compute that part
// itself with shadow rays. It is saved to and loaded from files, which hold the fingerprint of
// the scene they were solved for.
class RadiositySolution {
public:
    RadiositySolution() = default;
    RadiositySolution(std::vector<std::array<Vec3, 3>> faces,
                      std::vector<std::array<std::uint32_t, 3>> faceVertices,
                      std::vector<std::array<Color, 2>> vertexIrradiance,
                      std::vector<std::array<Color, 2>> vertexDirect, float lookupDistance,
                      std::uint64_t fingerprint, const RadiosityStatistics& statistics);

    // What irradiance() gives: all of it, or all but the sampled emitters' direct light.
    enum class Part { All, Indirect };

    // The irradiance at p, on a surface of geometric normal ng, on the side `towardsViewer`
    // points to: interpolated over the element found under p within the lookup distance along
    // ng. Nothing when no element is there (beyond a clipped plane, a shape not meshed).
    std::optional<Color> irradiance(const Vec3& p, const Vec3& ng, const Vec3& towardsViewer,
                                    Part part = Part::All) const;

    std::size_t faceCount() const { return faces_.size(); }
    std::uint64_t fingerprint() const { return fingerprint_; }
    const RadiosityStatistics& statistics() const { return statistics_; }

    // Writes the solution (through a temporary file renamed into place); throws
    // std::runtime_error when it cannot.
    void save(const std::filesystem::path& path) const;
    // The largest solution file read (a solution of 4 GiB holds some 50 million patches).
    static constexpr std::uintmax_t kMaxFileBytes = std::uintmax_t{4} << 30;

    // Reads a saved solution; throws InputError naming the file when it cannot be read or is
    // damaged, or when it (or a pipe) holds more than kMaxFileBytes. The caller refuses devices
    // (/dev/zero) and folders before (io/InputFile).
    static RadiositySolution load(const std::filesystem::path& path);

private:
    void buildLookup();

    std::vector<std::array<Vec3, 3>> faces_;  // in the lookup BVH's leaf order once built
    std::vector<std::array<std::uint32_t, 3>> faceVertices_;
    std::vector<std::array<Color, 2>> vertexIrradiance_;  // front, back
    std::vector<std::array<Color, 2>> vertexDirect_;      // its direct part
    float lookupDistance_ = 0;
    std::uint64_t fingerprint_ = 0;
    RadiosityStatistics statistics_;
    Bvh lookup_;
};

}  // namespace lancer
