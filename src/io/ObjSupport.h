#pragma once

#include <algorithm>
#include <cstddef>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "geometry/PolygonTriangulator.h"
#include "math/Vec3.h"

namespace lancer {

// What the model loaders (OBJ and its MTL material converter, PLY) share: warnings in the loaders'
// format, names quoted and things counted in messages, the file names written inside OBJ and
// MTL files, and how a file's normals and faces become the mesh's.

inline void warn(std::vector<std::string>& warnings, const std::filesystem::path& file,
                 const std::string& message) {
    warnings.push_back(file.string() + ": warning: " + message);
}

inline std::string inQuotes(const std::string& s) {
    return "\"" + s + "\"";
}

// "1 face", "3 faces".
inline std::string countOf(std::size_t count, const std::string& noun) {
    return std::to_string(count) + " " + noun + (count == 1 ? "" : "s");
}

// A file named inside an OBJ or MTL file: relative to that file's folder, and written with
// Windows separators as often as not.
inline std::filesystem::path resolvePath(const std::filesystem::path& folder, std::string name) {
    std::replace(name.begin(), name.end(), '\\', '/');
    const std::filesystem::path path(name);
    return (path.is_absolute() ? path : folder / path).lexically_normal();
}

// A normal as given in a model, normalised; a zero or broken one stays zero: "none", shaded flat.
inline Vec3 usableNormal(const Vec3& given) {
    return isFinite(given) && length(given) > 0 ? normalize(given) : Vec3();
}

// A face split as every loader splits its faces (ear clipping: concave ones right), less its
// zero-area triangles, whose count is returned.
inline std::size_t triangulateLessZeroArea(
    std::span<const Vec3> corners, std::vector<PolygonTriangulator::CornerTriple>& triangles) {
    PolygonTriangulator::triangulate(corners, triangles);
    return std::erase_if(triangles, [&](const PolygonTriangulator::CornerTriple& t) {
        const Vec3& p0 = corners[t[0]];
        return !(length(cross(corners[t[1]] - p0, corners[t[2]] - p0)) > 0);
    });
}

}  // namespace lancer
