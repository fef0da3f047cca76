// OBJ geometry: triangulation of convex and concave polygons, index forms, line endings, vertex
// attributes, dropped faces, and the errors for files that cannot be used.

#include <cmath>
#include <fstream>
#include <iomanip>
#include <numbers>
#include <sstream>

#include "MeshTestSupport.h"

namespace lancer::test {
namespace {

namespace fs = std::filesystem;

std::string vertexLines(const std::vector<Vec3>& points) {
    std::ostringstream lines;
    lines << std::setprecision(9);  // every float exactly
    for (const Vec3& p : points)
        lines << "v " << p.x << " " << p.y << " " << p.z << "\n";
    return lines.str();
}

// A plane in space: where a 2D outline's (x, y) lands.
struct Plane3 {
    Vec3 origin, u, v;
    Vec3 normal() const { return cross(u, v); }
    std::vector<Vec3> place(const std::vector<Vec2>& outline) const {
        std::vector<Vec3> corners;
        for (const Vec2& p : outline)
            corners.push_back(origin + p.x * u + p.y * v);
        return corners;
    }
};

const std::vector<Plane3> kPlanes{
    {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}},                                  // xy
    {{0, 0, 0}, {0, 1, 0}, {0, 0, 1}},                                  // yz
    {{0, 0, 0}, {0, 0, 1}, {1, 0, 0}},                                  // zx
    {{3, -2, 5}, normalize(Vec3(1, 1, 0)), normalize(Vec3(-1, 1, 2))},  // tilted, off the origin
};

std::vector<Vec2> regularPolygon(int n, float radius) {
    std::vector<Vec2> outline;
    for (int i = 0; i < n; ++i) {
        const float angle = 2 * std::numbers::pi_v<float> * float(i) / float(n);
        outline.push_back({radius * std::cos(angle), radius * std::sin(angle)});
    }
    return outline;
}

// A five-pointed star: ten corners, five of them reflex.
std::vector<Vec2> star() {
    std::vector<Vec2> outline;
    for (int i = 0; i < 10; ++i) {
        const float radius = i % 2 == 0 ? 1.0f : 0.4f;
        const float angle = std::numbers::pi_v<float> * float(i) / 5;
        outline.push_back({radius * std::cos(angle), radius * std::sin(angle)});
    }
    return outline;
}

// A comb: a bar 1 high with `teeth` teeth 1 wide and 2 high standing on it, 1 apart. Where the
// outer teeth meet the bar, a corner lies on a straight edge.
std::vector<Vec2> comb(int teeth) {
    std::vector<Vec2> outline{{0, 0}, {float(2 * teeth - 1), 0}};
    for (int t = teeth - 1; t >= 0; --t) {
        const float x = float(2 * t);
        outline.insert(outline.end(), {{x + 1, 1}, {x + 1, 3}, {x, 3}, {x, 1}});
    }
    return outline;
}

LoadedObj loadPolygon(const ScratchFolder& folder, const std::vector<Vec3>& corners) {
    const int n = int(corners.size());
    return loadObj(folder.write("polygon.obj", vertexLines(corners) + faceLine(1, n)));
}

// A triangulation is right when it has n - 2 triangles that all face the way the polygon turns and
// add up to its area: triangles cut along diagonals that all keep the polygon's orientation can
// neither overlap nor leave it. Rounding aside: where three corners are collinear (the L shape's
// reflex corner lies on the line between two others) a sliver of almost no area may come out,
// facing either way.
void expectTriangulates(const std::vector<Vec3>& corners, const Vec3& front) {
    ScratchFolder folder;
    const LoadedObj loaded = loadPolygon(folder, corners);
    const TriangleMesh& mesh = *loaded.mesh;
    EXPECT_TRUE(loaded.warnings.empty());
    ASSERT_EQ(mesh.triangleCount(), corners.size() - 2);
    const double area = polygonArea(corners);
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t)
        EXPECT_GT(dot(areaVector(mesh, t), front), -1e-6 * area)
            << "triangle " << t << " is flipped";
    EXPECT_NEAR(totalArea(mesh), area, 1e-5 * area);
}

