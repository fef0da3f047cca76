#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "geometry/TriangleMesh.h"

namespace lancer {

// Reads a glTF 2.0 model (.gltf with its buffers and images, or embedded data; .glb) into one
// triangle mesh: every triangle primitive of every mesh of the default scene, placed by its node's
// transform (its ancestors' composed), with the metallic-roughness materials mapped onto ours
// (the mapping is explained in the .cpp).
class GltfLoader {
public:
    // Throws InputError naming the file when it is missing, unreadable, malformed (an accessor
    // beyond its buffer, an index beyond the vertices, a node hierarchy with a cycle) or holds
    // no triangles. What lancer cannot show (skins, morph targets, animations, cameras, lights
    // and other extensions) is appended to `warnings` as "file: warning: message", one per kind.
    // The files the model's buffers and images were read from (beside a .gltf) are appended to
    // `externalFiles`, if given: what a render of it depends on besides the model's own file.
    static std::shared_ptr<TriangleMesh> load(
        const std::filesystem::path& path, std::vector<std::string>& warnings,
        std::vector<std::filesystem::path>* externalFiles = nullptr);
};

}  // namespace lancer
