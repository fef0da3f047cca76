#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "geometry/TriangleMesh.h"

namespace lancer {

// Reads a PLY model (ASCII, or binary of either byte order) into one triangle mesh: positions,
// vertex normals (nx, ny, nz) where given, uvs (u/v, s/t, texture_u/texture_v) where given, and
// the faces, triangulated. PLY has no materials: the mesh has one default material, which the
// scene's replaces.
class PlyLoader {
public:
    // Whether `path` is to be read as PLY: named .ply, or a file whose first line is "ply"
    // (PLY's magic line), whatever its name.
    static bool isPly(const std::filesystem::path& path);

    // Throws InputError naming the file when it is missing, unreadable, not PLY, truncated,
    // malformed (a face's vertex index out of range) or has no faces. What lancer does not use
    // (vertex colours, points and lines) is appended to `warnings` as "file: warning: message".
    static std::shared_ptr<TriangleMesh> load(const std::filesystem::path& path,
                                              std::vector<std::string>& warnings);
};

}  // namespace lancer
