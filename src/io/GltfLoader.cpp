// glTF 2.0 through tinygltf, which parses the JSON, reads the buffers (files, data URIs, the GLB
// chunk) and decodes the images (PNG, JPEG) to 8- or 16-bit RGBA.
//
// Geometry: the nodes of the default scene (the first when none is named), depth first, each
// mesh's triangle primitives (mode 4) with POSITION, NORMAL (smooth shading; without it flat) and
// TEXCOORD_0 (glTF's v runs down the image, ours up: v becomes 1 - v), in world space by the
// node's matrix or its translation * rotation * scale, composed with its ancestors'. A transform
// that mirrors turns the triangles' winding, so that their front stays outside.
//
// Materials (pbrMetallicRoughness onto the scene format's):
//   baseColorFactor x baseColorTexture   diffuse (the factor multiplied into the texels), sRGB
//   emissiveFactor (x emissiveStrength)  emission, times the emissiveTexture (sRGB) per texel
//   normalTexture                        normal_map (tangent space, linear; its scale is ignored)
//   metallicFactor m, roughnessFactor r  glTF's BRDF is mix(dielectric, metal, m), so ours is too:
//                                        diffuse (1 - m) x base colour, reflection m of a
//                                        conductor reflecting the base colour head-on
//                                        (conductorReflecting), roughness r^2 (GGX alpha). The
//                                        dielectric's specular layer (F0 = 0.04) is not drawn.
//   metallicRoughnessTexture             its mean blue (metallic) and green (roughness) times the
//                                        factors, since both are uniform over a material
//   base colour texture of a metal       the conductor's tint is its mean colour; the diffuse
//                                        part keeps the texels
// A material-less primitive gets glTF's default: white, metallic 1, roughness 1.

#include "io/GltfLoader.h"

#ifdef LANCER_TINYGLTF_HEADER_ONLY
// The bare header (vcpkg): its implementation, and stb's image decoder, are compiled here.
#define TINYGLTF_IMPLEMENTATION
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#endif
#include <tiny_gltf.h>

#include <algorithm>
#include <cctype>
#include <cstring>
#include <fstream>
#include <map>
#include <set>
#include <stdexcept>
#include <tuple>
#include <utility>

#include "image/Image.h"
#include "io/ImageReader.h"
#include "io/InputFile.h"
#include "io/ObjSupport.h"
#include "materials/BlinnPhongMaterial.h"
#include "materials/ConstantTexture.h"
#include "materials/ImageTexture.h"
#include "materials/MipMap.h"
#include "materials/NormalMap.h"
#include "materials/Optics.h"
#include "math/Srgb.h"
#include "math/Transform.h"
#include "scene/InputError.h"