TEST(ObjTriangulation, ConvexPolygonsBecomeNMinus2TrianglesWithTheirArea) {
    for (const Plane3& plane : kPlanes)
        for (int n = 3; n <= 12; ++n) {
            SCOPED_TRACE(std::to_string(n) + " corners");
            expectTriangulates(plane.place(regularPolygon(n, 1.5f)), plane.normal());
        }
}

TEST(ObjTriangulation, ConcaveQuadIsSplitThroughItsReflexCorner) {
    // An arrowhead whose reflex corner is far from the tip, so that the shorter diagonal (the one
    // tinyobjloader would cut along) lies outside it. Every starting corner is tried.
    const std::vector<Vec2> dart{{0, 2}, {-1, -1}, {0, -0.5f}, {1, -1}};
    for (std::size_t start = 0; start < dart.size(); ++start) {
        SCOPED_TRACE("starting at corner " + std::to_string(start));
        std::vector<Vec2> rotated(dart.begin() + long(start), dart.end());
        rotated.insert(rotated.end(), dart.begin(), dart.begin() + long(start));
        const std::vector<Vec3> corners = kPlanes[0].place(rotated);
        ASSERT_FLOAT_EQ(float(polygonArea(corners)), 2.5f);
        expectTriangulates(corners, kPlanes[0].normal());
    }
}

TEST(ObjTriangulation, ConcavePolygonsKeepTheirAreaInAnyPlaneAndWinding) {
    const std::vector<std::pair<std::string, std::vector<Vec2>>> outlines{
        {"L shape", {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}},
        {"star", star()},
        {"comb", comb(6)},
    };
    for (const auto& [name, outline] : outlines)
        for (const Plane3& plane : kPlanes) {
            SCOPED_TRACE(name);
            expectTriangulates(plane.place(outline), plane.normal());
            // Written clockwise, the polygon faces the other way, and so do its triangles.
            const std::vector<Vec2> reversed(outline.rbegin(), outline.rend());
            expectTriangulates(plane.place(reversed), -plane.normal());
        }
}

TEST(ObjTriangulation, HoleJoinedToTheOutlineByABridgeEdge) {
    // An outline, an edge to a hole, the hole backwards and the same edge back: a corner of the
    // outline and one of the hole appear twice. Found by a randomized search: here the hole's
    // corner at the bridge is reflex on one side, and would wrongly block the ears at its twin.
    const std::vector<Vec2> polygon{
        {-0.438f, 1.919f},  {-2.061f, 2.584f},  {-2.363f, 1.138f},  {-3.593f, 0},
        {-3.61f, -1.739f},  {-1.563f, -1.959f}, {-0.827f, -3.623f}, {0.655f, -2.869f},
        {2.111f, -2.647f},  {3.687f, -1.776f},  {2.715f, 0},        {2.032f, 0.979f},
        {1.434f, 1.798f},   {0.783f, 3.432f},   {-0.438f, 1.919f},  // back at the first corner
        {-1.31f, 1.036f},   {0.102f, 1.081f},   {0.633f, 0.215f},   {0.11f, -0.676f},
        {-1.141f, -0.484f}, {-1.31f, 1.036f},  // back at the hole's first corner
    };
    for (const Plane3& plane : kPlanes)
        expectTriangulates(plane.place(polygon), plane.normal());
}

// The corners of the one face of an OBJ file that has a single face (with `v` and `f v//vn` only).
std::vector<Vec3> readSingleFace(const fs::path& path) {
    std::ifstream file(path);
    std::vector<Vec3> vertices, corners;
    std::string keyword;
    for (std::string line; std::getline(file, line);) {
        std::istringstream fields(line);
        fields >> keyword;
        if (keyword == "v") {
            Vec3 v;
            fields >> v.x >> v.y >> v.z;
            vertices.push_back(v);
        } else if (keyword == "f") {
            for (std::string corner; fields >> corner;)
                corners.push_back(vertices.at(std::size_t(std::stoi(corner)) - 1));
        }
    }
    return corners;
}

