// Real models (the Cornell boxes and the low-resolution bunny of scenes/models) and every malformed
// or unusual OBJ of the loader test suites in data/edge_cases.

#include <algorithm>
#include <set>

#include "MeshTestSupport.h"
#include "scene/InputError.h"

namespace lancer::test {
namespace {

namespace fs = std::filesystem;

// The mesh's materials by the diffuse colour that tells them apart in the Cornell box files.
const BlinnPhongMaterial::Parameters* findByDiffuse(const TriangleMesh& mesh,
                                                    const Color& diffuse) {
    for (const auto& material : mesh.materials)
        if (colorOf(*parametersOf(*material).diffuse) == diffuse) return &parametersOf(*material);
    return nullptr;
}

TEST(CornellBox, OriginalHas36TrianglesAndAnEmissiveLightFacingDown) {
    const LoadedObj loaded = loadObj(sceneModel("cornell_box/CornellBox-Original.obj"));
    const TriangleMesh& mesh = *loaded.mesh;
    EXPECT_TRUE(loaded.warnings.empty());
    EXPECT_EQ(mesh.triangleCount(), 36u) << "18 quads";
    EXPECT_EQ(mesh.positions.size(), 64u) << "72 vertices, 8 of them unused";
    EXPECT_TRUE(mesh.normals.empty());
    EXPECT_TRUE(mesh.uvs.empty());
    EXPECT_EQ(mesh.materials.size(), 8u);
    std::size_t lightTriangles = 0;
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        const BlinnPhongMaterial::Parameters& material = materialOf(mesh, t);
        if (material.emission.isBlack()) continue;
        ++lightTriangles;
        EXPECT_EQ(material.emission, Color(17, 12, 4));
        EXPECT_LT(areaVector(mesh, t).y, 0) << "the light emits on its front side, downwards";
    }
    EXPECT_EQ(lightTriangles, 2u);
    const BlinnPhongMaterial::Parameters* leftWall =
        findByDiffuse(mesh, Color(0.63f, 0.065f, 0.05f));
    ASSERT_NE(leftWall, nullptr);
    EXPECT_TRUE(leftWall->specular.isBlack());
    EXPECT_TRUE(leftWall->emission.isBlack());
}

TEST(CornellBox, MirrorBoxHasAFresnelMirrorBlock) {
    const LoadedObj loaded = loadObj(sceneModel("cornell_box/CornellBox-Mirror.obj"));
    EXPECT_TRUE(loaded.warnings.empty());
    std::size_t mirrorTriangles = 0;
    for (std::size_t t = 0; t < loaded.mesh->triangleCount(); ++t)
        mirrorTriangles += materialOf(*loaded.mesh, t).reflection == Color(0.95f);
    EXPECT_EQ(mirrorTriangles, 12u) << "the tall block: 6 quads, illum 5, Ks 0.95";
}

TEST(CornellBox, SphereBoxHasAMirrorSphereAndAGlassSphereWithNormalsAndUvs) {
    const LoadedObj loaded = loadObj(sceneModel("cornell_box/CornellBox-Sphere.obj"));
    const TriangleMesh& mesh = *loaded.mesh;
    EXPECT_TRUE(loaded.warnings.empty());
    EXPECT_EQ(mesh.triangleCount(), 2188u);
    EXPECT_EQ(mesh.normals.size(), mesh.positions.size());
    EXPECT_EQ(mesh.uvs.size(), mesh.positions.size());
    const Material* mirror = nullptr;
    const Material* glass = nullptr;
    for (const auto& material : mesh.materials) {
        if (parametersOf(*material).reflection == Color(0.95f)) mirror = material.get();
        if (material->isTransmissive()) glass = material.get();
    }
    ASSERT_NE(mirror, nullptr) << "leftSphere, illum 5";
    EXPECT_FALSE(mirror->isTransmissive());
    ASSERT_NE(glass, nullptr) << "rightSphere, illum 7";
    EXPECT_EQ(glass->transmission(), Color(1));
    EXPECT_FLOAT_EQ(parametersOf(*glass).ior, 2.5f);
    EXPECT_TRUE(parametersOf(*glass).reflection.isBlack())
        << "its reflection is the Fresnel share of kt";
}

TEST(LowResBunny, Has6598TrianglesWithUnitNormals) {
    const LoadedObj loaded = loadObj(sceneModel("stanford_bunny_lowres/bunny.obj"));
    const TriangleMesh& mesh = *loaded.mesh;
    EXPECT_TRUE(loaded.warnings.empty());
    EXPECT_EQ(mesh.triangleCount(), 6598u);
    ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
    for (const Vec3& n : mesh.normals)
        ASSERT_NEAR(length(n), 1, 1e-6);
}

// A mesh that the rest of the renderer can use without checking anything.
::testing::AssertionResult isWellFormed(const TriangleMesh& mesh) {
    const std::size_t vertices = mesh.positions.size();
    if (mesh.indices.size() % 3 != 0 || mesh.faceMaterials.size() != mesh.triangleCount())
        return ::testing::AssertionFailure() << "index and material counts disagree";
    if (!mesh.normals.empty() && mesh.normals.size() != vertices)
        return ::testing::AssertionFailure() << "one normal per vertex, or none";
    if (!mesh.uvs.empty() && mesh.uvs.size() != vertices)
        return ::testing::AssertionFailure() << "one uv per vertex, or none";
    for (const std::uint32_t index : mesh.indices)
        if (index >= vertices) return ::testing::AssertionFailure() << "index " << index;
    for (const std::uint32_t material : mesh.faceMaterials)
        if (material >= mesh.materials.size() || !mesh.materials[material])
            return ::testing::AssertionFailure() << "material " << material;
    for (const Vec3& p : mesh.positions)
        if (!isFinite(p)) return ::testing::AssertionFailure() << "non-finite position";
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t)
        if (!(length(areaVector(mesh, t)) > 0))
            return ::testing::AssertionFailure() << "zero-area triangle " << t;
    return ::testing::AssertionSuccess();
}

