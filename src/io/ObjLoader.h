#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "geometry/TriangleMesh.h"
#include "io/ImageReader.h"

namespace lancer {

class Texture;

// Reads a Wavefront OBJ model and the MTL materials it names into one triangle mesh.
class ObjLoader {
public:
    // Loads the image at a path, of colour or of data (normal and bump maps); throws InputError
    // when it cannot (the caller caches textures).
    using TextureLoader = std::function<std::shared_ptr<const Texture>(const std::filesystem::path&,
                                                                       ImageReader::Content)>;

    // Throws InputError naming the file when the OBJ itself is missing, unreadable, or unusable
    // (nothing in it can be rendered). Problems that still leave a mesh (a missing .mtl or
    // texture, faces dropped...) are appended to `warnings` as "file: warning: message", one per
    // kind of problem. With `materialFiles`, the MTL files read are added to it.
    static std::shared_ptr<TriangleMesh> load(
        const std::filesystem::path& objPath, const TextureLoader& loadTexture,
        std::vector<std::string>& warnings,
        std::vector<std::filesystem::path>* materialFiles = nullptr);
};

}  // namespace lancer