namespace lancer {

namespace fs = std::filesystem;

namespace {

constexpr int kTriangles = 4;  // a primitive's mode
// The most elements an accessor may have (2^28, far beyond any model lancer renders): one
// without a buffer view is zeros, its count bounded by nothing else in the file.
constexpr std::size_t kMostAccessorElements = std::size_t{1} << 28;
// Extensions read, the others get a warning each.
constexpr const char* kEmissiveStrength = "KHR_materials_emissive_strength";

bool isBinaryGltf(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    char magic[4] = {};
    in.read(magic, 4);
    return in.gcount() == 4 && std::memcmp(magic, "glTF", 4) == 0;
}

// tinygltf's message, on one line.
std::string oneLine(std::string text) {
    while (!text.empty() && (text.back() == '\n' || text.back() == ' '))
        text.pop_back();
    for (char& c : text)
        if (c == '\n') c = ' ';
    return text;
}

// The colour of a factor (RGB or RGBA), or `absent` when the file has none of that size.
Color colorOf(const std::vector<double>& factor, const Color& absent) {
    if (factor.size() < 3) return absent;
    return {static_cast<float>(factor[0]), static_cast<float>(factor[1]),
            static_cast<float>(factor[2])};
}

// The mean of an image's texels, for what a material holds uniform.
Color meanColor(const Image& image) {
    Color sum;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            sum += image.at(x, y);
    return sum / static_cast<float>(image.width() * image.height());
}

// The node's own transform: its matrix (column-major), or translation * rotation * scale.
Transform::Matrix localMatrix(const tinygltf::Node& node) {
    Transform::Matrix m{};
    if (node.matrix.size() == 16) {
        for (int row = 0; row < 4; ++row)
            for (int column = 0; column < 4; ++column)
                m[row][column] = static_cast<float>(node.matrix[std::size_t(column * 4 + row)]);
        return m;
    }
    double t[3] = {0, 0, 0}, q[4] = {0, 0, 0, 1}, s[3] = {1, 1, 1};
    if (node.translation.size() == 3) std::copy_n(node.translation.begin(), 3, t);
    if (node.rotation.size() == 4) std::copy_n(node.rotation.begin(), 4, q);
    if (node.scale.size() == 3) std::copy_n(node.scale.begin(), 3, s);
    const double x = q[0], y = q[1], z = q[2], w = q[3];
    const double r[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)},
                            {2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)},
                            {2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)}};
    for (int row = 0; row < 3; ++row) {
        for (int column = 0; column < 3; ++column)
            m[row][column] = static_cast<float>(r[row][column] * s[column]);
        m[row][3] = static_cast<float>(t[row]);
    }
    m[3][3] = 1;
    return m;
}

// tinygltf's image decoder (stb) behind the image reader's check of the declared size, so that a
// small file whose header claims a huge image is refused before its pixels are allocated. `model`
// is the model being read: tinygltf hands an image stored in a buffer view over as the view's
// place in its buffer without checking that the view ends within the buffer, so that is checked
// here before anything reads the bytes (a view past the buffer's end was read beyond it).
bool decodeSizeCheckedImage(tinygltf::Image* image, int index, std::string* error,
                            std::string* warning, int width, int height, const unsigned char* bytes,
                            int size, void* model) {
    if (image->bufferView >= 0) {
        // tinygltf has checked both indices before calling here.
        const auto& gltf = *static_cast<const tinygltf::Model*>(model);
        const tinygltf::BufferView& view =
            gltf.bufferViews[static_cast<std::size_t>(image->bufferView)];
        const std::size_t length = gltf.buffers[static_cast<std::size_t>(view.buffer)].data.size();
        if (view.byteOffset > length || view.byteLength > length - view.byteOffset) {
            *error += "image " + std::to_string(index) + ": its buffer view (" +
                      std::to_string(view.byteLength) + " bytes from byte " +
                      std::to_string(view.byteOffset) + ") ends beyond its buffer (" +
                      std::to_string(length) + " bytes)";
            return false;
        }
    }
    try {
        ImageReader::checkDeclaredSize(bytes, static_cast<std::size_t>(std::max(size, 0)), "");
    } catch (const InputError& refused) {
        *error += "image " + std::to_string(index) + ": " + refused.message();
        return false;
    }
    return tinygltf::LoadImageData(image, index, error, warning, width, height, bytes, size,
                                   nullptr);
}

class GltfReader {
public:
    // parserWarning: what tinygltf said while reading (why an image is missing, for one).
    GltfReader(const fs::path& path, const tinygltf::Model& model, std::string parserWarning,
               std::vector<std::string>& warnings)
        : path_(path),
          model_(model),
          parserWarning_(std::move(parserWarning)),
          warnings_(warnings) {}