TEST(ObjTriangulation, ConcavePolygonWithABridgedHoleFromAssimp) {
    // A ring drawn as one 66-gon: the outer circle, an edge to the inner circle, the inner circle
    // backwards, and the same edge back (two corners appear twice). tinyobjloader makes 44
    // overlapping triangles of it, covering 7 times its area.
    const fs::path path = meshData("edge_cases/assimp_obj/concave_polygon.obj");
    const LoadedObj loaded = loadObj(path);
    const TriangleMesh& mesh = *loaded.mesh;
    EXPECT_TRUE(loaded.warnings.empty());
    ASSERT_EQ(mesh.triangleCount(), 64u);
    // The polygon lies in the plane x = -1.146: all triangles must face the same way along x.
    const float firstSide = areaVector(mesh, 0).x;
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t)
        EXPECT_GT(areaVector(mesh, t).x * firstSide, 0) << "triangle " << t << " is flipped";
    const double area = polygonArea(readSingleFace(path));
    EXPECT_NEAR(area, 0.2455, 1e-4);  // the ring between radii 0.69 and 0.74
    EXPECT_NEAR(totalArea(mesh), area, 1e-5);
}

TEST(ObjTriangulation, FaceOfMoreThan255VerticesIsTriangulatedByTinyobjloaderWithAWarning) {
    ScratchFolder folder;
    const std::vector<Vec3> corners = kPlanes[3].place(regularPolygon(300, 2));
    const LoadedObj loaded = loadPolygon(folder, corners);
    EXPECT_EQ(loaded.mesh->triangleCount(), 298u);
    EXPECT_NEAR(totalArea(*loaded.mesh), polygonArea(corners), 1e-4);
    ASSERT_EQ(loaded.warnings.size(), 1u);
    EXPECT_NE(loaded.warnings[0].find("more than 255 vertices"), std::string::npos);
}

const std::string kSquareAndTriangleWithNegativeIndices =
    "v 0 0 0\n"
    "v 1 0 0\n"
    "v 1 1 0\n"
    "v 0 1 0\n"
    "f -4 -3 -2 -1\n"
    "v 0 0 1\n"
    "v 2 0 1\n"
    "v 0 2 1\n"
    "vn 0 0 1\n"
    "vt 0.5 0.25\n"
    "f -3/-1/-1 -2/-1/-1 -1/-1/-1\n";

TEST(ObjIndices, NegativeIndicesCountBackFromTheLastVertex) {
    ScratchFolder folder;
    const LoadedObj loaded =
        loadObj(folder.write("model.obj", kSquareAndTriangleWithNegativeIndices));
    const TriangleMesh& mesh = *loaded.mesh;
    EXPECT_TRUE(loaded.warnings.empty());
    ASSERT_EQ(mesh.triangleCount(), 3u);
    EXPECT_DOUBLE_EQ(0.5 * length(areaVector(mesh, 0)) + 0.5 * length(areaVector(mesh, 1)), 1.0);
    const std::uint32_t* last = &mesh.indices[6];
    EXPECT_EQ(mesh.positions[last[0]], Vec3(0, 0, 1));
    EXPECT_EQ(mesh.positions[last[1]], Vec3(2, 0, 1));
    EXPECT_EQ(mesh.positions[last[2]], Vec3(0, 2, 1));
    ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
    ASSERT_EQ(mesh.uvs.size(), mesh.positions.size());
    EXPECT_EQ(mesh.normals[last[1]], Vec3(0, 0, 1));
    EXPECT_EQ(mesh.uvs[last[2]], Vec2(0.5f, 0.25f));
}

