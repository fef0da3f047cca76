#pragma once

// Helpers shared by the OBJ/MTL tests: the model files, a scratch folder for files written
// by a test, a stand-in for the scene loader's texture loader, and measures of a loaded mesh.

#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "geometry/TriangleMesh.h"
#include "io/ObjLoader.h"
#include "materials/BlinnPhongMaterial.h"
#include "math/Color.h"

namespace lancer::test {

// A file or folder under tests/mesh/data (see data/SOURCES.md).
std::filesystem::path meshData(const std::string& relativePath);
// A model under scenes/models, which the scenes use too (see its SOURCES.md).
std::filesystem::path sceneModel(const std::string& relativePath);

// A fresh folder for the files that one test writes, removed when the test ends.
class ScratchFolder {
public:
    ScratchFolder();
    ~ScratchFolder();
    ScratchFolder(const ScratchFolder&) = delete;
    ScratchFolder& operator=(const ScratchFolder&) = delete;

    const std::filesystem::path& path() const { return path_; }
    // Writes `bytes` exactly as given (no newline translation); creates subfolders as needed.
    std::filesystem::path write(const std::string& relativePath, const std::string& bytes) const;

private:
    std::filesystem::path path_;
};

// Stands in for the scene loader's texture loader: an existing file loads as a constant colour,
// a missing one throws InputError. It records every path it is asked for.
class FakeTextures {
public:
    static constexpr Color kColor{0.25f, 0.5f, 0.75f};

    ObjLoader::TextureLoader loader();
    const std::vector<std::filesystem::path>& requested() const { return requested_; }
    // Whether each was asked for as colour or as data, in the same order.
    const std::vector<ImageReader::Content>& contents() const { return contents_; }

private:
    std::vector<std::filesystem::path> requested_;
    std::vector<ImageReader::Content> contents_;
};

struct LoadedObj {
    std::shared_ptr<TriangleMesh> mesh;
    std::vector<std::string> warnings;
};

LoadedObj loadObj(const std::filesystem::path& path, FakeTextures& textures);
LoadedObj loadObj(const std::filesystem::path& path);
// The message of the InputError that loading throws, or else the warnings, one a line.
std::string loadOutcome(const std::filesystem::path& path);

// (v1 - v0) x (v2 - v0) of a triangle: its front side, with twice its area as length.
Vec3 areaVector(const TriangleMesh& mesh, std::size_t triangle);
double totalArea(const TriangleMesh& mesh);
// Half the length of the sum of (p_i x p_i+1) over a polygon's edges: the area of a planar polygon.
double polygonArea(const std::vector<Vec3>& corners);
// The parameters of a material the OBJ loader made (a BlinnPhongMaterial, which it checks).
const BlinnPhongMaterial::Parameters& parametersOf(const Material& material);
const BlinnPhongMaterial::Parameters& materialOf(const TriangleMesh& mesh, std::size_t triangle);
// The colour of a texture that does not vary (a ConstantTexture).
Color colorOf(const Texture& texture);

// How many of the warnings contain `text`.
std::size_t countContaining(const std::vector<std::string>& warnings, const std::string& text);

// An OBJ face line "f 1 2 3 ..." listing vertices first..first+count-1.
std::string faceLine(int first, int count);

#define EXPECT_COLOR_NEAR(actual, expected, tolerance)                     \
    do {                                                                   \
        const Color actualColor_ = (actual);                               \
        const Color expectedColor_ = (expected);                           \
        EXPECT_NEAR(actualColor_.r, expectedColor_.r, tolerance) << "(r)"; \
        EXPECT_NEAR(actualColor_.g, expectedColor_.g, tolerance) << "(g)"; \
        EXPECT_NEAR(actualColor_.b, expectedColor_.b, tolerance) << "(b)"; \
    } while (0)

}  // namespace lancer::test