    std::shared_ptr<TriangleMesh> read();

private:
    [[noreturn]] void fail(const std::string& message) const {
        throw InputError(path_.string(), message);
    }
    // One warning per kind of problem.
    void warnOnce(const std::string& kind, const std::string& message) {
        if (warned_.insert(kind).second) warn(warnings_, path_, message);
    }
    void warnUnsupported();
    void addNode(int index, const Transform& parent, int depth);
    void addPrimitive(const tinygltf::Primitive& primitive, const Transform& toWorld);
    // An accessor's elements of `components` numbers each, as floats.
    std::vector<float> floats(int accessorIndex, int components, const std::string& what) const;
    std::vector<std::uint32_t> indices(int accessorIndex) const;
    // The bytes of an accessor's elements, checked against its buffer: where each starts.
    std::vector<const unsigned char*> elements(const tinygltf::Accessor& accessor,
                                               std::size_t elementSize,
                                               const std::string& what) const;
    std::uint32_t materialOf(int index);
    std::shared_ptr<const Material> convert(const tinygltf::Material& material);
    // The image of texture `index`, times `factor` (colour: decoded from sRGB); null without one.
    std::shared_ptr<const Image> texels(int index, const Color& factor, bool colour);

    const fs::path& path_;
    const tinygltf::Model& model_;
    std::string parserWarning_;
    std::vector<std::string>& warnings_;
    std::set<std::string> warned_;
    TriangleMesh mesh_;
    bool hasNormals_ = false, hasUvs_ = false;
    std::size_t degenerate_ = 0;
    std::map<int, std::uint32_t> materials_;  // glTF's index (-1: the default) to ours
};

std::shared_ptr<TriangleMesh> GltfReader::read() {
    warnUnsupported();
    if (model_.scenes.empty()) fail("the file has no scene");
    const std::size_t scene =
        model_.defaultScene >= 0 ? std::size_t(model_.defaultScene) : std::size_t(0);
    if (scene >= model_.scenes.size()) fail("the default scene does not exist");
    for (const int node : model_.scenes[scene].nodes)
        addNode(node, Transform(), 0);
    if (degenerate_ > 0)
        warn(warnings_, path_,
             std::to_string(degenerate_) + " triangles of zero area are left out");
    if (mesh_.indices.empty()) fail("the default scene has no triangles");
    if (!hasNormals_) mesh_.normals.clear();
    if (!hasUvs_) mesh_.uvs.clear();
    return std::make_shared<TriangleMesh>(std::move(mesh_));
}

void GltfReader::warnUnsupported() {
    if (!model_.skins.empty())
        warnOnce("skins", "skins are not supported: skinned meshes are drawn in their bind pose");
    if (!model_.animations.empty())
        warnOnce("animations", "animations are not supported: the model is drawn at rest");
    if (!model_.cameras.empty())
        warnOnce("cameras", "the file's cameras are not used: the scene's camera is");
    for (const std::string& extension : model_.extensionsUsed) {
        if (extension == kEmissiveStrength) continue;
        if (extension == "KHR_lights_punctual")
            warnOnce(extension, "the file's lights (KHR_lights_punctual) are not used");
        else
            warnOnce(extension, "extension " + inQuotes(extension) + " is not supported");
    }
}

void GltfReader::addNode(int index, const Transform& parent, int depth) {
    if (index < 0 || std::size_t(index) >= model_.nodes.size())
        fail("node " + std::to_string(index) + " does not exist");
    // A tree has no path longer than its nodes: a longer one goes round a cycle.
    if (std::size_t(depth) > model_.nodes.size()) fail("the node hierarchy has a cycle");
    const tinygltf::Node& node = model_.nodes[std::size_t(index)];
    Transform toWorld;
    try {
        toWorld = parent * Transform(localMatrix(node));
    } catch (const std::invalid_argument&) {
        // A zero scale hides a node (and its children): nothing of it would be seen.
        warnOnce("singular", "nodes with a singular transform (zero scale) are left out");
        return;
    }
    if (node.mesh >= 0) {
        if (std::size_t(node.mesh) >= model_.meshes.size())
            fail("mesh " + std::to_string(node.mesh) + " does not exist");
        for (const tinygltf::Primitive& primitive :
             model_.meshes[std::size_t(node.mesh)].primitives)
            addPrimitive(primitive, toWorld);
    }
    for (const int child : node.children)
        addNode(child, toWorld, depth + 1);
}