std::string withCrlf(const std::string& text) {
    std::string crlf;
    for (const char c : text)
        crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
    return crlf;
}

TEST(ObjLineEndings, CrlfFilesReadLikeLfFiles) {
    const std::string obj =
        "mtllib model.mtl\nusemtl red\n" + kSquareAndTriangleWithNegativeIndices;
    const std::string mtl = "newmtl red\nKd 0.8 0.1 0.1\nillum 2\n";
    ScratchFolder lf, crlf;
    lf.write("model.mtl", mtl);
    crlf.write("model.mtl", withCrlf(mtl));
    const LoadedObj expected = loadObj(lf.write("model.obj", obj));
    const LoadedObj loaded = loadObj(crlf.write("model.obj", withCrlf(obj)));
    EXPECT_TRUE(loaded.warnings.empty());
    EXPECT_EQ(loaded.mesh->positions, expected.mesh->positions);
    EXPECT_EQ(loaded.mesh->normals, expected.mesh->normals);
    EXPECT_EQ(loaded.mesh->uvs, expected.mesh->uvs);
    EXPECT_EQ(loaded.mesh->indices, expected.mesh->indices);
    ASSERT_EQ(loaded.mesh->materials.size(), 1u);
    EXPECT_COLOR_NEAR(colorOf(*parametersOf(*loaded.mesh->materials[0]).diffuse),
                      Color(0.8f, 0.1f, 0.1f), 0);
}

TEST(ObjAttributes, NormalsAreUnitAndUvsAsGivenWherePresent) {
    ScratchFolder folder;
    const LoadedObj loaded = loadObj(folder.write("model.obj",
                                                  "v 0 0 0\nv 1 0 0\nv 0 1 0\n"
                                                  "vn 0 0 2\nvn 0 3 4\n"
                                                  "vt 0 0\nvt 1 0\nvt 0 1\n"
                                                  "f 1/1/1 2/2/1 3/3/2\n"));
    const TriangleMesh& mesh = *loaded.mesh;
    ASSERT_EQ(mesh.normals.size(), 3u);
    ASSERT_EQ(mesh.uvs.size(), 3u);
    EXPECT_EQ(mesh.normals[mesh.indices[0]], Vec3(0, 0, 1));
    EXPECT_NEAR(length(mesh.normals[mesh.indices[2]] - Vec3(0, 0.6f, 0.8f)), 0, 1e-6);
    EXPECT_EQ(mesh.uvs[mesh.indices[1]], Vec2(1, 0));
    EXPECT_EQ(mesh.uvs[mesh.indices[2]], Vec2(0, 1));
}

TEST(ObjAttributes, WithoutNormalsOrUvsBothAreEmpty) {
    ScratchFolder folder;
    const LoadedObj loaded =
        loadObj(folder.write("model.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"));
    EXPECT_TRUE(loaded.mesh->normals.empty());
    EXPECT_TRUE(loaded.mesh->uvs.empty());
}

TEST(ObjAttributes, FacesWithoutNormalsAreFlatAmongFacesWithNormals) {
    ScratchFolder folder;
    const LoadedObj loaded = loadObj(folder.write("model.obj",
                                                  "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n"
                                                  "vn 0 0 1\nvt 0.5 0.5\n"
                                                  "f 1/1/1 2/1/1 3/1/1\n"
                                                  "f 2 4 3\n"));
    const TriangleMesh& mesh = *loaded.mesh;
    EXPECT_TRUE(loaded.warnings.empty());
    ASSERT_EQ(mesh.triangleCount(), 2u);
    ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
    ASSERT_EQ(mesh.uvs.size(), mesh.positions.size());
    for (int corner = 3; corner < 6; ++corner) {
        EXPECT_EQ(mesh.normals[mesh.indices[corner]], Vec3()) << "zero normal: shaded flat";
        EXPECT_EQ(mesh.uvs[mesh.indices[corner]], Vec2());
    }
    EXPECT_EQ(mesh.normals[mesh.indices[0]], Vec3(0, 0, 1));
}

