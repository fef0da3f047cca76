// libFuzzer target: the reader of model cache entries (--model-cache). An entry is taken only
// when its header names the model as it is, so the target makes a real entry for a small model
// once, keeps its header (magic, the model's fingerprint, no MTL library, their fingerprint) and
// puts the input after it: the mutations reach the arrays and the tree. A damaged entry must be
// refused with a warning; an entry taken must make a mesh that rays can traverse. Anything else
// is a finding.

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>
#include <vector>

#include "FuzzFolder.h"
#include "accel/Mesh.h"
#include "io/ModelCache.h"
#include "math/Ray.h"

namespace {

namespace fs = std::filesystem;

// The header of an entry for this program and model: 16 bytes of magic, the model's
// fingerprint, no library names, and the fingerprint of none.
constexpr std::size_t kHeaderBytes = 16 + 8 + 8 + 8;

struct CachedModel {
    fs::path obj;
    lancer::ModelCache cache{lancer::fuzz::FuzzFolder::path() / "cache", "fuzz", 0};
    fs::path entry;
    std::string header;

    CachedModel() {
        // A bumpy 6 x 6 grid: a tree of a few nodes.
        std::string text;
        for (int y = 0; y <= 6; ++y)
            for (int x = 0; x <= 6; ++x)
                text += "v " + std::to_string(x) + " " + std::to_string(y) + " " +
                        std::to_string((x * y) % 3) + "\n";
        for (int y = 0; y < 6; ++y)
            for (int x = 0; x < 6; ++x) {
                const int a = y * 7 + x + 1;
                text += "f " + std::to_string(a) + " " + std::to_string(a + 1) + " " +
                        std::to_string(a + 8) + " " + std::to_string(a + 7) + "\n";
            }
        obj = lancer::fuzz::FuzzFolder::write("model.obj", text);
        std::vector<std::string> warnings;
        lancer::ObjLoader::Geometry geometry = lancer::ObjLoader::readGeometry(obj);
        geometry.triangles->materials =
            lancer::ObjLoader::complete(obj, geometry.completion, noTexture(), warnings);
        const lancer::Mesh mesh(std::move(*geometry.triangles));
        cache.storeObj(obj, std::nullopt, geometry.completion, geometry.sources, mesh, warnings);
        entry = fs::directory_iterator(lancer::fuzz::FuzzFolder::path() / "cache")->path();
        std::ifstream in(entry, std::ios::binary);
        header.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
        header.resize(kHeaderBytes);
    }

    static lancer::ObjLoader::TextureLoader noTexture() {
        return [](const fs::path&, lancer::ImageReader::Content) {
            return std::shared_ptr<const lancer::Texture>();
        };
    }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static CachedModel model;
    {
        std::ofstream out(model.entry, std::ios::binary | std::ios::trunc);
        out << model.header << lancer::fuzz::asText(data, size);
    }
    std::vector<std::string> warnings;
    std::vector<fs::path> materialFiles;
    const std::shared_ptr<const lancer::Mesh> mesh = model.cache.findObj(
        model.obj, std::nullopt, CachedModel::noTexture(), warnings, materialFiles);
    if (!mesh) return 0;
    // Rays through the mesh's box from its corners, and along its axes, both queries.
    const lancer::Bounds3 box = mesh->bounds();
    for (int corner = 0; corner < 8; ++corner) {
        const lancer::Vec3 from((corner & 1) ? box.max.x : box.min.x,
                                (corner & 2) ? box.max.y : box.min.y,
                                (corner & 4) ? box.max.z : box.min.z);
        const lancer::Vec3 towards = box.centroid() - from;
        if (!(lancer::lengthSquared(towards) > 0)) continue;
        const lancer::Ray ray{from - towards, lancer::normalize(towards)};
        if (const auto crossing = mesh->cross(ray, lancer::kInfinity)) mesh->record(ray, *crossing);
        mesh->occluded(ray, lancer::kInfinity);
    }
    return 0;
}
