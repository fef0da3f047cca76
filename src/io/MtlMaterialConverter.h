#pragma once

#include <filesystem>
#include <istream>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "io/ObjLoader.h"

namespace tinyobj {
struct material_t;
}

namespace lancer {

class Material;
class ShadingNormalMap;
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
    // The texture that key `key` of `mtl` names (file `name`), of colour or of data; null when it
    // cannot be loaded, with one warning per texture file saying what is used instead.
    std::shared_ptr<const Texture> readTexture(const tinyobj::material_t& mtl,
                                               const std::filesystem::path& mtlPath,
                                               const std::string& key, const std::string& name,
                                               ImageReader::Content content,
                                               const std::string& instead);
    // The normal map (norm) or else the bump map (bump, map_Bump, with -bm) of `mtl`, or null.
    std::shared_ptr<const ShadingNormalMap> shadingNormalMap(const tinyobj::material_t& mtl,
                                                             const std::filesystem::path& mtlPath);
    // Exporters often write absolute paths of the author's machine: when the path leads nowhere,
    // the file of that name next to the MTL is taken instead.
    static std::filesystem::path findTexture(const std::filesystem::path& mtlFolder,
                                             const std::string& name);

    const ObjLoader::TextureLoader& loadTexture_;
    std::vector<std::string>& warnings_;
    std::map<std::pair<std::filesystem::path, ImageReader::Content>, std::shared_ptr<const Texture>>
        textures_;
};

}  // namespace lancer