const std::string kCubeCorners =
    "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\n"
    "v -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n"
    "v 9 9 9\n";  // unused

TEST(ObjAttributes, VerticesAreSharedPerPositionNormalUvTriple) {
    ScratchFolder folder;
    const LoadedObj shared =
        loadObj(folder.write("shared.obj", kCubeCorners + "f 1 4 3 2\nf 5 6 7 8\n"
                                                          "f 1 2 6 5\nf 2 3 7 6\n"
                                                          "f 3 4 8 7\nf 4 1 5 8\n"));
    EXPECT_EQ(shared.mesh->triangleCount(), 12u);
    EXPECT_EQ(shared.mesh->positions.size(), 8u)
        << "one vertex per corner; the unused one left out";
    EXPECT_DOUBLE_EQ(totalArea(*shared.mesh), 24.0);

    const LoadedObj perFace = loadObj(folder.write(
        "per_face.obj", kCubeCorners +
                            "vn 0 0 -1\nvn 0 0 1\nvn 0 -1 0\nvn 1 0 0\nvn 0 1 0\nvn -1 0 0\n"
                            "f 1//1 4//1 3//1 2//1\nf 5//2 6//2 7//2 8//2\n"
                            "f 1//3 2//3 6//3 5//3\nf 2//4 3//4 7//4 6//4\n"
                            "f 3//5 4//5 8//5 7//5\nf 4//6 1//6 5//6 8//6\n"));
    EXPECT_EQ(perFace.mesh->positions.size(), 24u) << "each corner has 3 normals";
    for (std::size_t t = 0; t < perFace.mesh->triangleCount(); ++t) {
        const Vec3 faceNormal = normalize(areaVector(*perFace.mesh, t));
        EXPECT_EQ(perFace.mesh->normals[perFace.mesh->indices[3 * t]], faceNormal)
            << "triangle " << t << " keeps the OBJ winding (outward here)";
    }
}

TEST(ObjDroppedFaces, ZeroAreaTrianglesAreDroppedWithOneWarning) {
    ScratchFolder folder;
    const fs::path path = folder.write("model.obj",
                                       "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 2 0 0\nv 1 0 0\n"
                                       "f 1 2 3\n"
                                       "f 1 1 3\n"    // a repeated index
                                       "f 1 2 4\n"    // collinear corners
                                       "f 2 5 3\n");  // two corners at the same place
    const LoadedObj loaded = loadObj(path);
    EXPECT_EQ(loaded.mesh->triangleCount(), 1u);
    EXPECT_EQ(loaded.warnings,
              std::vector<std::string>{path.string() + ": warning: 3 zero-area triangles dropped"});
}

TEST(ObjDroppedFaces, FacesWithNonFiniteCoordinatesAreDroppedWithOneWarning) {
    ScratchFolder folder;
    const fs::path path = folder.write("model.obj",
                                       "v 0 0 0\nv 1 0 0\nv 0 1 0\n"
                                       "v 1e39 0 0\n"    // beyond the float range
                                       "v 0 -1e999 0\n"  // beyond the double range
                                       "f 1 2 3\nf 1 2 4\nf 5 1 2 3\n");
    const LoadedObj loaded = loadObj(path);
    EXPECT_EQ(loaded.mesh->triangleCount(), 1u);
    EXPECT_EQ(loaded.warnings,
              std::vector<std::string>{path.string() +
                                       ": warning: 2 faces with non-finite vertex coordinates "
                                       "dropped"});
}

TEST(ObjDroppedFaces, FacesWithVertexIndicesOutOfRangeAreDroppedWithOneWarning) {
    ScratchFolder folder;
    const LoadedObj loaded = loadObj(folder.write("model.obj",
                                                  "v 0 0 0\nv 1 0 0\nv 0 1 0\n"
                                                  "f 1 2 3\n"
                                                  "f 1 2 9\n"
                                                  "f -1 -2 -7\n"));
    EXPECT_EQ(loaded.mesh->triangleCount(), 1u);
    ASSERT_EQ(loaded.warnings.size(), 1u);
    EXPECT_EQ(countContaining(loaded.warnings, "2 faces with vertex indices out of range dropped"),
              1u);
}

