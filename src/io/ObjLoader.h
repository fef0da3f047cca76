#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "geometry/TriangleMesh.h"
#include "io/ImageReader.h"
#include "io/ObjCompletion.h"

namespace lancer {

class Material;
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

    // The files a model is read from, each by its path, size and time of change
    // (Fingerprint::addFile): the OBJ, and the MTL files its libraries name, found or not.
    struct SourceFiles {
        std::uint64_t obj = 0;
        std::uint64_t libraries = 0;
    };

    // load() in its two steps, so that the model cache can keep the first one's result: the
    // triangles (their faces' material indices set, their materials not made yet) and what
    // completes them, which complete() then turns into the materials, adding the reading's
    // warnings to `warnings` in the order load() gives them.
    struct Geometry {
        std::shared_ptr<TriangleMesh> triangles;
        ObjCompletion completion;
        // Each file as it was just before it was read: a file changed while the model was read
        // then differs from it, and is never taken for the file the geometry came from.
        SourceFiles sources;
    };
    static Geometry readGeometry(const std::filesystem::path& objPath);
    static std::vector<std::shared_ptr<const Material>> complete(
        const std::filesystem::path& objPath, const ObjCompletion& completion,
        const TextureLoader& loadTexture, std::vector<std::string>& warnings,
        std::vector<std::filesystem::path>* materialFiles = nullptr);
    // The files of the model at `objPath` completed by `completion`, as they are now.
    static SourceFiles sourceFiles(const std::filesystem::path& objPath,
                                   const ObjCompletion& completion);
};

}  // namespace lancer
