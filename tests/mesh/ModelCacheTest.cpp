// The model cache: a model taken from its entry is the model built from its file, with the same
// materials, warnings and MTL files; an entry out of date (the OBJ, an MTL file, the smoothing,
// the program changed) is not used; a damaged entry is refused with a warning, never trusted.

#include <algorithm>
#include <chrono>
#include <cstring>
#include <fstream>
#include <functional>

#include "MeshTestSupport.h"
#include "accel/Mesh.h"
#include "geometry/SmoothingByAngle.h"
#include "io/ModelCache.h"

namespace lancer::test {
namespace {

namespace fs = std::filesystem;

template <typename T>
bool sameBytes(std::span<const T> a, std::span<const T> b) {
    // (memcmp must not be given the null data of an empty array, even for no bytes.)
    return a.size() == b.size() &&
           (a.empty() || std::memcmp(a.data(), b.data(), a.size_bytes()) == 0);
}

class ModelCacheTest : public ::testing::Test {
protected:
    ModelCacheTest() {
        // A 12 x 12 grid of quads in two materials (one defined, one not), a textured one, a
        // face of two vertices and a zero-area triangle: warnings before and after the materials.
        folder_.write("grid.mtl", "newmtl red\nKd 1 0 0\nmap_Kd red.png\n");
        folder_.write("red.png", "a texture");
        std::string obj = "mtllib grid.mtl\n";
        constexpr int kSide = 12;
        for (int y = 0; y <= kSide; ++y)
            for (int x = 0; x <= kSide; ++x)
                obj += "v " + std::to_string(x) + " " + std::to_string(y) + " " +
                       std::to_string((x * y) % 3) + "\n";
        for (int y = 0; y < kSide; ++y) {
            obj += y % 2 == 0 ? "usemtl red\n" : "usemtl missing\n";
            for (int x = 0; x < kSide; ++x) {
                const int a = y * (kSide + 1) + x + 1, b = a + 1, c = a + kSide + 2,
                          d = a + kSide + 1;
                obj += "f " + std::to_string(a) + " " + std::to_string(b) + " " +
                       std::to_string(c) + " " + std::to_string(d) + "\n";
            }
        }
        obj += "f 1 2\nf 1 2 3\nf 1 1 1\n";
        obj_ = folder_.write("grid.obj", obj);
    }

    ModelCache cache(const std::string& identity = "test build") const {
        return ModelCache(folder_.path() / "cache", identity, 0);
    }

    // The model read and built from its file, as the scene loader does without an entry; kept in
    // `cache` when given. `meanwhile` runs once the files are read, before the model is kept.
    std::shared_ptr<const Mesh> build(const ModelCache* cache,
                                      const std::optional<float>& smooth = std::nullopt,
                                      const std::function<void()>& meanwhile = {}) {
        warnings_.clear();
        materialFiles_.clear();
        ObjLoader::Geometry geometry = ObjLoader::readGeometry(obj_);
        if (meanwhile) meanwhile();
        geometry.triangles->materials = ObjLoader::complete(
            obj_, geometry.completion, textures_.loader(), warnings_, &materialFiles_);
        if (smooth) SmoothingByAngle::apply(*geometry.triangles, *smooth);
        auto mesh = std::make_shared<const Mesh>(std::move(*geometry.triangles));
        if (cache)
            cache->storeObj(obj_, smooth, geometry.completion, geometry.sources, *mesh, warnings_);
        return mesh;
    }

    std::shared_ptr<const Mesh> find(const ModelCache& cache,
                                     const std::optional<float>& smooth = std::nullopt) {
        warnings_.clear();
        materialFiles_.clear();
        return cache.findObj(obj_, smooth, textures_.loader(), warnings_, materialFiles_);
    }

    std::vector<fs::path> entries() const {
        std::vector<fs::path> found;
        if (fs::exists(folder_.path() / "cache"))
            for (const auto& entry : fs::directory_iterator(folder_.path() / "cache"))
                found.push_back(entry.path());
        return found;
    }

    static void expectSameMesh(const Mesh& a, const Mesh& b) {
        const TriangleMesh &ta = a.triangles(), &tb = b.triangles();
        EXPECT_TRUE(sameBytes<Vec3>(ta.positions, tb.positions));
        EXPECT_TRUE(sameBytes<Vec3>(ta.normals, tb.normals));
        EXPECT_TRUE(sameBytes<Vec2>(ta.uvs, tb.uvs));
        EXPECT_TRUE(sameBytes<std::uint32_t>(ta.indices, tb.indices));
        EXPECT_TRUE(sameBytes<std::uint32_t>(ta.faceMaterials, tb.faceMaterials));
        ASSERT_EQ(ta.materials.size(), tb.materials.size());
        for (std::size_t i = 0; i < ta.materials.size(); ++i)
            EXPECT_EQ(colorOf(*parametersOf(*ta.materials[i]).diffuse),
                      colorOf(*parametersOf(*tb.materials[i]).diffuse));
        EXPECT_TRUE(sameBytes(a.bvhNodes(), b.bvhNodes()));
        EXPECT_TRUE(sameBytes(a.packs(), b.packs()));
        EXPECT_EQ(a.bounds().min, b.bounds().min);
        EXPECT_EQ(a.bounds().max, b.bounds().max);
    }