void GltfReader::addPrimitive(const tinygltf::Primitive& primitive, const Transform& toWorld) {
    if (!primitive.targets.empty())
        warnOnce("morph", "morph targets are not supported: meshes are drawn in their base shape");
    if (primitive.mode != kTriangles) {
        warnOnce("mode",
                 "primitives other than triangles (points, lines, strips, fans) are left "
                 "out");
        return;
    }
    const auto attribute = [&](const char* name) {
        const auto it = primitive.attributes.find(name);
        return it == primitive.attributes.end() ? -1 : it->second;
    };
    if (attribute("POSITION") < 0) {
        warnOnce("position", "primitives without POSITION are left out");
        return;
    }
    const std::vector<float> positions = floats(attribute("POSITION"), 3, "POSITION");
    const std::size_t count = positions.size() / 3;
    const std::vector<float> normals =
        attribute("NORMAL") >= 0 ? floats(attribute("NORMAL"), 3, "NORMAL") : std::vector<float>();
    const std::vector<float> uvs = attribute("TEXCOORD_0") >= 0
                                       ? floats(attribute("TEXCOORD_0"), 2, "TEXCOORD_0")
                                       : std::vector<float>();
    if ((!normals.empty() && normals.size() != 3 * count) ||
        (!uvs.empty() && uvs.size() != 2 * count))
        fail("a primitive's attributes have different counts");

    const auto base = static_cast<std::uint32_t>(mesh_.positions.size());
    for (std::size_t i = 0; i < count; ++i) {
        mesh_.positions.push_back(
            toWorld.applyPoint(Vec3(positions[3 * i], positions[3 * i + 1], positions[3 * i + 2])));
        Vec3 n;
        if (!normals.empty()) {
            n = toWorld.applyNormal(Vec3(normals[3 * i], normals[3 * i + 1], normals[3 * i + 2]));
            n = lengthSquared(n) > 0 ? normalize(n) : Vec3();
        }
        mesh_.normals.push_back(n);
        mesh_.uvs.push_back(uvs.empty() ? Vec2() : Vec2(uvs[2 * i], 1 - uvs[2 * i + 1]));
    }
    hasNormals_ = hasNormals_ || !normals.empty();
    hasUvs_ = hasUvs_ || !uvs.empty();

    std::vector<std::uint32_t> corners;
    if (primitive.indices >= 0) {
        corners = indices(primitive.indices);
    } else {
        for (std::uint32_t i = 0; i < count; ++i)
            corners.push_back(i);
    }
    const std::uint32_t material = materialOf(primitive.material);
    const auto& m = toWorld.matrix();
    const float determinant = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                              m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                              m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    for (std::size_t t = 0; t + 2 < corners.size(); t += 3) {
        std::uint32_t a = corners[t], b = corners[t + 1], c = corners[t + 2];
        if (a >= count || b >= count || c >= count)
            fail("an index is beyond the primitive's " + std::to_string(count) + " vertices");
        if (determinant < 0) std::swap(b, c);
        a += base, b += base, c += base;
        const Vec3 &p0 = mesh_.positions[a], &p1 = mesh_.positions[b], &p2 = mesh_.positions[c];
        if (!(lengthSquared(cross(p1 - p0, p2 - p0)) > 0)) {
            ++degenerate_;
            continue;
        }
        mesh_.indices.insert(mesh_.indices.end(), {a, b, c});
        mesh_.faceMaterials.push_back(material);
    }
}

