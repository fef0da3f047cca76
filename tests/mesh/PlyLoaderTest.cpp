// PLY models: the unit cube of data/ply (written by its make-cubes.py) in ASCII and both binary
// byte orders reads as the same mesh as its OBJ twin; which files are PLY; what is warned of;
// and the errors of bad files, whose seeds are in tests/fuzz/corpus/ply.

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <tuple>
#include <vector>

#include "MeshTestSupport.h"
#include "io/PlyLoader.h"
#include "scene/InputError.h"

namespace lancer::test {
namespace {

namespace fs = std::filesystem;

struct LoadedPly {
    std::shared_ptr<TriangleMesh> mesh;
    std::vector<std::string> warnings;
};

LoadedPly loadPly(const fs::path& path) {
    LoadedPly loaded;
    loaded.mesh = PlyLoader::load(path, loaded.warnings);
    return loaded;
}

std::string plyError(const fs::path& path) {
    std::vector<std::string> warnings;
    try {
        PlyLoader::load(path, warnings);
    } catch (const InputError& e) {
        return e.what();
    }
    return "no error";
}

fs::path corpus(const std::string& name) {
    return fs::path(LANCER_FUZZ_CORPUS) / "ply" / name;
}

// A vertex's position, normal and uv, comparable across meshes whose vertex order differs.
using VertexTuple = std::tuple<float, float, float, float, float, float, float, float>;

std::vector<VertexTuple> sortedVertices(const TriangleMesh& mesh) {
    std::vector<VertexTuple> vertices;
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
        const Vec3 &p = mesh.positions[i], &n = mesh.normals[i];
        const Vec2& uv = mesh.uvs[i];
        vertices.emplace_back(p.x, p.y, p.z, n.x, n.y, n.z, uv.x, uv.y);
    }
    std::sort(vertices.begin(), vertices.end());
    return vertices;
}

TEST(PlyLoader, CubeReadsTheSameInEveryEncoding) {
    const LoadedPly ascii = loadPly(meshData("ply/cube-ascii.ply"));
    EXPECT_TRUE(ascii.warnings.empty());
    const TriangleMesh& mesh = *ascii.mesh;
    // 6 quads of their own 4 vertices: each quad becomes two triangles.
    ASSERT_EQ(mesh.positions.size(), 24u);
    ASSERT_EQ(mesh.normals.size(), 24u);
    ASSERT_EQ(mesh.uvs.size(), 24u);
    EXPECT_EQ(mesh.triangleCount(), 12u);
    EXPECT_EQ(mesh.materials.size(), 1u);
    EXPECT_NEAR(totalArea(mesh), 6.0, 1e-6);
    // The file's vertices in its order: the +x face first, with uvs (0,0) (1,0) (1,1) (0,1).
    EXPECT_EQ(mesh.positions[1], Vec3(1, 1, 0));
    EXPECT_EQ(mesh.normals[1], Vec3(1, 0, 0));
    EXPECT_EQ(mesh.uvs[2], Vec2(1, 1));
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        // Counter-clockwise seen from outside: the front is the face's normal.
        const Vec3 front = normalize(areaVector(mesh, t));
        EXPECT_NEAR(dot(front, mesh.normals[mesh.indices[3 * t]]), 1.0, 1e-6) << t;
    }
    for (const char* name : {"ply/cube-binary-le.ply", "ply/cube-binary-be.ply"}) {
        SCOPED_TRACE(name);
        const LoadedPly binary = loadPly(meshData(name));
        EXPECT_TRUE(binary.warnings.empty());
        EXPECT_EQ(binary.mesh->positions, mesh.positions);
        EXPECT_EQ(binary.mesh->normals, mesh.normals);
        EXPECT_EQ(binary.mesh->uvs, mesh.uvs);
        EXPECT_EQ(binary.mesh->indices, mesh.indices);
    }
    // The OBJ twin has the same vertices (its quads may be split along the other diagonal).
    const LoadedObj obj = loadObj(meshData("ply/cube.obj"));
    EXPECT_EQ(sortedVertices(*obj.mesh), sortedVertices(mesh));
    EXPECT_EQ(obj.mesh->triangleCount(), mesh.triangleCount());
}

