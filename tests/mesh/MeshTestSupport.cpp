#include "MeshTestSupport.h"

#include <fstream>
#include <random>

#include "geometry/Hit.h"
#include "materials/ConstantTexture.h"
#include "scene/InputError.h"

namespace lancer::test {

namespace fs = std::filesystem;

fs::path meshData(const std::string& relativePath) {
    return fs::path(LANCER_MESH_TEST_DATA) / relativePath;
}

fs::path sceneModel(const std::string& relativePath) {
    return fs::path(LANCER_SCENE_MODELS) / relativePath;
}

ScratchFolder::ScratchFolder() {
    const ::testing::TestInfo* test = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = std::string(test->test_suite_name()) + "." + test->name();
    for (char& c : name)
        if (c == '/') c = '_';  // parametrized test names
    path_ = fs::path(::testing::TempDir()) /
            ("lancer_mesh_" + name + "_" + std::to_string(std::random_device{}()));
    fs::create_directories(path_);
}

ScratchFolder::~ScratchFolder() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
}

fs::path ScratchFolder::write(const std::string& relativePath, const std::string& bytes) const {
    const fs::path file = path_ / relativePath;
    fs::create_directories(file.parent_path());
    std::ofstream out(file, std::ios::binary);
    out << bytes;
    if (!out) ADD_FAILURE() << "cannot write " << file;
    return file;
}

ObjLoader::TextureLoader FakeTextures::loader() {
    return [this](const fs::path& path,
                  ImageReader::Content content) -> std::shared_ptr<const Texture> {
        requested_.push_back(path);
        contents_.push_back(content);
        if (!fs::exists(path)) throw InputError(path.string(), "cannot open the image");
        return std::make_shared<ConstantTexture>(kColor);
    };
}

LoadedObj loadObj(const fs::path& path, FakeTextures& textures) {
    LoadedObj loaded;
    loaded.mesh = ObjLoader::load(path, textures.loader(), loaded.warnings);
    return loaded;
}

LoadedObj loadObj(const fs::path& path) {
    FakeTextures textures;
    return loadObj(path, textures);
}

std::string loadOutcome(const fs::path& path) {
    try {
        std::string warnings;
        for (const std::string& warning : loadObj(path).warnings)
            warnings += warning + "\n";
        return warnings;
    } catch (const InputError& error) {
        return error.what();
    }
}

Vec3 areaVector(const TriangleMesh& mesh, std::size_t triangle) {
    const Vec3& p0 = mesh.positions[mesh.indices[3 * triangle]];
    const Vec3& p1 = mesh.positions[mesh.indices[3 * triangle + 1]];
    const Vec3& p2 = mesh.positions[mesh.indices[3 * triangle + 2]];
    return cross(p1 - p0, p2 - p0);
}

double totalArea(const TriangleMesh& mesh) {
    double area = 0;
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t)
        area += 0.5 * length(Vec3d(areaVector(mesh, t)));
    return area;
}

double polygonArea(const std::vector<Vec3>& corners) {
    Vec3d sum;
    for (std::size_t i = 0; i < corners.size(); ++i)
        sum += cross(Vec3d(corners[i]), Vec3d(corners[(i + 1) % corners.size()]));
    return 0.5 * length(sum);
}

const BlinnPhongMaterial::Parameters& parametersOf(const Material& material) {
    return dynamic_cast<const BlinnPhongMaterial&>(material).parameters();
}

const BlinnPhongMaterial::Parameters& materialOf(const TriangleMesh& mesh, std::size_t triangle) {
    return parametersOf(*mesh.materials.at(mesh.faceMaterials.at(triangle)));
}

Color colorOf(const Texture& texture) {
    return texture.evaluate(Hit{});
}

std::size_t countContaining(const std::vector<std::string>& warnings, const std::string& text) {
    std::size_t count = 0;
    for (const std::string& warning : warnings)
        count += warning.find(text) != std::string::npos;
    return count;
}

std::string faceLine(int first, int count) {
    std::string line = "f";
    for (int i = 0; i < count; ++i)
        line += " " + std::to_string(first + i);
    return line + "\n";
}

}  // namespace lancer::test
