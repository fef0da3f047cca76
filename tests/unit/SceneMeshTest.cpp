// The scene file's "mesh" objects, "transform" blocks and image textures.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "IntersectInto.h"
#include "io/SceneLoader.h"
#include "materials/Material.h"
#include "scene/InputError.h"

namespace lancer {
namespace {

namespace fs = std::filesystem;

// A scene file and the files it refers to, in a folder of their own.
class SceneMeshTest : public ::testing::Test {
protected:
    void SetUp() override {
        folder_ = fs::temp_directory_path() /
                  ("lancer-scene-mesh-" +
                   std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::remove_all(folder_);
        fs::create_directories(folder_ / "models");
        // A unit quad in the z = 0 plane, facing +z: two triangles.
        write("models/quad.obj", "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3 4\n");
    }
    void TearDown() override { fs::remove_all(folder_); }

    void write(const std::string& name, const std::string& text) const {
        std::ofstream(folder_ / name, std::ios::binary) << text;
    }

    Scene load(const std::string& objects, const std::string& materials = "{}") {
        const std::string text = R"({ "camera": { "position": [0, 0, 10], "look_at": [0, 0, 0] },
  "materials": )" + materials + R"(,
  "objects": [)" + objects + "] }";
        write("scene.json", text);
        warnings.clear();
        return SceneLoader::loadFile(folder_ / "scene.json", warnings);
    }

    // The error message of loading the scene, which must fail.
    std::string loadError(const std::string& objects, const std::string& materials = "{}") {
        try {
            load(objects, materials);
        } catch (const InputError& e) {
            return e.what();
        }
        ADD_FAILURE() << "the scene loaded";
        return "";
    }

    static bool hitsAt(const Scene& scene, const Vec3& origin, const Vec3& direction, Vec3& point) {
        Hit hit;
        if (!test::intersectInto(scene, {origin, direction}, kInfinity, hit)) return false;
        point = hit.p;
        return true;
    }

    fs::path folder_;
    std::vector<std::string> warnings;
};

TEST_F(SceneMeshTest, MeshPathsAreRelativeToTheSceneFile) {
    const Scene scene = load(R"({ "type": "mesh", "file": "models/quad.obj" })");
    Vec3 p;
    EXPECT_TRUE(hitsAt(scene, {0.5f, 0.5f, 5}, {0, 0, -1}, p));
    EXPECT_NEAR(p.z, 0, 1e-6f);
    EXPECT_FALSE(hitsAt(scene, {1.5f, 0, 5}, {0, 0, -1}, p));
    EXPECT_EQ(scene.statistics().uniqueTriangles, 2u);
}

TEST_F(SceneMeshTest, AModelUsedSeveralTimesIsStoredOnce) {
    const Scene scene = load(R"({ "type": "mesh", "file": "models/quad.obj" },
        { "type": "mesh", "file": "models/quad.obj", "transform": { "translate": [5, 0, 0] } },
        { "type": "mesh", "file": "models/../models/quad.obj", "transform": { "translate": [-5, 0, 0] } })");
    EXPECT_EQ(scene.statistics().uniqueTriangles, 2u);
    EXPECT_EQ(scene.statistics().instancedTriangles, 6u);
    Vec3 p;
    EXPECT_TRUE(hitsAt(scene, {5.5f, 0, 5}, {0, 0, -1}, p));
    EXPECT_TRUE(hitsAt(scene, {-5.5f, 0, 5}, {0, 0, -1}, p));
    EXPECT_FALSE(hitsAt(scene, {3, 0, 5}, {0, 0, -1}, p));
}

TEST_F(SceneMeshTest, TransformAppliesScaleThenRotateThenTranslate) {
    // The quad scaled by 2 along x (x in [-2, 2]), turned a quarter about y (x -> -z), then moved
    // up by 10: it now spans z in [-2, 2] at x = 0, facing +x, around y = 10.
    const Scene scene = load(R"({ "type": "mesh", "file": "models/quad.obj",
        "transform": { "scale": [2, 1, 1], "rotate": [0, 1, 0, 90], "translate": [0, 10, 0] } })");
    Vec3 p;
    ASSERT_TRUE(hitsAt(scene, {5, 10, 1.9f}, {-1, 0, 0}, p));
    EXPECT_NEAR(p.x, 0, 1e-5f);
    EXPECT_FALSE(hitsAt(scene, {5, 10, 2.1f}, {-1, 0, 0}, p));
    EXPECT_FALSE(hitsAt(scene, {5, 0, 0}, {-1, 0, 0}, p));
}

TEST_F(SceneMeshTest, MatrixIsRowMajorAsRowsOrAsSixteenNumbers) {
    for (const std::string matrix : {"[[1, 0, 0, 3], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]",
                                     "[1, 0, 0, 3, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]"}) {
        const Scene scene = load(R"({ "type": "sphere", "center": [0, 0, 0], "radius": 1,
            "transform": { "matrix": )" +
                                 matrix + " } }");
        Vec3 p;
        ASSERT_TRUE(hitsAt(scene, {3, 0, 5}, {0, 0, -1}, p)) << matrix;
        EXPECT_NEAR(p.z, 1, 1e-5f);
        EXPECT_FALSE(hitsAt(scene, {0, 0, 5}, {0, 0, -1}, p)) << matrix;
    }
}