TEST(PlyLoader, WithoutNormalsOrUvsTheMeshHasNone) {
    ScratchFolder folder;
    const fs::path path = folder.write(
        "triangle.ply",
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
        "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
        "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
    const LoadedPly loaded = loadPly(path);
    EXPECT_TRUE(loaded.warnings.empty());
    EXPECT_EQ(loaded.mesh->triangleCount(), 1u);
    EXPECT_TRUE(loaded.mesh->normals.empty());  // flat shading
    EXPECT_TRUE(loaded.mesh->uvs.empty());
}

TEST(PlyLoader, VertexColoursAndLinesAreWarnedOf) {
    const fs::path path = corpus("triangle-colours-and-a-line.ply");
    const LoadedPly loaded = loadPly(path);
    EXPECT_EQ(loaded.mesh->triangleCount(), 1u);
    ASSERT_EQ(loaded.warnings.size(), 2u);
    EXPECT_EQ(loaded.warnings[0],
              path.string() +
                  ": warning: vertex colours are not used; the object's material "
                  "applies");
    EXPECT_EQ(loaded.warnings[1], path.string() +
                                      ": warning: 1 face with fewer than 3 vertices (points, "
                                      "lines) ignored");
}

// A concave face is split by the OBJ loader's ear clipping: its triangles cover it exactly.
// A face of no vertices is ignored.
TEST(PlyLoader, ConcaveFacesAreTriangulatedAndEmptyFacesIgnored) {
    ScratchFolder folder;
    const std::vector<Vec3> lShape = {{0, 0, 0}, {2, 0, 0}, {2, 1, 0},
                                      {1, 1, 0}, {1, 2, 0}, {0, 2, 0}};
    std::string body;
    for (const Vec3& p : lShape)
        body += std::to_string(p.x) + " " + std::to_string(p.y) + " 0\n";
    body += "6 0 1 2 3 4 5\n0\n";
    const fs::path path = folder.write(
        "l.ply",
        "ply\nformat ascii 1.0\nelement vertex 6\nproperty float x\nproperty float y\n"
        "property float z\nelement face 2\nproperty list uchar int vertex_indices\nend_header\n" +
            body);
    const LoadedPly loaded = loadPly(path);
    EXPECT_EQ(loaded.mesh->triangleCount(), 4u);
    EXPECT_NEAR(totalArea(*loaded.mesh), polygonArea(lShape), 1e-6);
    ASSERT_EQ(loaded.warnings.size(), 1u);
    EXPECT_NE(loaded.warnings[0].find("1 face with fewer than 3 vertices"), std::string::npos);
}

// A header line starting with a carriage return, a vertical tab or a form feed made Assimp's
// header parser loop for ever: each is refused by line, within the time of a test.
TEST(PlyErrors, ControlCharactersInTheHeaderAreRefused) {
    ScratchFolder folder;
    for (const char c : {'\r', '\v', '\f'}) {
        const fs::path path = folder.write(
            "control.ply", std::string("ply\nformat ascii 1.0\nelement vertex 3\nproperty float "
                                       "x\nproperty float y\nproperty float z\n") +
                               c + "end_header\n0 0 0\n1 0 0\n0 1 0\n");
        EXPECT_NE(plyError(path).find("not a valid PLY file: header line 7 holds the control "
                                      "character 0x"),
                  std::string::npos)
            << int(c) << ": " << plyError(path);
    }
}

TEST(PlyLoader, CrlfHeaderIsRead) {
    EXPECT_EQ(loadPly(corpus("crlf-header.ply")).mesh->triangleCount(), 1u);
}

TEST(PlyLoader, WhichFilesArePly) {
    ScratchFolder folder;
    EXPECT_TRUE(PlyLoader::isPly(folder.path() / "missing.PLY"));  // by its name
    EXPECT_TRUE(PlyLoader::isPly(folder.write("binary.obj", "ply\r\nformat binary_little")));
    EXPECT_TRUE(PlyLoader::isPly(meshData("ply/cube-ascii.ply")));
    EXPECT_FALSE(PlyLoader::isPly(meshData("ply/cube.obj")));
    // An OBJ whose first word merely starts with "ply" is an OBJ.
    EXPECT_FALSE(PlyLoader::isPly(folder.write("plyish.obj", "plywood\n")));
    EXPECT_FALSE(PlyLoader::isPly("/dev/zero"));  // not read: a device is the OBJ loader's error
}

TEST(PlyErrors, EachBadFileIsOneInputErrorNamingIt) {
    ScratchFolder folder;
    const fs::path missing = folder.path() / "missing.ply";
    EXPECT_EQ(plyError(missing),
              missing.string() + ": error: cannot open the PLY file (does it exist?)");
    EXPECT_EQ(plyError(folder.path()),
              folder.path().string() + ": error: is a folder, not a PLY file");
    EXPECT_EQ(plyError("/dev/zero"), "/dev/zero: error: is a device, not a PLY file");
    const std::pair<const char*, const char*> kCases[] = {
        {"empty.ply", "is empty, not a PLY file"},
        {"not-ply.ply", "is not a PLY file (its first line is not \"ply\")"},
        {"no-end-header.ply", "not a valid PLY file: the header has no end_header line"},
        {"truncated-binary.ply",
         "is truncated: its header declares 24 \"vertex\" elements, more than its body holds"},
        {"truncated-binary-in-faces.ply",
         "is truncated: its header declares 6 \"face\" elements, more than its body holds"},
        {"truncated-ascii.ply",
         "is truncated: its header declares 3 \"vertex\" elements, more than its body holds"},
        {"billion-vertices-declared.ply",
         "is truncated: its header declares 1000000000 \"vertex\" elements, more than its "
         "body holds"},
        {"index-out-of-range.ply",
         "a face's vertex index is out of range: face 0 names vertex 7 of 3 vertices"},
        {"vertex-without-z.ply",
         "not a valid PLY file: the \"vertex\" element has no x, y and z properties"},
        {"face-without-vertex-indices.ply",
         "not a valid PLY file: the \"face\" element has no vertex_indices list"},
        {"negative-list-count-binary.ply",
         "not a valid PLY file: a list's count -1 is not a count"},
        // Counts typed float. fuzz_ply's file has a tiny count (it was read as 0) and then one of
        // 7.9e34, whose conversion to an integer overflowed.
        {"float-list-counts-found-by-fuzz-ply.ply",
         "not a valid PLY file: a list's count 4.7409786883692068e-29 is not a count"},
        {"huge-float-list-count.ply",
         "is truncated: its header declares 1 \"face\" element, more than its body holds"},
        {"fractional-float-list-count.ply",
         "not a valid PLY file: a list's count 2.5 is not a count"},
        {"no-faces.ply", "no faces to render"},
        // Found by fuzz_ply: Assimp's parser never returned from it.
        {"carriage-return-before-end-header.ply",
         "not a valid PLY file: header line 5 holds the control character 0x0D"},
    };
    for (const auto& [name, says] : kCases) {
        const fs::path path = corpus(name);
        EXPECT_EQ(plyError(path).rfind(path.string() + ": error: " + says, 0), 0u)
            << name << ": " << plyError(path);
    }
}

// A fault in an ASCII body is named by its line and column, the word at fault quoted (control
// characters as codes). The last file is one fuzz_ply was running when the heap was found
// corrupted inside Assimp 5.2.5's PLY importer, which lancer no longer uses.
TEST(PlyErrors, AsciiBodyFaultsNameTheLineAndColumn) {
    const std::pair<const char*, const char*> kCases[] = {
        {"list-count-not-a-number.ply",
         ":13:1: error: not a valid PLY file: a list's count \"x\" is not a count"},
        {"value-not-a-number.ply",
         ":11:3: error: not a valid PLY file: \"zero\" is not a number (the \"y\" property of a "
         "\"vertex\" element)"},
        {"negative-index.ply",
         ":13:5: error: a face's vertex index is out of range: face 0 names vertex -1"},
        {"fractional-index.ply",
         ":13:5: error: a face's vertex index is out of range: face 0 names vertex 1.5"},
        {"control-character-in-the-body.ply",
         ":19:3: error: not a valid PLY file: \"\\x10\" is not a number (the \"y\" property of "
         "a \"vertex\" element)"},
    };
    for (const auto& [name, says] : kCases) {
        const fs::path path = corpus(name);
        EXPECT_EQ(plyError(path), path.string() + says) << name;
    }
}

}  // namespace
}  // namespace lancer::test
