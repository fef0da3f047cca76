// MTL materials mapped onto ours (the table at the top of src/io/MtlMaterialConverter.cpp): every
// key, every illum model, defaults, texture paths, normal and bump maps, and the warnings for
// missing files.

#include <cmath>

#include "MeshTestSupport.h"
#include "geometry/Hit.h"
#include "materials/Material.h"

namespace lancer::test {
namespace {

namespace fs = std::filesystem;

// An OBJ with one triangle per listed material, in that order, and the MTL beside it.
class MtlTest : public ::testing::Test {
protected:
    LoadedObj loadWithMaterials(const std::string& mtl, const std::vector<std::string>& used) {
        folder_.write("model.mtl", mtl);
        return loadObj(folder_.write("model.obj", "mtllib model.mtl\n" + trianglesUsing(used)),
                       textures_);
    }

    // One material "m" from these MTL lines, as the first triangle has it; no warnings expected.
    BlinnPhongMaterial::Parameters loadMaterial(const std::string& lines) {
        const LoadedObj loaded = loadWithMaterials("newmtl m\n" + lines, {"m"});
        EXPECT_TRUE(loaded.warnings.empty()) << loaded.warnings.front();
        return materialOf(*loaded.mesh, 0);
    }

    static std::string trianglesUsing(const std::vector<std::string>& materials) {
        std::string obj;
        for (std::size_t i = 0; i < materials.size(); ++i) {
            const std::string x = std::to_string(i);
            obj += "v " + x + " 0 0\nv " + x + ".5 0 0\nv " + x + " 1 0\n";
            obj += "usemtl " + materials[i] + "\nf -3 -2 -1\n";
        }
        return obj;
    }