std::vector<const unsigned char*> GltfReader::elements(const tinygltf::Accessor& accessor,
                                                       std::size_t elementSize,
                                                       const std::string& what) const {
    if (accessor.sparse.isSparse) fail("accessor " + what + " is sparse, which is not supported");
    std::vector<const unsigned char*> starts;
    if (accessor.count > kMostAccessorElements)
        fail("accessor " + what + " has " + std::to_string(accessor.count) +
             " elements, more than lancer reads (" + std::to_string(kMostAccessorElements) + ")");
    if (accessor.bufferView < 0) return starts;  // all zeros: the caller fills them
    if (std::size_t(accessor.bufferView) >= model_.bufferViews.size())
        fail("accessor " + what + " names a buffer view that does not exist");
    const tinygltf::BufferView& view = model_.bufferViews[std::size_t(accessor.bufferView)];
    if (view.buffer < 0 || std::size_t(view.buffer) >= model_.buffers.size())
        fail("a buffer view names a buffer that does not exist");
    const std::vector<unsigned char>& data = model_.buffers[std::size_t(view.buffer)].data;
    const int stride = accessor.ByteStride(view);
    if (stride <= 0) fail("accessor " + what + " has an invalid byte stride");
    const std::size_t count = accessor.count;
    const std::size_t start = view.byteOffset + accessor.byteOffset;
    const std::size_t end = std::min(data.size(), view.byteOffset + view.byteLength);
    if (count > 0 && (start > end || (count - 1) * std::size_t(stride) + elementSize > end - start))
        fail("accessor " + what + " reaches beyond its buffer");
    for (std::size_t i = 0; i < count; ++i)
        starts.push_back(data.data() + start + i * std::size_t(stride));
    return starts;
}

std::vector<float> GltfReader::floats(int accessorIndex, int components,
                                      const std::string& what) const {
    if (accessorIndex < 0 || std::size_t(accessorIndex) >= model_.accessors.size())
        fail("accessor " + what + " does not exist");
    const tinygltf::Accessor& accessor = model_.accessors[std::size_t(accessorIndex)];
    if (tinygltf::GetNumComponentsInType(std::uint32_t(accessor.type)) != components)
        fail(what + " must have " + std::to_string(components) + " components");
    const int size = tinygltf::GetComponentSizeInBytes(std::uint32_t(accessor.componentType));
    if (size <= 0) fail(what + " has an unknown component type");
    const auto starts = elements(accessor, std::size_t(size * components), what);
    std::vector<float> values(accessor.count * std::size_t(components), 0.0f);
    // Integers are scaled to [0, 1] or [-1, 1] when normalized, else taken as they are
    // (KHR_mesh_quantization's positions).
    const bool normalized = accessor.normalized;
    for (std::size_t i = 0; i < starts.size(); ++i)
        for (int c = 0; c < components; ++c) {
            const unsigned char* at = starts[i] + c * size;
            float v = 0;
            switch (accessor.componentType) {
                case TINYGLTF_COMPONENT_TYPE_FLOAT:
                    std::memcpy(&v, at, 4);
                    break;
                case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
                    v = normalized ? *at / 255.0f : *at;
                    break;
                case TINYGLTF_COMPONENT_TYPE_BYTE: {
                    const auto b = static_cast<signed char>(*at);
                    v = normalized ? std::max(b / 127.0f, -1.0f) : b;
                    break;
                }
                case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
                    std::uint16_t u;
                    std::memcpy(&u, at, 2);
                    v = normalized ? u / 65535.0f : u;
                    break;
                }
                case TINYGLTF_COMPONENT_TYPE_SHORT: {
                    std::int16_t h;
                    std::memcpy(&h, at, 2);
                    v = normalized ? std::max(h / 32767.0f, -1.0f) : h;
                    break;
                }
                default:
                    fail(what + " has a component type that glTF does not allow for it");
            }
            values[i * std::size_t(components) + std::size_t(c)] = v;
        }
    return values;
}

std::vector<std::uint32_t> GltfReader::indices(int accessorIndex) const {
    if (std::size_t(accessorIndex) >= model_.accessors.size())
        fail("the indices' accessor does not exist");
    const tinygltf::Accessor& accessor = model_.accessors[std::size_t(accessorIndex)];
    const int size = tinygltf::GetComponentSizeInBytes(std::uint32_t(accessor.componentType));
    if (accessor.type != TINYGLTF_TYPE_SCALAR || (size != 1 && size != 2 && size != 4))
        fail("indices must be unsigned scalars of 8, 16 or 32 bits");
    const auto starts = elements(accessor, std::size_t(size), "of the indices");
    std::vector<std::uint32_t> values(accessor.count, 0);
    for (std::size_t i = 0; i < starts.size(); ++i) {
        std::uint32_t v = 0;
        if (size == 1) {
            v = *starts[i];
        } else if (size == 2) {
            std::uint16_t u;
            std::memcpy(&u, starts[i], 2);
            v = u;
        } else {
            std::memcpy(&v, starts[i], 4);
        }
        values[i] = v;
    }
    return values;
}