    // Rewrites the bytes of the only entry with `change`.
    void damageEntry(const std::function<void(std::string&)>& change) {
        ASSERT_EQ(entries().size(), 1u);
        const fs::path entry = entries().front();
        std::ifstream in(entry, std::ios::binary);
        std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        in.close();
        change(bytes);
        std::ofstream(entry, std::ios::binary | std::ios::trunc) << bytes;
    }

    ScratchFolder folder_;
    fs::path obj_;
    FakeTextures textures_;
    std::vector<std::string> warnings_;
    std::vector<fs::path> materialFiles_;
};

TEST_F(ModelCacheTest, AnEntryGivesTheModelBuiltFromTheFile) {
    const ModelCache models = cache();
    EXPECT_EQ(find(models), nullptr);  // nothing kept yet
    const std::shared_ptr<const Mesh> built = build(&models);
    const std::vector<std::string> builtWarnings = warnings_;
    const std::vector<fs::path> builtMaterialFiles = materialFiles_;
    ASSERT_EQ(entries().size(), 1u);
    ASSERT_GE(builtWarnings.size(), 3u);  // the undefined material, the short and flat faces

    const std::shared_ptr<const Mesh> found = find(models);
    ASSERT_NE(found, nullptr);
    expectSameMesh(*built, *found);
    EXPECT_EQ(warnings_, builtWarnings);
    EXPECT_EQ(materialFiles_, builtMaterialFiles);
    // The texture is loaded again (the scene loader's own cache shares it).
    EXPECT_EQ(std::count(textures_.requested().begin(), textures_.requested().end(),
                         folder_.path() / "red.png"),
              2);
}

TEST_F(ModelCacheTest, EachSmoothingAngleHasItsOwnEntry) {
    const ModelCache models = cache();
    const std::shared_ptr<const Mesh> smoothed = build(&models, 30.0f);
    EXPECT_EQ(find(models), nullptr);
    EXPECT_EQ(find(models, 45.0f), nullptr);
    const std::shared_ptr<const Mesh> found = find(models, 30.0f);
    ASSERT_NE(found, nullptr);
    expectSameMesh(*smoothed, *found);
}

TEST_F(ModelCacheTest, AChangedModelOrMaterialFileOrProgramIsReadAgain) {
    const ModelCache models = cache();
    build(&models);
    ASSERT_NE(find(models), nullptr);
    EXPECT_EQ(find(cache("another build")), nullptr);

    // The MTL file changed: other materials, maybe other faces' materials.
    folder_.write("grid.mtl", "newmtl red\nKd 0 1 0\n");
    EXPECT_EQ(find(models), nullptr);
    const std::shared_ptr<const Mesh> rebuilt = build(&models);
    EXPECT_EQ(entries().size(), 1u);  // the model's entry, replaced
    const std::shared_ptr<const Mesh> found = find(models);
    ASSERT_NE(found, nullptr);
    expectSameMesh(*rebuilt, *found);

    // The OBJ changed (a size of its own, so that a coarse clock cannot hide it).
    std::ofstream(obj_, std::ios::app) << "# one more line\n";
    EXPECT_EQ(find(models), nullptr);
}

TEST_F(ModelCacheTest, AFileChangedWhileTheModelWasReadLeavesNoEntryForTheNewFile) {
    // As when an exporter finishes writing the model while it is read: the entry holds the old
    // triangles or materials, and must not pass for the files as they are afterwards.
    const ModelCache models = cache();
    build(&models, std::nullopt, [&] { std::ofstream(obj_, std::ios::app) << "# meanwhile\n"; });
    EXPECT_EQ(find(models), nullptr);
    build(&models, std::nullopt, [&] { folder_.write("grid.mtl", "newmtl red\nKd 0 0 1\n"); });
    EXPECT_EQ(find(models), nullptr);
    // Unchanged since, the files are read and kept again, and the entry is then taken.
    const std::shared_ptr<const Mesh> rebuilt = build(&models);
    const std::shared_ptr<const Mesh> found = find(models);
    ASSERT_NE(found, nullptr);
    expectSameMesh(*rebuilt, *found);
}

TEST_F(ModelCacheTest, SmallModelsAreNotKept) {
    const ModelCache models(folder_.path() / "cache", "test build", fs::file_size(obj_) + 1);
    build(&models);
    EXPECT_TRUE(entries().empty());
    EXPECT_EQ(find(models), nullptr);
}

TEST_F(ModelCacheTest, TheEntriesWrittenLongestAgoMakeRoomForANewOne) {
    // Three models whose entries have the same size: the same file under three names of the
    // same length (the warnings kept name it), written in turn.
    for (const char* name : {"a.obj", "b.obj", "c.obj"})
        fs::copy_file(obj_, folder_.path() / name);
    obj_ = folder_.path() / "a.obj";
    const ModelCache unbounded = cache();
    build(&unbounded);
    const std::uintmax_t entryBytes = fs::file_size(entries().front());
    fs::remove(entries().front());
    // Room for two entries, less a byte.
    const ModelCache models(folder_.path() / "cache", "test build", 0, 2 * entryBytes - 1);
    std::vector<fs::path> kept;
    for (const char* name : {"a.obj", "b.obj", "c.obj"}) {
        obj_ = folder_.path() / name;
        build(&models);
        kept = entries();
        ASSERT_EQ(kept.size(), 1u) << name;  // the one just written, never deleted
        ASSERT_NE(find(models), nullptr) << name;
    }
    // Room for two: the oldest goes, the two newest stay. Each entry is dated an hour after the
    // one before (a file system's clock may give entries written in a row the same time).
    fs::remove_all(folder_.path() / "cache");
    const ModelCache roomier(folder_.path() / "cache", "test build", 0, 2 * entryBytes);
    const fs::file_time_type start = fs::file_time_type::clock::now() - std::chrono::hours(10);
    int hour = 0;
    for (const char* name : {"a.obj", "b.obj", "c.obj"}) {
        const std::vector<fs::path> before = entries();
        obj_ = folder_.path() / name;
        build(&roomier);
        for (const fs::path& entry : entries())
            if (std::find(before.begin(), before.end(), entry) == before.end())
                fs::last_write_time(entry, start + std::chrono::hours(hour++));
    }
    EXPECT_EQ(entries().size(), 2u);
    obj_ = folder_.path() / "a.obj";
    EXPECT_EQ(find(roomier), nullptr);
    for (const char* name : {"b.obj", "c.obj"}) {
        obj_ = folder_.path() / name;
        EXPECT_NE(find(roomier), nullptr) << name;
    }
}

TEST_F(ModelCacheTest, ATruncatedEntryIsRefusedWithAWarning) {
    const ModelCache models = cache();
    build(&models);
    damageEntry([](std::string& bytes) { bytes.resize(bytes.size() - 100); });
    EXPECT_EQ(find(models), nullptr);
    ASSERT_EQ(warnings_.size(), 1u);
    EXPECT_NE(warnings_[0].find("model cache entry is truncated"), std::string::npos)
        << warnings_[0];
    EXPECT_NE(warnings_[0].find(entries().front().string()), std::string::npos) << warnings_[0];
}

TEST_F(ModelCacheTest, AnEntryWhoseTreeLoopsIsRefusedWithAWarning) {
    const ModelCache models = cache();
    const std::shared_ptr<const Mesh> built = build(&models);
    ASSERT_GT(built->bvhNodes().size(), 1u);
    // The root's first interior child made to point back at the root.
    const WideBvhNode& root = built->bvhNodes()[0];
    int slot = 0;
    while (root.primitiveCount[slot] != 0 || root.child[slot] == 0)
        ++slot;
    damageEntry([&](std::string& bytes) {
        const auto at = bytes.find(std::string(reinterpret_cast<const char*>(&root), sizeof root));
        ASSERT_NE(at, std::string::npos);
        const std::uint32_t toRoot = 0;
        // Slot 0 of an unused child is refused as well; an interior one now loops.
        std::memcpy(&bytes[at + offsetof(WideBvhNode, child) + slot * sizeof(std::uint32_t)],
                    &toRoot, sizeof toRoot);
        const float box[2] = {0, 1};  // so that the slot cannot pass for an unused one
        std::memcpy(&bytes[at + offsetof(WideBvhNode, bounds) + slot * sizeof(float)], &box[0],
                    sizeof(float));
        std::memcpy(&bytes[at + offsetof(WideBvhNode, bounds) +
                           (3 * WideBvhNode::kWidth + slot) * sizeof(float)],
                    &box[1], sizeof(float));
    });
    EXPECT_EQ(find(models), nullptr);
    ASSERT_EQ(warnings_.size(), 1u);
    EXPECT_NE(warnings_[0].find("model cache entry is damaged"), std::string::npos) << warnings_[0];
}

TEST_F(ModelCacheTest, AFileThatIsNoEntryIsRefusedWithAWarning) {
    const ModelCache models = cache();
    build(&models);
    damageEntry([](std::string& bytes) { bytes = "not a model at all"; });
    EXPECT_EQ(find(models), nullptr);
    ASSERT_EQ(warnings_.size(), 1u);
    EXPECT_NE(warnings_[0].find("not a lancer model cache entry"), std::string::npos);
}

TEST_F(ModelCacheTest, AFolderThatCannotBeWrittenIsAWarning) {
    folder_.write("cache", "a file where the folder would be");
    const ModelCache models = cache();
    build(&models);
    ASSERT_EQ(countContaining(warnings_, "not kept in the model cache"), 1u);
    EXPECT_EQ(find(models), nullptr);
}

}  // namespace
}  // namespace lancer::test
