// glTF 2.0 models: the node hierarchy's transforms, attributes, materials, the warnings for what
// lancer cannot show and the errors of malformed files, on small files written here (one buffer
// embedded as a data URI), and the sample model of scenes/models as .gltf and .glb.

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <nlohmann/json.hpp>

#include "MeshTestSupport.h"
#include "io/GltfLoader.h"
#include "materials/Optics.h"
#include "scene/InputError.h"

namespace lancer::test {
namespace {

using json = nlohmann::json;

std::string base64(const std::string& bytes) {
    static const char* kDigits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        const std::size_t n = std::min<std::size_t>(3, bytes.size() - i);
        std::uint32_t v = 0;
        for (std::size_t k = 0; k < 3; ++k)
            v = (v << 8) | (k < n ? static_cast<unsigned char>(bytes[i + k]) : 0u);
        for (std::size_t k = 0; k < 4; ++k)
            out += k <= n ? kDigits[(v >> (18 - 6 * k)) & 63] : '=';
    }
    return out;
}

// A glTF document whose accessors read one embedded buffer.
class GltfDocument {
public:
    GltfDocument() {
        doc_ = {{"asset", {{"version", "2.0"}}},
                {"scene", 0},
                {"scenes", {{{"nodes", json::array()}}}},
                {"nodes", json::array()},
                {"meshes", json::array()},
                {"accessors", json::array()},
                {"bufferViews", json::array()}};
    }