std::vector<fs::path> edgeCaseObjFiles() {
    std::vector<fs::path> files;
    for (const auto& entry : fs::recursive_directory_iterator(meshData("edge_cases")))
        if (entry.path().extension() == ".obj") files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    return files;
}

TEST(EdgeCases, EveryFileLoadsWithWarningsOrFailsWithAClearError) {
    const std::vector<fs::path> files = edgeCaseObjFiles();
    ASSERT_EQ(files.size(), 71u);
    std::set<std::string> failed;
    for (const fs::path& file : files) {
        SCOPED_TRACE(file.string());
        try {
            const LoadedObj loaded = loadObj(file);
            EXPECT_TRUE(isWellFormed(*loaded.mesh));
            const std::set<std::string> distinct(loaded.warnings.begin(), loaded.warnings.end());
            EXPECT_EQ(distinct.size(), loaded.warnings.size()) << "a warning repeated";
            for (const std::string& warning : loaded.warnings)
                EXPECT_TRUE(warning.find(".obj: warning: ") != std::string::npos ||
                            warning.find(".mtl: warning: ") != std::string::npos)
                    << "names the OBJ or MTL file: " << warning;
        } catch (const InputError& error) {
            failed.insert(file.filename().string());
            const std::string message = error.what();
            EXPECT_EQ(message.rfind(file.string() + ":", 0), 0u) << message;
            EXPECT_NE(message.find(": error: "), std::string::npos) << message;
        }
    }
    // The files with nothing to render in them, or that are not OBJ text at all.
    const std::set<std::string> expectedFailures{
        "box_UTF16BE.obj",                      // UTF-16
        "invalid-face-definition.obj",          // faces of 1 and 2 vertices
        "invalid-relative-texture-index.obj",   // no vertices at all
        "invalid-relative-vertex-index.obj",    // no vertices at all
        "issue-140-zero-face-idx.obj",          // index 0
        "issue-356-leading-spaces-newmtl.obj",  // usemtl only
        "line-prim.obj",                        // lines only
        "number_formats.obj",                   // its one triangle is a line
        "point_cloud.obj",                      // vertices only
        "points-prim.obj",                      // points only
        "testline.obj",                         // lines only
        "testpoints.obj",                       // points only
    };
    EXPECT_EQ(failed, expectedFailures);
}

struct EdgeCase {
    std::string file;      // under data/edge_cases
    std::string expected;  // in one of the warnings, or in the error
};

TEST(EdgeCases, EachProblemIsReportedOnce) {
    const std::string tinyobj = "tinyobjloader/models/", assimp = "assimp_obj/";
    const std::vector<EdgeCase> cases{
        {assimp + "box_longline.obj", "more than 255 vertices"},
        {assimp + "box_UTF16BE.obj", "error: is UTF-16 text"},
        {assimp + "cube_mtllib_after_g.obj", "cube_mtllib_after_g.mat\" not found"},
        {assimp + "cube_usemtl.obj", "materials \"mtl3\" are not defined"},
        {assimp + "mtl_different_folder.obj", "folder/image.jpg\" (map_Kd of material"},
        {assimp + "point_cloud.obj", "error: no faces (f) to render"},
        {assimp + "testmixed.obj", "points (p) and lines (l) are not rendered"},
        {tinyobj + "catmark_torus_creases0.obj", "32 faces with normal (vn) indices out of range"},
        {tinyobj + "invalid-face-definition.obj", "error: none of its 2 faces can be rendered"},
        {tinyobj + "issue-140-zero-face-idx.obj", ":16:1: error: index 0"},
        {tinyobj + "issue-319-002.obj", "1 zero-area triangle dropped"},
        {tinyobj + "missing_material_file.obj", "no material library (mtllib) is named"},
        {tinyobj + "texture-filename-with-whitespace.obj", "texture 01.png\""},
    };
    for (const EdgeCase& c : cases) {
        SCOPED_TRACE(c.file);
        const std::string text = loadOutcome(meshData("edge_cases/" + c.file));
        const std::size_t first = text.find(c.expected);
        EXPECT_NE(first, std::string::npos) << text;
        EXPECT_EQ(text.find(c.expected, first + 1), std::string::npos) << "reported twice:\n"
                                                                       << text;
    }
    const std::string missingLibraries =
        loadOutcome(meshData("edge_cases/" + tinyobj + "mtllib-multiple-files-issue-112.obj"));
    EXPECT_NE(missingLibraries.find("invalid-file-aaa.mtl\" not found"), std::string::npos);
    EXPECT_NE(missingLibraries.find("invalid-file-bbb.mtl\" not found"), std::string::npos);
}

}  // namespace
}  // namespace lancer::test
