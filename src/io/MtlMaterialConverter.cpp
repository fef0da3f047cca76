// MTL keys, mapped onto the scene format's material (a key a material leaves out takes the scene
// format's default):
//   Kd      diffuse colour (absent: 0.8)
//   map_Kd  diffuse texture, through the caller's TextureLoader; it replaces Kd. A texture that
//           cannot be loaded leaves Kd, with a warning. Texture options (-s, -o...) are ignored.
//   Ka      ambient colour; absent or black: the diffuse colour or texture (the format's default)
//   Ks      highlight colour, and the mirror reflection of the reflecting models below
//   Ns      shininess (absent: 32)
//   Ni      ior (absent: 1.5)
//   d / Tr  dissolve d is the opacity (Tr = 1 - d; d wins when both are given). A surface with
//           d < 1 gets transmission 1 - d with ior 1: see-through without bending light, as
//           dissolve is. Glass models are clear whatever d says.
//   Ke      emission; an emissive triangle is an ordinary triangle with an emissive material
//   norm    normal map (tangent space, read as data); it wins over a bump map, with a warning
//   bump / map_Bump  bump map (read as data), its -bm multiplier the bump_scale (absent: 1)
//   Tf and the other maps (map_Ka, map_Ks, map_d...) are not used.
//
// illum (absent: 2)                              specular  reflection  transmission
//   0  colour on, ambient off                    0         0           1 - d
//      A constant colour that no light changes is an emitter: Kd is added to the emission and the
//      diffuse and ambient colours are black (map_Kd is not shown, with a warning).
//   1  colour and ambient on                     0         0           1 - d
//   2  highlights on                             Ks        0           1 - d
//   3  mirror (reflection, ray trace on)         Ks        Ks          1 - d
//   4  glass, ray-traced reflection              Ks        Ks          1, ior Ni
//   5  Fresnel mirror                            Ks        Ks          1 - d
//      Our Fresnel term only splits refracting materials, and a metal mirror's reflectance hardly
//      changes with the angle: a plain mirror of Ks is the closest.
//   6  refraction, Fresnel off                   Ks        Ks          1, ior Ni
//   7  refraction, Fresnel on                    Ks        0           1, ior Ni
//      A clear dielectric: transmission splits itself into reflection kt F and refraction
//      kt (1 - F), so Fresnel alone reflects. In 4 and 6 the mirror Ks is added on top of it.
//   8  reflection, ray trace off                 as 3 (reflections are always traced)
//   9  glass, ray trace off                      as 7
//   10 casts shadows onto invisible surfaces     as 1
//   Other values are used as 2, with a warning.

#include "io/MtlMaterialConverter.h"

#include <tiny_obj_loader.h>

#include <array>
#include <cmath>
#include <istream>

#include "io/ObjSupport.h"
#include "materials/BlinnPhongMaterial.h"
#include "materials/BumpMap.h"
#include "materials/ConstantTexture.h"
#include "materials/NormalMap.h"
#include "math/Float.h"
#include "scene/InputError.h"