std::uint32_t GltfReader::materialOf(int index) {
    if (index >= 0 && std::size_t(index) >= model_.materials.size())
        fail("material " + std::to_string(index) + " does not exist");
    const auto [it, isNew] = materials_.try_emplace(index, std::uint32_t(mesh_.materials.size()));
    if (isNew)
        mesh_.materials.push_back(index < 0 ? convert(tinygltf::Material())
                                            : convert(model_.materials[std::size_t(index)]));
    return it->second;
}

std::shared_ptr<const Material> GltfReader::convert(const tinygltf::Material& material) {
    const tinygltf::PbrMetallicRoughness& pbr = material.pbrMetallicRoughness;
    BlinnPhongMaterial::Parameters ours;
    // glTF requires both factors in [0, 1]; a file beyond that is taken at the nearest bound.
    float metallic = std::clamp(static_cast<float>(pbr.metallicFactor), 0.0f, 1.0f);
    float roughness = std::clamp(static_cast<float>(pbr.roughnessFactor), 0.0f, 1.0f);
    if (const auto image = texels(pbr.metallicRoughnessTexture.index, Color(1), false)) {
        warnOnce("metallicRoughnessTexture",
                 "metallic-roughness textures are drawn as their mean metallic and roughness "
                 "(both are uniform over a material)");
        const Color mean = meanColor(*image);
        roughness *= mean.g;
        metallic *= mean.b;
    }

    const Color base = colorOf(pbr.baseColorFactor, Color(1));
    const float dielectric = 1 - metallic;
    if (const auto image =
            dielectric > 0 ? texels(pbr.baseColorTexture.index, base * dielectric, true) : nullptr)
        ours.diffuse = std::make_shared<ImageTexture>(std::make_shared<MipMap>(*image));
    else
        ours.diffuse = std::make_shared<ConstantTexture>(base * dielectric);
    ours.ambient = ours.diffuse;
    ours.specular = Color(0);
    if (metallic > 0) {
        Color tint = base;
        if (const auto image = texels(pbr.baseColorTexture.index, base, true)) {
            warnOnce("metallicTexture",
                     "base colour textures tint metals by their mean colour "
                     "(a conductor is uniform over a material)");
            tint = meanColor(*image);
        }
        ours.reflection = Color(metallic);
        ours.conductor = conductorReflecting(tint);
        ours.roughness = roughness * roughness;
    }

    Color emission = colorOf(material.emissiveFactor, Color(0));
    if (const auto it = material.extensions.find(kEmissiveStrength);
        it != material.extensions.end() && it->second.Has("emissiveStrength"))
        emission *= static_cast<float>(it->second.Get("emissiveStrength").GetNumberAsDouble());
    ours.emission = emission;
    if (!emission.isBlack())
        if (const auto image = texels(material.emissiveTexture.index, Color(1), true))
            ours.emissionMap = std::make_shared<ImageTexture>(std::make_shared<MipMap>(*image));

    auto converted = std::make_shared<BlinnPhongMaterial>(std::move(ours));
    if (const auto image = texels(material.normalTexture.index, Color(1), false)) {
        if (material.normalTexture.scale != 1)
            warnOnce("normalScale", "the scale of normal textures is ignored");
        converted->setShadingNormalMap(std::make_shared<NormalMap>(
            std::make_shared<ImageTexture>(std::make_shared<MipMap>(*image))));
    }
    return converted;
}

