#pragma once

#include <filesystem>
#include <istream>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "io/ObjLoader.h"

namespace tinyobj {
struct material_t;
}

namespace lancer {

class Material;
class Texture;

// Turns MTL materials, as tinyobjloader reads them, into ours, loading each texture once. The
// mapping of the MTL keys and illumination models is explained in the .cpp.
class MtlMaterialConverter {
public:
    // Problems (unknown illum, textures that cannot be loaded...) are appended to `warnings`.
    MtlMaterialConverter(const ObjLoader::TextureLoader& loadTexture,
                         std::vector<std::string>& warnings);

    // The text of an MTL file with every material's keys first set to values that no file
    // writes: what tinyobjloader then reads from it lets convert() tell the keys left out.
    static std::string markAbsentKeys(std::istream& mtl);

    // Ours for `mtl`, which tinyobjloader read from the marked text (see markAbsentKeys) of the
    // MTL file at mtlPath; texture paths are relative to that file.
    std::shared_ptr<const Material> convert(const tinyobj::material_t& mtl,
                                            const std::filesystem::path& mtlPath);

private:
    // Null when the texture cannot be loaded (with one warning per texture file).
    std::shared_ptr<const Texture> diffuseTexture(const tinyobj::material_t& mtl,
                                                  const std::filesystem::path& mtlPath);
    // Exporters often write absolute paths of the author's machine: when the path leads nowhere,
    // the file of that name next to the MTL is taken instead.
    static std::filesystem::path findTexture(const std::filesystem::path& mtlFolder,
                                             const std::string& name);

    const ObjLoader::TextureLoader& loadTexture_;
    std::vector<std::string>& warnings_;
    std::map<std::filesystem::path, std::shared_ptr<const Texture>> textures_;
};

}  // namespace lancer