namespace lancer {

namespace fs = std::filesystem;

namespace {

// tinyobjloader gives a key that a material leaves out the same value that a file may write
// (illum 0, Ns 1, Ni 1, Kd 0), but here absent keys take the scene format's defaults. So every
// material starts with these impossible values, which the file's own lines then overwrite.
constexpr const char* kAbsentKeys = "Kd -1 -1 -1\nNs -1\nNi -1\nillum -1\n";
constexpr tinyobj::real_t kAbsent = -1;
constexpr int kAbsentIllum = -1;

bool startsMaterial(const std::string& line) {
    const std::size_t start = line.find_first_not_of(" \t");
    return start != std::string::npos && line.compare(start, 6, "newmtl") == 0 &&
           start + 6 < line.size() && (line[start + 6] == ' ' || line[start + 6] == '\t');
}

struct IlluminationModel {
    bool lit;         // false: a constant colour (illum 0)
    bool highlights;  // Ks as Blinn-Phong highlights
    bool mirror;      // Ks as mirror reflection
    bool glass;       // clear, refracting with ior Ni
};

// Indexed by illum; see the table at the top of the file.
constexpr std::array<IlluminationModel, 11> kIlluminationModels{{
    {false, false, false, false},  // 0
    {true, false, false, false},   // 1
    {true, true, false, false},    // 2
    {true, true, true, false},     // 3
    {true, true, true, true},      // 4
    {true, true, true, false},     // 5
    {true, true, true, true},      // 6
    {true, true, false, true},     // 7
    {true, true, true, false},     // 8
    {true, true, false, true},     // 9
    {true, false, false, false},   // 10
}};
constexpr int kDefaultIllum = 2;
constexpr float kDefaultDiffuse = 0.8f;  // the scene format's

bool isGiven(const tinyobj::real_t* rgb) {
    return rgb[0] != kAbsent;
}

// Negative and non-finite components are read as 0.
Color colorOf(const tinyobj::real_t* rgb) {
    const auto component = [](tinyobj::real_t v) { return std::isfinite(v) && v > 0 ? v : 0; };
    return {component(rgb[0]), component(rgb[1]), component(rgb[2])};
}

// The model of the material's illum (a warning when illum is not one).
const IlluminationModel& illuminationModel(const tinyobj::material_t& mtl, const fs::path& mtlPath,
                                           std::vector<std::string>& warnings) {
    if (mtl.illum == kAbsentIllum) return kIlluminationModels[kDefaultIllum];
    if (mtl.illum >= 0 && mtl.illum < int(kIlluminationModels.size()))
        return kIlluminationModels[std::size_t(mtl.illum)];
    warn(warnings, mtlPath,
         "material " + inQuotes(mtl.name) + " has illum " + std::to_string(mtl.illum) +
             ", which is not an illumination model (0 to 10); illum " +
             std::to_string(kDefaultIllum) + " is used");
    return kIlluminationModels[kDefaultIllum];
}

}  // namespace

std::string MtlMaterialConverter::markAbsentKeys(std::istream& mtl) {
    std::string marked, line;
    while (std::getline(mtl, line)) {
        marked += line + "\n";
        if (startsMaterial(line)) marked += kAbsentKeys;
    }
    return marked;
}

MtlMaterialConverter::MtlMaterialConverter(const ObjLoader::TextureLoader& loadTexture,
                                           std::vector<std::string>& warnings)
    : loadTexture_(loadTexture), warnings_(warnings) {}

std::shared_ptr<const Material> MtlMaterialConverter::convert(const tinyobj::material_t& mtl,
                                                              const fs::path& mtlPath) {
    const IlluminationModel& model = illuminationModel(mtl, mtlPath, warnings_);
    BlinnPhongMaterial::Parameters material;
    const Color kd = isGiven(mtl.diffuse) ? colorOf(mtl.diffuse) : Color(kDefaultDiffuse);
    const Color ka = colorOf(mtl.ambient), ks = colorOf(mtl.specular);
    material.emission = colorOf(mtl.emission);
    // map_Ke multiplies Ke, as map_Ks multiplies Ks.
    if (!material.emission.isBlack() && !mtl.emissive_texname.empty())
        material.emissionMap = readTexture(mtl, mtlPath, "map_Ke", mtl.emissive_texname,
                                           ImageReader::Content::Color, "Ke is used alone");
    if (model.lit) {
        std::shared_ptr<const Texture> texture;
        if (!mtl.diffuse_texname.empty())
            texture = readTexture(mtl, mtlPath, "map_Kd", mtl.diffuse_texname,
                                  ImageReader::Content::Color, "the Kd colour is used instead");
        material.diffuse = texture ? texture : std::make_shared<ConstantTexture>(kd);
        material.ambient = ka.isBlack() ? material.diffuse : std::make_shared<ConstantTexture>(ka);
    } else {
        material.emission += kd;
        material.diffuse = material.ambient = std::make_shared<ConstantTexture>(Color(0));
        if (!mtl.diffuse_texname.empty())
            warn(warnings_, mtlPath,
                 "material " + inQuotes(mtl.name) +
                     " is illum 0, an unlit constant colour: it shows its Kd colour, not "
                     "its map_Kd texture");
    }
    if (model.highlights) {
        material.specular = ks;
        // As the MTL definition has it, map_Ks multiplies Ks.
        if (!mtl.specular_texname.empty())
            material.specularMap =
                readTexture(mtl, mtlPath, "map_Ks", mtl.specular_texname,
                            ImageReader::Content::Color, "the Ks colour is used alone");
    }
    if (model.mirror) material.reflection = ks;
    if (mtl.shininess >= 0) material.shininess = mtl.shininess;
    if (mtl.ior > 0) material.ior = mtl.ior;
    const float opacity = std::isfinite(mtl.dissolve) ? clamp(mtl.dissolve, 0.0f, 1.0f) : 1;
    if (model.glass) {
        material.transmission = Color(1);
    } else if (opacity < 1) {
        material.transmission = Color(1 - opacity);
        material.ior = 1;
    }
    auto converted = std::make_shared<BlinnPhongMaterial>(std::move(material));
    converted->setShadingNormalMap(shadingNormalMap(mtl, mtlPath));
    if (!mtl.alpha_texname.empty())
        converted->setOpacity(readTexture(mtl, mtlPath, "map_d", mtl.alpha_texname,
                                          ImageReader::Content::Alpha, "the surface is whole"));
    return converted;
}

std::shared_ptr<const ShadingNormalMap> MtlMaterialConverter::shadingNormalMap(
    const tinyobj::material_t& mtl, const fs::path& mtlPath) {
    constexpr const char* kUnmapped = "the surface is shaded without it";
    if (!mtl.normal_texname.empty()) {
        if (!mtl.bump_texname.empty())
            warn(warnings_, mtlPath,
                 "material " + inQuotes(mtl.name) +
                     " has both a normal map (norm) and a bump map; the normal map is used");
        const auto texels = readTexture(mtl, mtlPath, "norm", mtl.normal_texname,
                                        ImageReader::Content::Data, kUnmapped);
        return texels ? std::make_shared<NormalMap>(texels) : nullptr;
    }
    if (mtl.bump_texname.empty()) return nullptr;
    const auto heights =
        readTexture(mtl, mtlPath, "bump", mtl.bump_texname, ImageReader::Content::Data, kUnmapped);
    const float scale = mtl.bump_texopt.bump_multiplier;
    return heights && std::isfinite(scale) ? std::make_shared<BumpMap>(heights, scale) : nullptr;
}

std::shared_ptr<const Texture> MtlMaterialConverter::readTexture(
    const tinyobj::material_t& mtl, const fs::path& mtlPath, const std::string& key,
    const std::string& name, ImageReader::Content content, const std::string& instead) {
    const fs::path path = findTexture(mtlPath.parent_path(), name);
    const auto [cached, isNew] = textures_.try_emplace({path, content});
    if (!isNew) return cached->second;
    try {
        cached->second = loadTexture_(path, content);
    } catch (const InputError& error) {
        warn(warnings_, mtlPath,
             "texture " + inQuotes(path.string()) + " (" + key + " of material " +
                 inQuotes(mtl.name) + ") cannot be loaded; " + instead + " (" + error.message() +
                 ")");
    }
    return cached->second;
}

fs::path MtlMaterialConverter::findTexture(const fs::path& mtlFolder, const std::string& name) {
    const fs::path path = resolvePath(mtlFolder, name);
    const fs::path besideMtl = mtlFolder / path.filename();
    std::error_code error;
    if (!fs::exists(path, error) && fs::exists(besideMtl, error)) return besideMtl;
    return path;
}

}  // namespace lancer