std::shared_ptr<const Image> GltfReader::texels(int index, const Color& factor, bool colour) {
    if (index < 0) return nullptr;
    if (std::size_t(index) >= model_.textures.size())
        fail("texture " + std::to_string(index) + " does not exist");
    const int source = model_.textures[std::size_t(index)].source;
    if (source < 0 || std::size_t(source) >= model_.images.size()) {
        warnOnce("textureSource",
                 "textures without an image (or of an extension's image "
                 "format) are left out");
        return nullptr;
    }
    const tinygltf::Image& image = model_.images[std::size_t(source)];
    const int channels = image.component, bytes = image.bits / 8;
    if (image.width <= 0 || image.height <= 0 || channels <= 0 || (bytes != 1 && bytes != 2) ||
        image.image.size() <
            std::size_t(image.width) * std::size_t(image.height) * std::size_t(channels * bytes))
        fail("image " + (image.uri.empty() ? std::to_string(source) : inQuotes(image.uri)) +
             " is missing or cannot be decoded" +
             (parserWarning_.empty() ? "" : " (" + oneLine(parserWarning_) + ")"));
    const float largest = bytes == 1 ? 255.0f : 65535.0f;
    auto result = std::make_shared<Image>(image.width, image.height);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const std::size_t texel = (std::size_t(y) * std::size_t(image.width) + std::size_t(x)) *
                                      std::size_t(channels);
            float rgb[3];
            for (int c = 0; c < 3; ++c) {
                // Grey images have one channel (two with alpha).
                const std::size_t channel = texel + std::size_t(channels >= 3 ? c : 0);
                std::uint16_t value = image.image[channel * std::size_t(bytes)];
                if (bytes == 2) std::memcpy(&value, &image.image[channel * 2], 2);
                rgb[c] = value / largest;
                if (colour) rgb[c] = srgbToLinear(rgb[c]);
            }
            result->at(x, y) = Color(rgb[0], rgb[1], rgb[2]) * factor;
        }
    return result;
}

// A URI's path as tinygltf reads it (its dlib decoder): %XX is the byte XX, + a space.
std::string decodedUri(const std::string& uri) {
    std::string path;
    for (std::size_t i = 0; i < uri.size(); ++i) {
        const auto hex = [&](std::size_t at) {
            return at < uri.size() && std::isxdigit(static_cast<unsigned char>(uri[at]));
        };
        if (uri[i] == '%' && hex(i + 1) && hex(i + 2)) {
            path += static_cast<char>(std::stoi(uri.substr(i + 1, 2), nullptr, 16));
            i += 2;
        } else {
            path += uri[i] == '+' ? ' ' : uri[i];
        }
    }
    return path;
}

}  // namespace

std::shared_ptr<TriangleMesh> GltfLoader::load(const fs::path& path,
                                               std::vector<std::string>& warnings,
                                               std::vector<fs::path>* externalFiles) {
    InputFile::check(path, "a glTF file", "glTF files", InputFile::kMaxModelBytes);
    if (!fs::exists(path))
        throw InputError(path.string(), "cannot open the glTF file (does it exist?)");
    tinygltf::TinyGLTF parser;
    tinygltf::Model model;
    parser.SetImageLoader(decodeSizeCheckedImage, &model);
    std::string error, warning;
    const bool read = isBinaryGltf(path)
                          ? parser.LoadBinaryFromFile(&model, &error, &warning, path.string())
                          : parser.LoadASCIIFromFile(&model, &error, &warning, path.string());
    if (!read)
        throw InputError(path.string(),
                         "cannot read the glTF file: " + oneLine(error.empty() ? warning : error));
    std::shared_ptr<TriangleMesh> mesh = GltfReader(path, model, warning, warnings).read();
    if (externalFiles) {
        // Where tinygltf found them: relative to the model's folder, the URI decoded as it
        // decodes it.
        const auto addFile = [&](const std::string& uri) {
            if (!uri.empty() && !tinygltf::IsDataURI(uri))
                externalFiles->push_back(path.parent_path() / decodedUri(uri));
        };
        for (const tinygltf::Buffer& buffer : model.buffers)
            addFile(buffer.uri);
        for (const tinygltf::Image& image : model.images)
            addFile(image.uri);
    }
    return mesh;
}

}  // namespace lancer