TEST_F(SceneMeshTest, EveryShapeTakesATransform) {
    const Scene scene = load(R"({ "type": "sphere", "center": [0, 0, 0], "radius": 1,
            "transform": { "scale": [3, 1, 1], "translate": [0, 20, 0] } },
        { "type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "transform": { "translate": [0, -7, 0] } },
        { "type": "triangle", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "transform": { "scale": 4 } })");
    Vec3 p;
    ASSERT_TRUE(hitsAt(scene, {2.9f, 20, 5}, {0, 0, -1}, p));  // the stretched sphere
    ASSERT_TRUE(hitsAt(scene, {50, 0, 3}, {0, -1, 0}, p));     // the lowered plane
    EXPECT_NEAR(p.y, -7, 1e-5f);
    ASSERT_TRUE(hitsAt(scene, {3.5f, 0.4f, 5}, {0, 0, -1}, p));  // the enlarged triangle
}

TEST_F(SceneMeshTest, MeshMaterialReplacesTheModelsOwn) {
    write("models/red.mtl", "newmtl red\nKd 1 0 0\n");
    write("models/red.obj", "mtllib red.mtl\nv -1 -1 0\nv 1 -1 0\nv 0 1 0\nusemtl red\nf 1 2 3\n");
    const Scene own = load(R"({ "type": "mesh", "file": "models/red.obj" })");
    const Scene replaced =
        load(R"({ "type": "mesh", "file": "models/red.obj", "material": "blue" })",
             R"({ "blue": { "diffuse": [0, 0, 1] } })");
    Hit a, b;
    ASSERT_TRUE(test::intersectInto(own, {{0, 0, 5}, {0, 0, -1}}, kInfinity, a));
    ASSERT_TRUE(test::intersectInto(replaced, {{0, 0, 5}, {0, 0, -1}}, kInfinity, b));
    EXPECT_EQ(a.material->diffuseReflectance(a), Color(1, 0, 0));
    EXPECT_EQ(b.material->diffuseReflectance(b), Color(0, 0, 1));
}

struct BadInput {
    const char* name;
    const char* objects;   // starting on line 3, column 15 of the scene file
    const char* location;  // "LINE:COL" of the value at fault
    const char* expected;  // what the message must name
};

class SceneMeshErrorTest : public SceneMeshTest, public ::testing::WithParamInterface<BadInput> {};

TEST_P(SceneMeshErrorTest, NamesTheFileLineAndKey) {
    const std::string message = loadError(GetParam().objects);
    EXPECT_NE(message.find("scene.json:" + std::string(GetParam().location) + ": error: "),
              std::string::npos)
        << message;
    EXPECT_NE(message.find(GetParam().expected), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

INSTANTIATE_TEST_SUITE_P(
    SceneMesh, SceneMeshErrorTest,
    ::testing::Values(
        BadInput{"MissingMesh", R"({ "type": "mesh", "file": "models/nowhere.obj" })", "3:41",
                 "nowhere.obj"},
        BadInput{"MeshWithoutFile", R"({ "type": "mesh" })", "3:15", "\"file\""},
        BadInput{"MatrixAndScale", R"({ "type": "sphere", "center": [0,0,0], "radius": 1,
            "transform": { "scale": 2, "matrix": [1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1] } })",
                 "4:50", "\"matrix\""},
        BadInput{"SingularMatrix", R"({ "type": "sphere", "center": [0,0,0], "radius": 1,
            "transform": { "matrix": [1,0,0,0, 0,0,0,0, 0,0,1,0, 0,0,0,1] } })",
                 "4:38", "singular"},
        BadInput{"MatrixOfWrongSize", R"({ "type": "sphere", "center": [0,0,0], "radius": 1,
            "transform": { "matrix": [1, 2, 3] } })",
                 "4:38", "\"matrix\""},
        BadInput{
            "ZeroScale",
            R"({ "type": "sphere", "center": [0,0,0], "radius": 1, "transform": { "scale": [1, 0, 1] } })",
            "3:91", "\"scale\""},
        BadInput{"RotateWithoutAngle", R"({ "type": "sphere", "center": [0,0,0], "radius": 1,
            "transform": { "rotate": [0, 1, 0] } })",
                 "4:38", "\"rotate\""},
        BadInput{"MisspeltTransformKey", R"({ "type": "sphere", "center": [0,0,0], "radius": 1,
            "transform": { "translat": [0, 1, 0] } })",
                 "4:28", "did you mean \"translate\""}),
    [](const ::testing::TestParamInfo<BadInput>& param) { return std::string(param.param.name); });

// The texture error needs a material that names a missing file: give it through the materials.
TEST_F(SceneMeshTest, MissingTextureIsAnErrorAtItsKey) {
    const std::string message =
        loadError(R"({ "type": "sphere", "center": [0,0,0], "radius": 1, "material": "wood" })",
                  R"({ "wood": { "diffuse": { "texture": "textures/wood.png" } } })");
    EXPECT_NE(message.find("scene.json:2:52: error: texture"), std::string::npos) << message;
    EXPECT_NE(message.find("wood.png"), std::string::npos) << message;
}

}  // namespace
}  // namespace lancer