TEST(ObjDroppedFaces, NormalAndUvIndicesOutOfRangeAreIgnoredWithAWarningEach) {
    ScratchFolder folder;
    const LoadedObj loaded = loadObj(folder.write("model.obj",
                                                  "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nvt 0 0\n"
                                                  "f 1//5 2//5 3//5\n"
                                                  "f 1/7 3/7 2/7\n"));
    const TriangleMesh& mesh = *loaded.mesh;
    EXPECT_EQ(mesh.triangleCount(), 2u);
    EXPECT_TRUE(mesh.normals.empty());
    EXPECT_TRUE(mesh.uvs.empty());
    EXPECT_EQ(loaded.warnings.size(), 2u);
    EXPECT_EQ(countContaining(loaded.warnings, "1 face with normal (vn) indices out of range"), 1u);
    EXPECT_EQ(countContaining(loaded.warnings, "1 face with texture coordinate (vt) indices"), 1u);
}

TEST(ObjDroppedFaces, PointsAndLinesAreIgnoredWithOneWarning) {
    ScratchFolder folder;
    const LoadedObj loaded = loadObj(folder.write("model.obj",
                                                  "v 0 0 0\nv 1 0 0\nv 0 1 0\n"
                                                  "p 1 2\nl 1 2 3\nf 1 2 3\nl 2 3\np 3\n"));
    EXPECT_EQ(loaded.mesh->triangleCount(), 1u);
    ASSERT_EQ(loaded.warnings.size(), 1u);
    EXPECT_NE(loaded.warnings[0].find("points (p) and lines (l) are not rendered"),
              std::string::npos);
}

TEST(ObjErrors, MissingObjIsAnInputErrorNamingIt) {
    ScratchFolder folder;
    const fs::path path = folder.path() / "missing.obj";
    EXPECT_EQ(loadOutcome(path),
              path.string() + ": error: cannot open the OBJ file (does it exist?)");
}

TEST(ObjErrors, FolderIsAnInputError) {
    ScratchFolder folder;
    EXPECT_EQ(loadOutcome(folder.path()),
              folder.path().string() + ": error: is a folder, not an OBJ file");
}

TEST(ObjErrors, ObjWithoutFacesIsAnInputError) {
    ScratchFolder folder;
    const fs::path empty = folder.write("empty.obj", "");
    EXPECT_EQ(loadOutcome(empty), empty.string() + ": error: no faces (f) to render");
    const fs::path vertices = folder.write("vertices.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n");
    EXPECT_EQ(loadOutcome(vertices), vertices.string() + ": error: no faces (f) to render");
}

TEST(ObjErrors, ObjWhoseFacesAreAllDroppedIsAnInputError) {
    ScratchFolder folder;
    const fs::path path = folder.write("model.obj", "v 0 0 0\nv 1 0 0\nf 1 2 7\nf 1 2 1\n");
    EXPECT_EQ(loadOutcome(path), path.string() + ": error: none of its 2 faces can be rendered");
}

TEST(ObjErrors, ZeroIndexIsAnInputError) {
    ScratchFolder folder;
    const fs::path path = folder.write("model.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n");
    EXPECT_EQ(loadOutcome(path),
              path.string() + ":4:1: error: index 0 (OBJ indices count from 1, or back from -1)");
}

TEST(ObjErrors, Utf16IsAnInputError) {
    const fs::path path = meshData("edge_cases/assimp_obj/box_UTF16BE.obj");
    EXPECT_EQ(loadOutcome(path),
              path.string() + ": error: is UTF-16 text; an OBJ file must be ASCII or UTF-8");
}

}  // namespace
}  // namespace lancer::test