    // An accessor of float elements of `type` (VEC3, VEC2) over `values`.
    int floats(const std::vector<float>& values, const std::string& type, int components) {
        std::string bytes(values.size() * 4, '\0');
        std::memcpy(bytes.data(), values.data(), bytes.size());
        return accessor(bytes, 5126, values.size() / std::size_t(components), type);
    }
    // An accessor of unsigned bytes, normalized to [0, 1] or integers.
    int bytes(const std::vector<std::uint8_t>& values, const std::string& type, int components,
              bool normalized) {
        const int index = accessor(std::string(values.begin(), values.end()), 5121,
                                   values.size() / std::size_t(components), type);
        doc_["accessors"][std::size_t(index)]["normalized"] = normalized;
        return index;
    }
    int indices(const std::vector<std::uint16_t>& values) {
        std::string bytes(values.size() * 2, '\0');
        std::memcpy(bytes.data(), values.data(), bytes.size());
        return accessor(bytes, 5123, values.size(), "SCALAR");
    }
    // A mesh of one triangle primitive with these attributes (and indices, if >= 0).
    int mesh(const json& attributes, int indices = -1, int material = -1) {
        json primitive = {{"attributes", attributes}};
        if (indices >= 0) primitive["indices"] = indices;
        if (material >= 0) primitive["material"] = material;
        doc_["meshes"].push_back({{"primitives", {primitive}}});
        return int(doc_["meshes"].size()) - 1;
    }
    // The triangle (0,0,0), (1,0,0), (0,1,0) as a mesh.
    int unitTriangle(int material = -1) {
        return mesh({{"POSITION", floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3", 3)}}, -1, material);
    }
    int node(json node) {
        doc_["nodes"].push_back(std::move(node));
        return int(doc_["nodes"].size()) - 1;
    }
    void addRoot(int node) { doc_["scenes"][0]["nodes"].push_back(node); }

    json& json_() { return doc_; }
    std::string text() const {
        json doc = doc_;
        doc["buffers"] = {{{"byteLength", buffer_.size()},
                           {"uri", "data:application/octet-stream;base64," + base64(buffer_)}}};
        return doc.dump();
    }

private:
    int accessor(std::string bytes, int componentType, std::size_t count, const std::string& type) {
        while (buffer_.size() % 4 != 0)
            buffer_ += '\0';
        doc_["bufferViews"].push_back(
            {{"buffer", 0}, {"byteOffset", buffer_.size()}, {"byteLength", bytes.size()}});
        buffer_ += bytes;
        doc_["accessors"].push_back({{"bufferView", doc_["bufferViews"].size() - 1},
                                     {"componentType", componentType},
                                     {"count", count},
                                     {"type", type}});
        return int(doc_["accessors"].size()) - 1;
    }

    json doc_;
    std::string buffer_;
};

class GltfTest : public ::testing::Test {
protected:
    LoadedObj load(const GltfDocument& doc) {
        LoadedObj loaded;
        loaded.mesh = GltfLoader::load(folder_.write("model.gltf", doc.text()), loaded.warnings);
        return loaded;
    }
    // A triangle of one material of these pbrMetallicRoughness keys.
    LoadedObj loadPbr(const json& pbr) {
        GltfDocument doc;
        doc.json_()["materials"] = {{{"pbrMetallicRoughness", pbr}}};
        doc.addRoot(doc.node({{"mesh", doc.unitTriangle(0)}}));
        return load(doc);
    }
    std::string failure(const std::string& text) {
        std::vector<std::string> warnings;
        try {
            GltfLoader::load(folder_.write("bad.gltf", text), warnings);
        } catch (const InputError& error) {
            return error.what();
        }
        ADD_FAILURE() << "no error";
        return "";
    }

    ScratchFolder folder_;
};

void expectNear(const Vec3& a, const Vec3& b) {
    EXPECT_NEAR(a.x, b.x, 1e-6f) << "x";
    EXPECT_NEAR(a.y, b.y, 1e-6f) << "y";
    EXPECT_NEAR(a.z, b.z, 1e-6f) << "z";
}

Vec3 corner(const TriangleMesh& mesh, std::size_t triangle, std::size_t k) {
    return mesh.positions[mesh.indices[3 * triangle + k]];
}

// The child's scale 2 and quarter turn about z, then the parent's translation (1, 2, 3).
TEST_F(GltfTest, NodeTransformsComposeDownTheHierarchy) {
    GltfDocument doc;
    const int child = doc.node({{"mesh", doc.unitTriangle()},
                                {"scale", {2, 2, 2}},
                                {"rotation", {0, 0, std::sqrt(0.5), std::sqrt(0.5)}}});
    doc.addRoot(doc.node({{"translation", {1, 2, 3}}, {"children", {child}}}));
    const LoadedObj loaded = load(doc);
    ASSERT_EQ(loaded.mesh->triangleCount(), 1u);
    expectNear(corner(*loaded.mesh, 0, 0), Vec3(1, 2, 3));
    expectNear(corner(*loaded.mesh, 0, 1), Vec3(1, 4, 3));
    expectNear(corner(*loaded.mesh, 0, 2), Vec3(-1, 2, 3));
}

// A node's matrix is column-major: its last column, the translation, is elements 12 to 14.
TEST_F(GltfTest, NodeMatrixIsColumnMajor) {
    GltfDocument doc;
    doc.addRoot(doc.node({{"mesh", doc.unitTriangle()},
                          {"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 5, 0, 0, 1}}}));
    const LoadedObj loaded = load(doc);
    expectNear(corner(*loaded.mesh, 0, 0), Vec3(5, 0, 0));
    expectNear(corner(*loaded.mesh, 0, 1), Vec3(6, 0, 0));
}

// A mirroring transform turns the winding, so that the front stays where glTF says it is.
TEST_F(GltfTest, MirroringTransformKeepsTheFrontFacing) {
    GltfDocument doc;
    doc.addRoot(doc.node({{"mesh", doc.unitTriangle()}, {"scale", {-1, 1, 1}}}));
    const LoadedObj loaded = load(doc);
    EXPECT_GT(areaVector(*loaded.mesh, 0).z, 0);
}

// Every node using a mesh places a copy of it; nodes outside the default scene are not drawn.
TEST_F(GltfTest, EachNodeOfTheDefaultSceneDrawsItsMesh) {
    GltfDocument doc;
    const int mesh = doc.unitTriangle();
    doc.addRoot(doc.node({{"mesh", mesh}}));
    doc.addRoot(doc.node({{"mesh", mesh}, {"translation", {0, 0, 1}}}));
    doc.node({{"mesh", mesh}, {"translation", {0, 0, 2}}});  // in no scene
    const LoadedObj loaded = load(doc);
    ASSERT_EQ(loaded.mesh->triangleCount(), 2u);
    expectNear(corner(*loaded.mesh, 1, 0), Vec3(0, 0, 1));
}

// Indices, normals (smooth shading) and uvs, glTF's v turned to ours (v up the image).
TEST_F(GltfTest, IndicesNormalsAndUvsAreRead) {
    GltfDocument doc;
    const int positions = doc.floats({0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0}, "VEC3", 3);
    const int normals = doc.floats({0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1}, "VEC3", 3);
    const int uvs = doc.floats({0, 0.25f, 1, 0, 0, 1, 1, 1}, "VEC2", 2);
    const int mesh = doc.mesh({{"POSITION", positions}, {"NORMAL", normals}, {"TEXCOORD_0", uvs}},
                              doc.indices({0, 1, 2, 2, 1, 3}));
    doc.addRoot(doc.node({{"mesh", mesh}, {"scale", {2, 2, 2}}}));
    const LoadedObj loaded = load(doc);
    ASSERT_EQ(loaded.mesh->triangleCount(), 2u);
    expectNear(corner(*loaded.mesh, 1, 2), Vec3(2, 2, 0));
    ASSERT_EQ(loaded.mesh->normals.size(), 4u);
    expectNear(loaded.mesh->normals[0], Vec3(0, 0, 1));  // normalised after the scale
    ASSERT_EQ(loaded.mesh->uvs.size(), 4u);
    EXPECT_EQ(loaded.mesh->uvs[0].y, 0.75f);
}

// Integer attributes: normalized ones scaled to [0, 1] (uvs), others taken as they are
// (positions of KHR_mesh_quantization).
TEST_F(GltfTest, IntegerAttributesAreScaledOnlyWhenNormalized) {
    GltfDocument doc;
    const int positions = doc.bytes({0, 0, 0, 2, 0, 0, 0, 2, 0}, "VEC3", 3, false);
    const int uvs = doc.bytes({0, 255, 255, 255, 0, 0}, "VEC2", 2, true);
    doc.addRoot(doc.node({{"mesh", doc.mesh({{"POSITION", positions}, {"TEXCOORD_0", uvs}})}}));
    const LoadedObj loaded = load(doc);
    expectNear(corner(*loaded.mesh, 0, 1), Vec3(2, 0, 0));
    EXPECT_EQ(loaded.mesh->uvs[1], Vec2(1, 0));  // glTF's (1, 1): v turned up
    EXPECT_EQ(loaded.mesh->uvs[2], Vec2(0, 1));
}

TEST_F(GltfTest, BaseColourIsTheDiffuseAndEmissionIsScaledByItsStrength) {
    GltfDocument doc;
    doc.json_()["materials"] = {
        {{"pbrMetallicRoughness",
          {{"baseColorFactor", {0.5, 0.25, 0.125, 1}}, {"metallicFactor", 0}}},
         {"emissiveFactor", {1, 0.5, 0}},
         {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 4}}}}}}};
    doc.json_()["extensionsUsed"] = {"KHR_materials_emissive_strength"};
    doc.addRoot(doc.node({{"mesh", doc.unitTriangle(0)}}));
    const LoadedObj loaded = load(doc);
    EXPECT_TRUE(loaded.warnings.empty());
    const BlinnPhongMaterial::Parameters& m = materialOf(*loaded.mesh, 0);
    EXPECT_EQ(colorOf(*m.diffuse), Color(0.5f, 0.25f, 0.125f));
    EXPECT_EQ(m.emission, Color(4, 2, 0));
    EXPECT_EQ(m.specular, Color(0));
}

// glTF's default material: white, metallic 1, roughness 1: a white conductor of GGX alpha 1.
TEST_F(GltfTest, PrimitiveWithoutMaterialIsARoughWhiteMetal) {
    GltfDocument doc;
    doc.addRoot(doc.node({{"mesh", doc.unitTriangle()}}));
    const LoadedObj loaded = load(doc);
    const BlinnPhongMaterial::Parameters& m = materialOf(*loaded.mesh, 0);
    EXPECT_EQ(colorOf(*m.diffuse), Color(0));
    EXPECT_EQ(m.reflection, Color(1));
    ASSERT_TRUE(m.conductor.has_value());
    EXPECT_EQ(m.conductor->k, conductorReflecting(Color(1)).k);
    EXPECT_EQ(m.roughness, 1.0f);
    EXPECT_TRUE(loaded.warnings.empty());
}

// glTF's BRDF mix(dielectric, metal, metallic) as ours: the diffuse weighted by 1 - metallic, the
// conductor (reflecting the base colour head-on) by metallic, roughness squared to GGX alpha.
TEST_F(GltfTest, MetallicWeighsAConductorOfTheBaseColourAndRoughnessIsSquared) {
    const LoadedObj loaded = loadPbr({{"baseColorFactor", {0.8, 0.5, 0.2, 1}},
                                      {"metallicFactor", 0.25},
                                      {"roughnessFactor", 0.5}});
    EXPECT_TRUE(loaded.warnings.empty());
    const BlinnPhongMaterial::Parameters& m = materialOf(*loaded.mesh, 0);
    EXPECT_EQ(colorOf(*m.diffuse), Color(0.8f, 0.5f, 0.2f) * 0.75f);
    EXPECT_EQ(colorOf(*m.ambient), colorOf(*m.diffuse));
    EXPECT_EQ(m.reflection, Color(0.25f));
    ASSERT_TRUE(m.conductor.has_value());
    EXPECT_EQ(m.conductor->eta, Color(1));
    EXPECT_EQ(m.conductor->k, conductorReflecting(Color(0.8f, 0.5f, 0.2f)).k);
    EXPECT_EQ(m.roughness, 0.25f);
}

// A dielectric (metallic 0) is the diffuse base colour as before: no conductor, and its
// roughness has no lobe to act on (the specular layer of glTF's dielectric is not drawn).
TEST_F(GltfTest, DielectricIsDiffuseWithoutAConductor) {
    const LoadedObj loaded = loadPbr(
        {{"baseColorFactor", {0.8, 0.5, 0.2, 1}}, {"metallicFactor", 0}, {"roughnessFactor", 0.5}});
    EXPECT_TRUE(loaded.warnings.empty());
    const BlinnPhongMaterial::Parameters& m = materialOf(*loaded.mesh, 0);
    EXPECT_EQ(colorOf(*m.diffuse), Color(0.8f, 0.5f, 0.2f));
    EXPECT_EQ(m.reflection, Color(0));
    EXPECT_FALSE(m.conductor.has_value());
    EXPECT_EQ(m.roughness, 0.0f);
}

// A 2x1 PNG of the texels (0, 255, 255) and (0, 0, 0): mean (0, 0.5, 0.5) read linear or as sRGB.
const char* const kHalfPng =
    "data:image/png;base64,"
    "iVBORw0KGgoAAAANSUhEUgAAAAIAAAABCAIAAAB7QOjdAAAAD0lEQVR4nGNg+P+fgYEBAAj+"
    "Af9QVHg0AAAAAElFTkSuQmCC";

// Per-texel metallic, roughness and metal tints are not supported: their means stand in (the
// factors times the texture's mean blue and green; the base colour's mean), one warning each.
TEST_F(GltfTest, MetallicRoughnessAndMetalTexturesAreTheirMeansWithAWarningEach) {
    GltfDocument doc;
    doc.json_()["images"] = {{{"uri", kHalfPng}}};
    doc.json_()["textures"] = {{{"source", 0}}};
    doc.json_()["materials"] = {
        {{"pbrMetallicRoughness",
          {{"baseColorTexture", {{"index", 0}}}, {"metallicRoughnessTexture", {{"index", 0}}}}}},
        {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}};
    doc.addRoot(doc.node({{"mesh", doc.unitTriangle(0)}}));
    doc.addRoot(doc.node({{"mesh", doc.unitTriangle(1)}}));
    const LoadedObj loaded = load(doc);
    EXPECT_EQ(
        countContaining(loaded.warnings, "metallic-roughness textures are drawn as their mean"),
        1u);
    EXPECT_EQ(countContaining(loaded.warnings, "base colour textures tint metals by their mean"),
              1u);
    EXPECT_EQ(loaded.warnings.size(), 2u);
    const BlinnPhongMaterial::Parameters& half = materialOf(*loaded.mesh, 0);
    EXPECT_EQ(half.reflection, Color(0.5f));  // metallic 1 x mean blue 0.5
    EXPECT_EQ(half.roughness, 0.25f);         // (1 x mean green 0.5)^2
    // The base colour's texels are decoded from sRGB: 1 within a float's rounding, which moves
    // k = 2 sqrt(F0 / (1 - F0)) by at most 4 per unit of F0 at F0 = 0.5.
    constexpr float kSrgbRounding = 1e-5f;
    EXPECT_COLOR_NEAR(half.conductor->k, conductorReflecting(Color(0, 0.5f, 0.5f)).k,
                      kSrgbRounding);
    const BlinnPhongMaterial::Parameters& metal = materialOf(*loaded.mesh, 1);
    EXPECT_EQ(metal.reflection, Color(1));
    EXPECT_EQ(colorOf(*metal.diffuse), Color(0));
    EXPECT_COLOR_NEAR(metal.conductor->k, conductorReflecting(Color(0, 0.5f, 0.5f)).k,
                      kSrgbRounding);
}

// What lancer cannot show is one warning each, never an error: the geometry is still drawn.
TEST_F(GltfTest, UnsupportedFeaturesAreOneWarningEach) {
    GltfDocument doc;
    const int positions = doc.floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3", 3);
    const int offsets = doc.floats({0, 0, 1, 0, 0, 1, 0, 0, 1}, "VEC3", 3);
    const int mesh = doc.mesh({{"POSITION", positions}});
    doc.json_()["meshes"][mesh]["primitives"][0]["targets"] = {{{"POSITION", offsets}}};
    doc.json_()["meshes"][mesh]["primitives"][0]["material"] = 0;
    doc.json_()["materials"] = {{{"pbrMetallicRoughness", {{"metallicFactor", 0}}}}};
    const int node = doc.node({{"mesh", mesh}});
    doc.node({{"mesh", mesh}});  // a second user of the morphed mesh: still one warning
    doc.addRoot(node);
    doc.addRoot(1);
    doc.json_()["cameras"] = {
        {{"type", "perspective"}, {"perspective", {{"yfov", 0.8}, {"znear", 0.1}}}}};
    doc.json_()["skins"] = {{{"joints", {node}}}};
    doc.json_()["extensionsUsed"] = {"KHR_lights_punctual", "KHR_texture_transform"};
    doc.json_()["extensions"] = {
        {"KHR_lights_punctual", {{"lights", {{{"type", "point"}, {"intensity", 5}}}}}}};
    const LoadedObj loaded = load(doc);
    EXPECT_EQ(loaded.mesh->triangleCount(), 2u);
    for (const char* kind : {"morph targets", "cameras", "skins", "KHR_lights_punctual",
                             "\"KHR_texture_transform\" is not supported"})
        EXPECT_EQ(countContaining(loaded.warnings, kind), 1u) << kind;
    EXPECT_EQ(loaded.warnings.size(), 5u);
    for (const std::string& warning : loaded.warnings)
        EXPECT_EQ(warning.rfind((folder_.path() / "model.gltf").string() + ": warning: ", 0), 0u);
}

TEST_F(GltfTest, IndexBeyondTheVerticesIsAnError) {
    GltfDocument doc;
    const int positions = doc.floats({0, 0, 0, 1, 0, 0, 0, 1, 0}, "VEC3", 3);
    doc.addRoot(doc.node({{"mesh", doc.mesh({{"POSITION", positions}}, doc.indices({0, 1, 7}))}}));
    EXPECT_NE(failure(doc.text()).find("beyond the primitive's 3 vertices"), std::string::npos);
}

TEST_F(GltfTest, AccessorBeyondItsBufferIsAnError) {
    GltfDocument doc;
    doc.addRoot(doc.node({{"mesh", doc.unitTriangle()}}));
    doc.json_()["accessors"][0]["count"] = 30;
    EXPECT_NE(failure(doc.text()).find("beyond its buffer"), std::string::npos);
}

TEST_F(GltfTest, AccessorOfZerosTooLargeIsAnErrorNotAnAllocation) {
    // Without a buffer view an accessor is zeros, and its count is all the file says: a fuzzed
    // file asked for 5.5e15 normals, which the loader tried to allocate before looking.
    GltfDocument doc;
    doc.addRoot(doc.node({{"mesh", doc.unitTriangle()}}));
    doc.json_()["accessors"][0].erase("bufferView");
    doc.json_()["accessors"][0]["count"] = 66810146937514636;
    EXPECT_NE(failure(doc.text()).find("elements, more than lancer reads"), std::string::npos);
}

TEST_F(GltfTest, ImageViewBeyondItsBufferIsAnErrorNotARead) {
    // tinygltf passes the view's place in the buffer on unchecked: read past the buffer's end
    // under AddressSanitizer before the loader checked it (found by fuzz_gltf).
    GltfDocument doc;
    doc.addRoot(doc.node({{"mesh", doc.unitTriangle()}}));
    doc.json_()["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 24}, {"byteLength", 48}});
    doc.json_()["images"] = {{{"bufferView", 1}, {"mimeType", "image/png"}}};
    EXPECT_NE(failure(doc.text())
                  .find("image 0: its buffer view (48 bytes from byte 24) ends "
                        "beyond its buffer (36 bytes)"),
              std::string::npos);
}

TEST_F(GltfTest, MissingImageIsAnErrorNamingIt) {
    GltfDocument doc;
    doc.json_()["images"] = {{{"uri", "gone.png"}}};
    doc.json_()["textures"] = {{{"source", 0}}};
    doc.json_()["materials"] = {{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}}};
    doc.addRoot(doc.node({{"mesh", doc.unitTriangle(0)}}));
    EXPECT_NE(failure(doc.text()).find("image \"gone.png\" is missing"), std::string::npos);
}

TEST_F(GltfTest, NodeCycleIsAnError) {
    GltfDocument doc;
    doc.node({{"mesh", doc.unitTriangle()}, {"children", {1}}});
    doc.node({{"children", {0}}});
    doc.addRoot(0);
    EXPECT_NE(failure(doc.text()).find("cycle"), std::string::npos);
}

TEST_F(GltfTest, MalformedAndMissingFilesAreErrorsNamingThem) {
    const std::string malformed = failure("{ \"asset\": ");
    EXPECT_EQ(malformed.rfind((folder_.path() / "bad.gltf").string(), 0), 0u) << malformed;
    EXPECT_NE(malformed.find("cannot read the glTF file"), std::string::npos) << malformed;
    std::vector<std::string> warnings;
    EXPECT_THROW(GltfLoader::load(folder_.path() / "gone.glb", warnings), InputError);
    EXPECT_NE(failure(R"({"asset": {"version": "2.0"}})").find("no scene"), std::string::npos);
}

// The sample model as .gltf (with .bin and PNG) and as .glb (all embedded) is the OBJ it was
// made from: the same triangles, uvs to float rounding of 1 - (1 - v), and its texture.
TEST(GltfSample, GltfAndGlbHoldTheObjsTriangles) {
    const LoadedObj obj = loadObj(sceneModel("spot/spot_textured.obj"));
    for (const char* file : {"spot/spot.gltf", "spot/spot.glb"}) {
        std::vector<std::string> warnings;
        const auto gltf = GltfLoader::load(sceneModel(file), warnings);
        EXPECT_TRUE(warnings.empty()) << file;
        ASSERT_EQ(gltf->triangleCount(), obj.mesh->triangleCount()) << file;
        for (std::size_t t = 0; t < gltf->triangleCount(); t += 97)
            for (std::size_t k = 0; k < 3; ++k) {
                EXPECT_EQ(corner(*gltf, t, k), corner(*obj.mesh, t, k)) << file;
                const Vec2 a = gltf->uvs[gltf->indices[3 * t + k]];
                const Vec2 b = obj.mesh->uvs[obj.mesh->indices[3 * t + k]];
                EXPECT_NEAR(a.x, b.x, 1e-7f);
                EXPECT_NEAR(a.y, b.y, 1e-7f);
            }
    }
}

}  // namespace
}  // namespace lancer::test