    ScratchFolder folder_;
    FakeTextures textures_;
};

TEST_F(MtlTest, KdIsTheDiffuseColourAndTheAmbientToo) {
    const BlinnPhongMaterial::Parameters material = loadMaterial("Kd 0.1 0.2 0.3\n");
    EXPECT_COLOR_NEAR(colorOf(*material.diffuse), Color(0.1f, 0.2f, 0.3f), 0);
    EXPECT_EQ(material.ambient, material.diffuse);
}

TEST_F(MtlTest, KaIsTheAmbientColourUnlessBlack) {
    const BlinnPhongMaterial::Parameters material =
        loadMaterial("Kd 0.1 0.2 0.3\nKa 0.4 0.5 0.6\n");
    EXPECT_COLOR_NEAR(colorOf(*material.ambient), Color(0.4f, 0.5f, 0.6f), 0);
    const BlinnPhongMaterial::Parameters black = loadMaterial("Kd 0.1 0.2 0.3\nKa 0 0 0\n");
    EXPECT_EQ(black.ambient, black.diffuse);
}

TEST_F(MtlTest, KsAndNsAreTheHighlight) {
    const BlinnPhongMaterial::Parameters material =
        loadMaterial("Ks 0.5 0.6 0.7\nNs 80\nillum 2\n");
    EXPECT_EQ(material.specular, Color(0.5f, 0.6f, 0.7f));
    EXPECT_EQ(material.shininess, 80);
    EXPECT_TRUE(material.reflection.isBlack());
}

TEST_F(MtlTest, NiIsTheIor) {
    EXPECT_FLOAT_EQ(loadMaterial("Ni 1.33\n").ior, 1.33f);
}

TEST_F(MtlTest, DissolveLetsLightThroughWithoutBendingIt) {
    const BlinnPhongMaterial::Parameters material = loadMaterial("Ni 1.5\nd 0.25\n");
    EXPECT_EQ(material.transmission, Color(0.75f));
    EXPECT_EQ(material.ior, 1);
}

TEST_F(MtlTest, TrIsOneMinusDissolve) {
    EXPECT_EQ(loadMaterial("Tr 0.25\n").transmission, Color(0.25f));
}

TEST_F(MtlTest, DissolveWinsOverTrInEitherOrder) {
    EXPECT_EQ(loadMaterial("d 0.5\nTr 0.9\n").transmission, Color(0.5f));
    EXPECT_EQ(loadMaterial("Tr 0.9\nd 0.5\n").transmission, Color(0.5f));
}

TEST_F(MtlTest, KeIsTheEmission) {
    EXPECT_EQ(loadMaterial("Kd 0.78 0.78 0.78\nKe 17 12 4\n").emission, Color(17, 12, 4));
}

TEST_F(MtlTest, MapKdIsTheDiffuseAndAmbientTexture) {
    folder_.write("wood.png", "");
    const BlinnPhongMaterial::Parameters material =
        loadMaterial("Kd 0.2 0.2 0.2\nmap_Kd -s 2 2 1 -o 0.5 0 0 wood.png\n");
    EXPECT_EQ(textures_.requested(), std::vector<fs::path>{folder_.path() / "wood.png"});
    EXPECT_EQ(colorOf(*material.diffuse), FakeTextures::kColor);
    EXPECT_EQ(material.ambient, material.diffuse);
}

TEST_F(MtlTest, MapKsIsASpecularTextureThatMultipliesKs) {
    folder_.write("shine.png", "");
    const BlinnPhongMaterial::Parameters material =
        loadMaterial("Ks 0.5 0.6 0.7\nmap_Ks shine.png\nillum 2\n");
    EXPECT_EQ(textures_.requested(), std::vector<fs::path>{folder_.path() / "shine.png"});
    EXPECT_EQ(textures_.contents(), std::vector<ImageReader::Content>{ImageReader::Content::Color});
    ASSERT_TRUE(material.specularMap);
    EXPECT_EQ(colorOf(*material.specularMap), FakeTextures::kColor);
    EXPECT_EQ(material.specular, Color(0.5f, 0.6f, 0.7f));
    // Without highlights (illum 1) there is no specular term to texture.
    EXPECT_FALSE(loadMaterial("Ks 0.5 0.6 0.7\nmap_Ks shine.png\nillum 1\n").specularMap);
}

TEST_F(MtlTest, KeysLeftOutTakeTheSceneFormatDefaults) {
    const BlinnPhongMaterial::Parameters material = loadMaterial("");
    const BlinnPhongMaterial::Parameters defaults;
    EXPECT_EQ(colorOf(*material.diffuse), colorOf(*defaults.diffuse));
    EXPECT_EQ(material.ambient, material.diffuse);
    EXPECT_EQ(material.specular, defaults.specular);
    EXPECT_EQ(material.shininess, defaults.shininess);
    EXPECT_EQ(material.reflection, defaults.reflection);
    EXPECT_EQ(material.transmission, defaults.transmission);
    EXPECT_EQ(material.ior, defaults.ior);
    EXPECT_EQ(material.emission, defaults.emission);
    // Without illum, highlights are on (illum 2).
    EXPECT_EQ(loadMaterial("Ks 0.5 0.5 0.5\n").specular, Color(0.5f));
}

struct IllumCase {
    int illum;
    bool lit, highlights, mirror, glass;
};

class IllumTest : public MtlTest, public ::testing::WithParamInterface<IllumCase> {};

TEST_P(IllumTest, MapsOntoOurMaterial) {
    const IllumCase& c = GetParam();
    const Color kd(0.5f, 0.4f, 0.3f), ks(0.2f, 0.3f, 0.4f), ke(0.1f, 0, 0);
    const BlinnPhongMaterial::Parameters material = loadMaterial(
        "Kd 0.5 0.4 0.3\nKs 0.2 0.3 0.4\nKe 0.1 0 0\nNs 50\n"
        "Ni 1.7\nillum " +
        std::to_string(c.illum) + "\n");
    EXPECT_COLOR_NEAR(colorOf(*material.diffuse), c.lit ? kd : Color(0), 0);
    EXPECT_COLOR_NEAR(colorOf(*material.ambient), c.lit ? kd : Color(0), 0);
    EXPECT_COLOR_NEAR(material.emission, c.lit ? ke : ke + kd, 1e-7f);
    EXPECT_EQ(material.specular, c.highlights ? ks : Color(0));
    EXPECT_EQ(material.reflection, c.mirror ? ks : Color(0));
    EXPECT_EQ(material.transmission, c.glass ? Color(1) : Color(0));
    EXPECT_FLOAT_EQ(material.ior, 1.7f);
    EXPECT_EQ(material.shininess, 50);
}

INSTANTIATE_TEST_SUITE_P(EveryModel, IllumTest,
                         ::testing::Values(  //  illum lit  highlights mirror glass
                             IllumCase{0, false, false, false, false},   // constant colour
                             IllumCase{1, true, false, false, false},    // diffuse only
                             IllumCase{2, true, true, false, false},     // Blinn-Phong
                             IllumCase{3, true, true, true, false},      // mirror
                             IllumCase{4, true, true, true, true},       // glass + mirror
                             IllumCase{5, true, true, true, false},      // Fresnel mirror
                             IllumCase{6, true, true, true, true},       // refraction + mirror
                             IllumCase{7, true, true, false, true},      // Fresnel dielectric
                             IllumCase{8, true, true, true, false},      // as 3
                             IllumCase{9, true, true, false, true},      // as 7
                             IllumCase{10, true, false, false, false}),  // as 1
                         [](const ::testing::TestParamInfo<IllumCase>& param) {
                             return "illum" + std::to_string(param.param.illum);
                         });

TEST_F(MtlTest, GlassIsClearWhateverItsDissolve) {
    const BlinnPhongMaterial::Parameters material = loadMaterial("Ni 2.5\nd 0.5\nillum 7\n");
    EXPECT_EQ(material.transmission, Color(1));
    EXPECT_FLOAT_EQ(material.ior, 2.5f);
}

TEST_F(MtlTest, UnknownIllumIsUsedAsTwoWithAWarning) {
    const LoadedObj loaded = loadWithMaterials("newmtl odd\nKs 0.5 0.5 0.5\nillum 12\n", {"odd"});
    EXPECT_EQ(materialOf(*loaded.mesh, 0).specular, Color(0.5f));
    EXPECT_EQ(loaded.warnings,
              std::vector<std::string>{(folder_.path() / "model.mtl").string() +
                                       ": warning: material \"odd\" has illum 12, which is not an "
                                       "illumination model (0 to 10); illum 2 is used"});
}

TEST_F(MtlTest, Illum0ShowsKdNotItsTextureWithAWarning) {
    folder_.write("wood.png", "");
    const LoadedObj loaded =
        loadWithMaterials("newmtl flat\nKd 0.5 0.5 0.5\nmap_Kd wood.png\nillum 0\n", {"flat"});
    EXPECT_EQ(materialOf(*loaded.mesh, 0).emission, Color(0.5f));
    EXPECT_TRUE(textures_.requested().empty());
    ASSERT_EQ(loaded.warnings.size(), 1u);
    EXPECT_EQ(countContaining(loaded.warnings, "is illum 0"), 1u);
}

TEST_F(MtlTest, SeveralMaterialsPerFile) {
    const LoadedObj loaded = loadWithMaterials(
        "newmtl red\nKd 1 0 0\n"
        "newmtl unused\nKd 0 0 0\nmap_Kd never_loaded.png\n"
        "newmtl green\nKd 0 1 0\n"
        "newmtl blue\nKd 0 0 1\n",
        {"green", "red", "blue", "red", "green"});
    const TriangleMesh& mesh = *loaded.mesh;
    EXPECT_TRUE(loaded.warnings.empty()) << "the unused material's texture is never loaded";
    EXPECT_TRUE(textures_.requested().empty());
    EXPECT_EQ(mesh.materials.size(), 3u) << "only the materials that faces use";
    const std::vector<Color> expected{{0, 1, 0}, {1, 0, 0}, {0, 0, 1}, {1, 0, 0}, {0, 1, 0}};
    ASSERT_EQ(mesh.triangleCount(), expected.size());
    for (std::size_t t = 0; t < expected.size(); ++t)
        EXPECT_EQ(colorOf(*materialOf(mesh, t).diffuse), expected[t]) << "triangle " << t;
    EXPECT_EQ(mesh.faceMaterials[1], mesh.faceMaterials[3]);
}

TEST_F(MtlTest, FacesWithoutMaterialGetTheDefault) {
    folder_.write("model.mtl", "newmtl red\nKd 1 0 0\n");
    const fs::path obj = folder_.write("model.obj",
                                       "mtllib model.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\n"
                                       "f 1 2 3\nusemtl red\nf 1 3 2\n");
    const LoadedObj loaded = loadObj(obj);
    EXPECT_TRUE(loaded.warnings.empty());
    EXPECT_EQ(colorOf(*materialOf(*loaded.mesh, 0).diffuse),
              colorOf(*BlinnPhongMaterial::Parameters().diffuse));
    EXPECT_EQ(colorOf(*materialOf(*loaded.mesh, 1).diffuse), Color(1, 0, 0));
}

TEST_F(MtlTest, MissingMtlFileGivesOneWarningNamingItAndTheDefaultMaterial) {
    // Named twice: still one warning.
    const fs::path obj =
        folder_.write("model.obj", "mtllib missing.mtl\n" + trianglesUsing({"red", "green"}) +
                                       "mtllib missing.mtl\n" + trianglesUsing({"red"}));
    const LoadedObj loaded = loadObj(obj);
    EXPECT_EQ(loaded.warnings,
              std::vector<std::string>{obj.string() + ": warning: material library \"" +
                                       (folder_.path() / "missing.mtl").string() +
                                       "\" not found; the default grey material is used for its "
                                       "materials"});
    ASSERT_EQ(loaded.mesh->materials.size(), 1u);
    EXPECT_EQ(colorOf(*parametersOf(*loaded.mesh->materials[0]).diffuse),
              colorOf(*BlinnPhongMaterial::Parameters().diffuse));
}

TEST_F(MtlTest, UsemtlWithoutMtllibGivesOneWarning) {
    const fs::path obj = folder_.write("model.obj", trianglesUsing({"red", "green", "red"}));
    const LoadedObj loaded = loadObj(obj);
    EXPECT_EQ(loaded.warnings,
              std::vector<std::string>{obj.string() +
                                       ": warning: faces use materials \"red\", \"green\" but no "
                                       "material library (mtllib) is named; the default grey "
                                       "material is used"});
}

TEST_F(MtlTest, UndefinedMaterialGivesOneWarningNamingIt) {
    const LoadedObj loaded =
        loadWithMaterials("newmtl red\nKd 1 0 0\n", {"red", "nosuch", "nosuch"});
    ASSERT_EQ(loaded.warnings.size(), 1u);
    EXPECT_EQ(countContaining(loaded.warnings, "materials \"nosuch\" are not defined"), 1u);
    EXPECT_EQ(colorOf(*materialOf(*loaded.mesh, 1).diffuse),
              colorOf(*BlinnPhongMaterial::Parameters().diffuse));
}

TEST_F(MtlTest, MissingTextureGivesOneWarningNamingItAndKeepsKd) {
    const LoadedObj loaded = loadWithMaterials(
        "newmtl a\nKd 0.1 0.2 0.3\nmap_Kd gone.png\n"
        "newmtl b\nKd 0.4 0.5 0.6\nmap_Kd gone.png\n",
        {"a", "b"});
    const fs::path texture = folder_.path() / "gone.png";
    EXPECT_EQ(textures_.requested(), std::vector<fs::path>{texture});
    ASSERT_EQ(loaded.warnings.size(), 1u);
    EXPECT_EQ(loaded.warnings[0].rfind((folder_.path() / "model.mtl").string() + ": warning: ", 0),
              0u);
    EXPECT_EQ(countContaining(loaded.warnings, "texture \"" + texture.string() + "\""), 1u);
    EXPECT_EQ(countContaining(loaded.warnings, "(cannot open the image)"), 1u) << "the reason";
    EXPECT_EQ(colorOf(*materialOf(*loaded.mesh, 0).diffuse), Color(0.1f, 0.2f, 0.3f));
    EXPECT_EQ(colorOf(*materialOf(*loaded.mesh, 1).diffuse), Color(0.4f, 0.5f, 0.6f));
}

TEST_F(MtlTest, WindowsPathsInMapKdAreReadWithSlashes) {
    folder_.write("textures/wood.png", "");
    const BlinnPhongMaterial::Parameters material = loadMaterial("map_Kd .\\textures\\wood.png\n");
    EXPECT_EQ(textures_.requested(), std::vector<fs::path>{folder_.path() / "textures/wood.png"});
    EXPECT_EQ(colorOf(*material.diffuse), FakeTextures::kColor);
}

TEST_F(MtlTest, AbsolutePathOfAnotherMachineFallsBackToTheFileBesideTheMtl) {
    folder_.write("wood.png", "");
    const BlinnPhongMaterial::Parameters material =
        loadMaterial("map_Kd C:\\Users\\someone\\models\\wood.png\n");
    EXPECT_EQ(textures_.requested(), std::vector<fs::path>{folder_.path() / "wood.png"});
    EXPECT_EQ(colorOf(*material.diffuse), FakeTextures::kColor);
}

TEST_F(MtlTest, TexturePathsAreRelativeToTheMtlFolder) {
    folder_.write("materials/lib.mtl", "newmtl m\nmap_Kd wood.png\n");
    folder_.write("materials/wood.png", "");
    const LoadedObj loaded =
        loadObj(folder_.write("model.obj", "mtllib materials/lib.mtl\n" + trianglesUsing({"m"})),
                textures_);
    EXPECT_TRUE(loaded.warnings.empty());
    EXPECT_EQ(textures_.requested(), std::vector<fs::path>{folder_.path() / "materials/wood.png"});
}

TEST_F(MtlTest, EachTextureIsLoadedOnce) {
    folder_.write("wood.png", "");
    const LoadedObj loaded = loadWithMaterials(
        "newmtl a\nmap_Kd wood.png\nnewmtl b\nKs 1 1 1\nmap_Kd ./wood.png\n", {"a", "b"});
    EXPECT_EQ(textures_.requested().size(), 1u);
    EXPECT_EQ(materialOf(*loaded.mesh, 0).diffuse, materialOf(*loaded.mesh, 1).diffuse);
}

// The shading normal of triangle `triangle` of the mesh, in the plane z = 0 with u along +x and v
// along +y, seen from above it.
Vec3 shadingNormalOf(const TriangleMesh& mesh, std::size_t triangle) {
    Hit hit;
    hit.ng = hit.ns = Vec3(0, 0, 1);
    hit.dpdu = Vec3(1, 0, 0);
    hit.dpdv = Vec3(0, 1, 0);
    return mesh.materials.at(mesh.faceMaterials.at(triangle))->shadingNormal(hit, Vec3(0, 0, 1));
}

// norm is a tangent-space normal map read as data: the fake texture's (0.25, 0.5, 0.75) is
// n_ts = (-0.5, 0, 0.5), a normal leaning 45 degrees towards -u.
TEST_F(MtlTest, NormIsTheNormalMapReadAsData) {
    folder_.write("normals.png", "");
    const LoadedObj loaded = loadWithMaterials("newmtl m\nnorm normals.png\n", {"m"});
    EXPECT_TRUE(loaded.warnings.empty());
    EXPECT_EQ(textures_.requested(), std::vector<fs::path>{folder_.path() / "normals.png"});
    EXPECT_EQ(textures_.contents(), std::vector<ImageReader::Content>{ImageReader::Content::Data});
    const Vec3 n = shadingNormalOf(*loaded.mesh, 0);
    EXPECT_NEAR(n.x, -std::sqrt(0.5f), 1e-6f);
    EXPECT_NEAR(n.y, 0, 1e-6f);
    EXPECT_NEAR(n.z, std::sqrt(0.5f), 1e-6f);
}

// bump, map_Bump and map_bump (with their -bm multiplier) name the height map, read as data. A
// constant height has no slope: the normal stays.
TEST_F(MtlTest, BumpAndMapBumpAreTheBumpMapReadAsData) {
    folder_.write("a.png", "");
    folder_.write("b.png", "");
    folder_.write("c.png", "");
    const LoadedObj loaded = loadWithMaterials(
        "newmtl a\nbump -bm 0.5 a.png\nnewmtl b\nmap_Bump b.png\nnewmtl c\nmap_bump -bm 2 c.png\n",
        {"a", "b", "c"});
    EXPECT_TRUE(loaded.warnings.empty());
    EXPECT_EQ(textures_.requested(),
              (std::vector<fs::path>{folder_.path() / "a.png", folder_.path() / "b.png",
                                     folder_.path() / "c.png"}));
    EXPECT_EQ(textures_.contents(),
              std::vector<ImageReader::Content>(3, ImageReader::Content::Data));
    for (std::size_t i = 0; i < 3; ++i)
        EXPECT_EQ(shadingNormalOf(*loaded.mesh, i), Vec3(0, 0, 1));
}

TEST_F(MtlTest, NormWinsOverBumpWithAWarning) {
    folder_.write("normals.png", "");
    folder_.write("heights.png", "");
    const LoadedObj loaded =
        loadWithMaterials("newmtl m\nbump heights.png\nnorm normals.png\n", {"m"});
    ASSERT_EQ(loaded.warnings.size(), 1u);
    EXPECT_EQ(countContaining(loaded.warnings, "both a normal map (norm) and a bump map"), 1u);
    EXPECT_EQ(textures_.requested(), std::vector<fs::path>{folder_.path() / "normals.png"});
}

TEST_F(MtlTest, MissingNormalMapGivesOneWarningAndNoMap) {
    const LoadedObj loaded = loadWithMaterials("newmtl m\nnorm gone.png\n", {"m"});
    ASSERT_EQ(loaded.warnings.size(), 1u);
    EXPECT_EQ(countContaining(loaded.warnings,
                              "(norm of material \"m\") cannot be loaded; the "
                              "surface is shaded without it"),
              1u);
    EXPECT_EQ(shadingNormalOf(*loaded.mesh, 0), Vec3(0, 0, 1));
}

// One file as both a colour texture and a map is read twice, once as each.
TEST_F(MtlTest, OneFileAsColourAndAsMapIsReadOnceAsEach) {
    folder_.write("both.png", "");
    const LoadedObj loaded = loadWithMaterials("newmtl m\nmap_Kd both.png\nbump both.png\n", {"m"});
    EXPECT_TRUE(loaded.warnings.empty());
    EXPECT_EQ(textures_.contents(), (std::vector<ImageReader::Content>{
                                        ImageReader::Content::Color, ImageReader::Content::Data}));
}

}  // namespace
}  // namespace lancer::test
