// OBJ models are parsed by tinyobjloader; faces are triangulated and MTL materials mapped here.
//
// Triangulation: tinyobjloader 2.0.0rc10 splits a quad along its shorter diagonal and clips the
// ears of larger polygons with a wrong convexity test, so its triangles of a concave face overlap
// and spill outside it (the concave 66-gon of assimp's concave_polygon.obj becomes 44 triangles
// covering 7 times its area). So faces are read whole and split here by ear clipping. tinyobjloader
// stores a face's vertex count in one byte, though: a file with a face of more than 255 vertices is
// read again with tinyobjloader's own triangulation, and a warning.
//
// MTL keys, mapped onto the scene format's material (a key a material leaves out takes the scene
// format's default):
//   Kd      diffuse colour (absent: 0.8)
//   map_Kd  diffuse texture, through the caller's TextureLoader; it replaces Kd. A texture that
//           cannot be loaded leaves Kd, with a warning. Texture options (-s, -o...) are ignored.
//   Ka      ambient colour; absent or black: the diffuse colour or texture (the format's default)
//   Ks      highlight colour, and the mirror reflection of the reflecting models below
//   Ns      shininess (absent: 32)
//   Ni      ior (absent: 1.5)
//   d / Tr  dissolve d is the opacity (Tr = 1 - d; d wins when both are given). A surface with
//           d < 1 gets transmission 1 - d with ior 1: see-through without bending light, as
//           dissolve is. Glass models are clear whatever d says.
//   Ke      emission; an emissive triangle is an ordinary triangle with an emissive material
//   Tf and the other maps (map_Ka, map_Ks, bump...) are not used.
//
// illum (absent: 2)                              specular  reflection  transmission
//   0  colour on, ambient off                    0         0           1 - d
//      A constant colour that no light changes is an emitter: Kd is added to the emission and the
//      diffuse and ambient colours are black (map_Kd is not shown, with a warning).
//   1  colour and ambient on                     0         0           1 - d
//   2  highlights on                             Ks        0           1 - d
//   3  mirror (reflection, ray trace on)         Ks        Ks          1 - d
//   4  glass, ray-traced reflection              Ks        Ks          1, ior Ni
//   5  Fresnel mirror                            Ks        Ks          1 - d
//      Our Fresnel term only splits refracting materials, and a metal mirror's reflectance hardly
//      changes with the angle: a plain mirror of Ks is the closest.
//   6  refraction, Fresnel off                   Ks        Ks          1, ior Ni
//   7  refraction, Fresnel on                    Ks        0           1, ior Ni
//      A clear dielectric: transmission splits itself into reflection kt F and refraction
//      kt (1 - F), so Fresnel alone reflects. In 4 and 6 the mirror Ks is added on top of it.
//   8  reflection, ray trace off                 as 3 (reflections are always traced)
//   9  glass, ray trace off                      as 7
//   10 casts shadows onto invisible surfaces     as 1
//   Other values are used as 2, with a warning.

#include "io/ObjLoader.h"

#include <tiny_obj_loader.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "materials/BlinnPhongMaterial.h"
#include "materials/ConstantTexture.h"
#include "math/Float.h"
#include "scene/InputError.h"

namespace lancer {

namespace fs = std::filesystem;

namespace {

void warn(std::vector<std::string>& warnings, const fs::path& file, const std::string& message) {
    warnings.push_back(file.string() + ": warning: " + message);
}

std::string inQuotes(const std::string& s) {
    return "\"" + s + "\"";
}

std::string quotedList(const std::vector<std::string>& names) {
    std::string list;
    for (const std::string& name : names)
        list += (list.empty() ? "" : ", ") + inQuotes(name);
    return list;
}

// "1 face", "3 faces".
std::string countOf(std::size_t count, const std::string& noun) {
    return std::to_string(count) + " " + noun + (count == 1 ? "" : "s");
}

// A file named inside an OBJ or MTL file: relative to that file's folder, and written with
// Windows separators as often as not.
fs::path resolvePath(const fs::path& folder, std::string name) {
    std::replace(name.begin(), name.end(), '\\', '/');
    const fs::path path(name);
    return (path.is_absolute() ? path : folder / path).lexically_normal();
}

// ---------------------------------------------------------------------------------------------
// Reading the files

// tinyobjloader gives a key that a material leaves out the same value that a file may write
// (illum 0, Ns 1, Ni 1, Kd 0), but here absent keys take the scene format's defaults. So every
// material starts with these impossible values, which the file's own lines then overwrite.
constexpr const char* kAbsentKeys = "Kd -1 -1 -1\nNs -1\nNi -1\nillum -1\n";
constexpr tinyobj::real_t kAbsent = -1;
constexpr int kAbsentIllum = -1;

bool startsMaterial(const std::string& line) {
    const std::size_t start = line.find_first_not_of(" \t");
    return start != std::string::npos && line.compare(start, 6, "newmtl") == 0 &&
           start + 6 < line.size() && (line[start + 6] == ' ' || line[start + 6] == '\t');
}

std::string markAbsentKeys(std::istream& mtl) {
    std::string marked, line;
    while (std::getline(mtl, line)) {
        marked += line + "\n";
        if (startsMaterial(line)) marked += kAbsentKeys;
    }
    return marked;
}

// Opens the MTL files that `mtllib` lines name, relative to the OBJ's folder, and remembers the
// file each material comes from (its texture paths are relative to it) and the files not found.
class MaterialLibraries final : public tinyobj::MaterialReader {
public:
    explicit MaterialLibraries(fs::path objFolder) : objFolder_(std::move(objFolder)) {}

    bool operator()(const std::string& name, std::vector<tinyobj::material_t>* materials,
                    std::map<std::string, int>* materialIds, std::string* mtlWarnings,
                    std::string* mtlErrors) override {
        named_ = true;
        const fs::path path = resolvePath(objFolder_, name);
        std::error_code error;
        std::ifstream file(path, std::ios::binary);
        if (!file || fs::is_directory(path, error)) {
            if (std::find(missing_.begin(), missing_.end(), path) == missing_.end())
                missing_.push_back(path);
            return false;
        }
        std::istringstream text(markAbsentKeys(file));
        tinyobj::LoadMtl(materialIds, materials, &text, mtlWarnings, mtlErrors);
        files_.resize(materials->size(), path);
        return true;
    }

    bool anyNamed() const { return named_; }
    const std::vector<fs::path>& missingFiles() const { return missing_; }
    const fs::path& fileOf(std::size_t material) const { return files_[material]; }

private:
    fs::path objFolder_;
    bool named_ = false;
    std::vector<fs::path> missing_;
    std::vector<fs::path> files_;  // per material
};

struct ObjContents {
    tinyobj::attrib_t attrib;
    std::vector<tinyobj::shape_t> shapes;
    std::vector<tinyobj::material_t> materials;
    MaterialLibraries libraries;
    std::string parserWarnings;
};

// tinyobjloader stops at an index 0 in an f, l or p line (and at a negative joint in a vw line),
// with a message that ends in "line N.)".
InputError parseError(const fs::path& objPath, const std::string& errors) {
    const std::string first = errors.substr(0, errors.find('\n'));
    const std::size_t lineWord = first.rfind("line ");
    const SourceLocation where{lineWord == std::string::npos ? 0 : std::atoi(&first[lineWord + 5]),
                               1};
    if (first.find("zero value") != std::string::npos)
        return InputError(objPath.string(), where,
                          "index 0 (OBJ indices count from 1, or back from -1)");
    return InputError(objPath.string(), where, "not a valid OBJ file: " + first);
}

ObjContents parseObj(std::istream& file, const fs::path& objPath, bool triangulate) {
    ObjContents obj{{}, {}, {}, MaterialLibraries(objPath.parent_path()), {}};
    std::string errors;
    const bool parsed =
        tinyobj::LoadObj(&obj.attrib, &obj.shapes, &obj.materials, &obj.parserWarnings, &errors,
                         &file, &obj.libraries, triangulate, /*default_vcols_fallback=*/false);
    if (file.bad()) throw InputError(objPath.string(), "cannot read the OBJ file");
    if (!parsed) throw parseError(objPath, errors);
    return obj;
}

// tinyobjloader keeps each face's vertex count in an unsigned char: larger faces wrap around.
bool hasTruncatedFaceSizes(const std::vector<tinyobj::shape_t>& shapes) {
    for (const tinyobj::shape_t& shape : shapes) {
        std::size_t corners = 0;
        for (const unsigned char count : shape.mesh.num_face_vertices)
            corners += count;
        if (corners != shape.mesh.indices.size()) return true;
    }
    return false;
}

std::ifstream openObj(const fs::path& path) {
    std::error_code error;
    if (fs::is_directory(path, error))
        throw InputError(path.string(), "is a folder, not an OBJ file");
    std::ifstream file(path, std::ios::binary);
    if (!file) throw InputError(path.string(), "cannot open the OBJ file (does it exist?)");
    const int first = file.get(), second = file.get();
    if ((first == 0xFE && second == 0xFF) || (first == 0xFF && second == 0xFE))
        throw InputError(path.string(), "is UTF-16 text; an OBJ file must be ASCII or UTF-8");
    file.clear();
    file.seekg(0);
    return file;
}

// tinyobjloader reports some problems only as text. The ones that only it can see are read back
// here; its other messages are about things checked again below in more detail (index ranges,
// missing MTL files) or harmless (empty group names; both d and Tr given, where d wins).
struct ParserFindings {
    std::size_t shortFaces = 0;                   // faces of 1 or 2 vertices, skipped
    std::vector<std::string> undefinedMaterials;  // usemtl names that no MTL file defines
};

ParserFindings readParserWarnings(const std::string& text) {
    static const std::string kUndefinedBefore = "material [ '", kUndefinedAfter = "' ] not found";
    ParserFindings findings;
    std::istringstream lines(text);
    std::string line;
    while (std::getline(lines, line)) {
        if (line.find("Degenerated face found") != std::string::npos) ++findings.shortFaces;
        const std::size_t after = line.find(kUndefinedAfter);
        if (line.starts_with(kUndefinedBefore) && after != std::string::npos) {
            std::string name =
                line.substr(kUndefinedBefore.size(), after - kUndefinedBefore.size());
            std::vector<std::string>& names = findings.undefinedMaterials;
            if (std::find(names.begin(), names.end(), name) == names.end())
                names.push_back(std::move(name));
        }
    }
    return findings;
}

void reportMaterialProblems(const ObjContents& obj, const ParserFindings& findings,
                            const fs::path& objPath, std::vector<std::string>& warnings) {
    const std::string fallback = "the default grey material is used";
    for (const fs::path& missing : obj.libraries.missingFiles())
        warn(warnings, objPath,
             "material library " + inQuotes(missing.string()) + " not found; " + fallback +
                 " for its materials");
    // Materials that a missing library would have defined need no second warning.
    if (!obj.libraries.missingFiles().empty() || findings.undefinedMaterials.empty()) return;
    const std::string names = quotedList(findings.undefinedMaterials);
    if (obj.libraries.anyNamed())
        warn(warnings, objPath,
             "materials " + names + " are not defined in its material libraries; " + fallback);
    else
        warn(warnings, objPath,
             "faces use materials " + names + " but no material library (mtllib) is named; " +
                 fallback);
}

// ---------------------------------------------------------------------------------------------
// Triangulation

struct Point2 {
    double x = 0, y = 0;
    bool operator==(const Point2&) const = default;
};

// Twice the signed area of the triangle abc: positive when it turns counter-clockwise.
double orientation(const Point2& a, const Point2& b, const Point2& c) {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// Inside or on the border of the counter-clockwise triangle abc.
bool inTriangle(const Point2& a, const Point2& b, const Point2& c, const Point2& p) {
    return orientation(a, b, p) >= 0 && orientation(b, c, p) >= 0 && orientation(c, a, p) >= 0;
}

// The corners of a polygon in the plane it (nearly) lies in, turning counter-clockwise: projected
// along the largest component of its Newell normal.
std::vector<Point2> projectPolygon(const std::vector<Vec3>& corners) {
    Vec3d normal;
    for (std::size_t i = 0; i < corners.size(); ++i)
        normal += cross(Vec3d(corners[i]), Vec3d(corners[(i + 1) % corners.size()]));
    const int axis = maxDimension(normal);
    const double flip = normal[axis] < 0 ? -1 : 1;
    std::vector<Point2> points;
    points.reserve(corners.size());
    for (const Vec3& c : corners)
        points.push_back({double(c[(axis + 1) % 3]), flip * double(c[(axis + 2) % 3])});
    return points;
}

using CornerTriple = std::array<std::size_t, 3>;

// Splits a polygon, convex or not, into triangles by ear clipping; the triangles keep the
// polygon's winding. Holes joined to the outline by a two-way bridge edge (as some exporters
// write them) work: a corner's duplicate does not block an ear. A self-intersecting or degenerate
// polygon, which has no proper triangulation, still gives n - 2 triangles.
std::vector<CornerTriple> triangulate(const std::vector<Vec3>& corners) {
    const std::size_t n = corners.size();
    if (n == 3) return {{0, 1, 2}};
    const std::vector<Point2> p = projectPolygon(corners);
    std::vector<std::size_t> prev(n), next(n);
    for (std::size_t i = 0; i < n; ++i) {
        prev[i] = (i + n - 1) % n;
        next[i] = (i + 1) % n;
    }
    // The corner b between a and c is an ear when it is convex and no reflex corner lies in abc
    // (a convex corner inside abc would come with a reflex one).
    const auto isEar = [&](std::size_t a, std::size_t b, std::size_t c) {
        if (orientation(p[a], p[b], p[c]) <= 0) return false;
        for (std::size_t i = next[c]; i != a; i = next[i]) {
            if (p[i] == p[a] || p[i] == p[b] || p[i] == p[c]) continue;
            if (inTriangle(p[a], p[b], p[c], p[i]) &&
                orientation(p[prev[i]], p[i], p[next[i]]) <= 0)
                return false;
        }
        return true;
    };
    std::vector<CornerTriple> triangles;
    triangles.reserve(n - 2);
    std::size_t remaining = n, corner = 0, failures = 0;
    while (remaining > 3) {
        const std::size_t a = prev[corner], c = next[corner];
        // After a whole round without an ear the polygon is not simple: clip anyway, so that
        // the loop ends.
        if (failures >= remaining || isEar(a, corner, c)) {
            triangles.push_back({a, corner, c});
            next[a] = c;
            prev[c] = a;
            --remaining;
            failures = 0;
        } else {
            ++failures;
        }
        corner = c;
    }
    triangles.push_back({prev[corner], corner, next[corner]});
    return triangles;
}

// ---------------------------------------------------------------------------------------------
// Materials

struct IlluminationModel {
    bool lit;         // false: a constant colour (illum 0)
    bool highlights;  // Ks as Blinn-Phong highlights
    bool mirror;      // Ks as mirror reflection
    bool glass;       // clear, refracting with ior Ni
};

// Indexed by illum; see the table at the top of the file.
constexpr std::array<IlluminationModel, 11> kIlluminationModels{{
    {false, false, false, false},  // 0
    {true, false, false, false},   // 1
    {true, true, false, false},    // 2
    {true, true, true, false},     // 3
    {true, true, true, true},      // 4
    {true, true, true, false},     // 5
    {true, true, true, true},      // 6
    {true, true, false, true},     // 7
    {true, true, true, false},     // 8
    {true, true, false, true},     // 9
    {true, false, false, false},   // 10
}};
constexpr int kDefaultIllum = 2;
constexpr float kDefaultDiffuse = 0.8f;  // the scene format's

bool isGiven(const tinyobj::real_t* rgb) {
    return rgb[0] != kAbsent;
}

// Negative and non-finite components are read as 0.
Color colorOf(const tinyobj::real_t* rgb) {
    const auto component = [](tinyobj::real_t v) { return std::isfinite(v) && v > 0 ? v : 0; };
    return {component(rgb[0]), component(rgb[1]), component(rgb[2])};
}

// Turns MTL materials into ours, loading each texture once.
class MaterialConverter {
public:
    MaterialConverter(const ObjLoader::TextureLoader& loadTexture,
                      std::vector<std::string>& warnings)
        : loadTexture_(loadTexture), warnings_(warnings) {}

    std::shared_ptr<const Material> convert(const tinyobj::material_t& mtl,
                                            const fs::path& mtlPath) {
        const IlluminationModel& model = illuminationModel(mtl, mtlPath);
        auto material = std::make_unique<BlinnPhongMaterial::Parameters>();
        const Color kd = isGiven(mtl.diffuse) ? colorOf(mtl.diffuse) : Color(kDefaultDiffuse);
        const Color ka = colorOf(mtl.ambient), ks = colorOf(mtl.specular);
        material->emission = colorOf(mtl.emission);
        if (model.lit) {
            std::shared_ptr<const Texture> texture;
            if (!mtl.diffuse_texname.empty()) texture = diffuseTexture(mtl, mtlPath);
            material->diffuse = texture ? texture : std::make_shared<ConstantTexture>(kd);
            material->ambient =
                ka.isBlack() ? material->diffuse : std::make_shared<ConstantTexture>(ka);
        } else {
            material->emission += kd;
            material->diffuse = material->ambient = std::make_shared<ConstantTexture>(Color(0));
            if (!mtl.diffuse_texname.empty())
                warn(warnings_, mtlPath,
                     "material " + inQuotes(mtl.name) +
                         " is illum 0, an unlit constant colour: it shows its Kd colour, not "
                         "its map_Kd texture");
        }
        if (model.highlights) material->specular = ks;
        if (model.mirror) material->reflection = ks;
        if (mtl.shininess >= 0) material->shininess = mtl.shininess;
        if (mtl.ior > 0) material->ior = mtl.ior;
        const float opacity = std::isfinite(mtl.dissolve) ? clamp(mtl.dissolve, 0.0f, 1.0f) : 1;
        if (model.glass) {
            material->transmission = Color(1);
        } else if (opacity < 1) {
            material->transmission = Color(1 - opacity);
            material->ior = 1;
        }
        return std::make_shared<BlinnPhongMaterial>(std::move(*material));
    }

private:
    const IlluminationModel& illuminationModel(const tinyobj::material_t& mtl,
                                               const fs::path& mtlPath) {
        if (mtl.illum == kAbsentIllum) return kIlluminationModels[kDefaultIllum];
        if (mtl.illum >= 0 && mtl.illum < int(kIlluminationModels.size()))
            return kIlluminationModels[std::size_t(mtl.illum)];
        warn(warnings_, mtlPath,
             "material " + inQuotes(mtl.name) + " has illum " + std::to_string(mtl.illum) +
                 ", which is not an illumination model (0 to 10); illum " +
                 std::to_string(kDefaultIllum) + " is used");
        return kIlluminationModels[kDefaultIllum];
    }

    // Null when the texture cannot be loaded (with one warning per texture file).
    std::shared_ptr<const Texture> diffuseTexture(const tinyobj::material_t& mtl,
                                                  const fs::path& mtlPath) {
        const fs::path path = findTexture(mtlPath.parent_path(), mtl.diffuse_texname);
        const auto [cached, isNew] = textures_.try_emplace(path);
        if (!isNew) return cached->second;
        try {
            cached->second = loadTexture_(path);
        } catch (const InputError& error) {
            warn(warnings_, mtlPath,
                 "texture " + inQuotes(path.string()) + " (map_Kd of material " +
                     inQuotes(mtl.name) + ") cannot be loaded; the Kd colour is used instead (" +
                     error.message() + ")");
        }
        return cached->second;
    }

    // Exporters often write absolute paths of the author's machine: when the path leads nowhere,
    // the file of that name next to the MTL is taken instead.
    static fs::path findTexture(const fs::path& mtlFolder, const std::string& name) {
        const fs::path path = resolvePath(mtlFolder, name);
        const fs::path besideMtl = mtlFolder / path.filename();
        std::error_code error;
        if (!fs::exists(path, error) && fs::exists(besideMtl, error)) return besideMtl;
        return path;
    }

    const ObjLoader::TextureLoader& loadTexture_;
    std::vector<std::string>& warnings_;
    std::map<fs::path, std::shared_ptr<const Texture>> textures_;
};

// ---------------------------------------------------------------------------------------------
// Building the mesh

// One vertex of the mesh: an OBJ position, normal and uv index triple (-1: none).
struct CornerKey {
    int position = -1, normal = -1, uv = -1;
    bool operator==(const CornerKey&) const = default;
};

struct CornerKeyHash {
    std::size_t operator()(const CornerKey& key) const noexcept {
        constexpr std::uint64_t kMultiplier = 0x9E3779B97F4A7C15ull;  // 2^64 / golden ratio
        std::uint64_t h = std::uint32_t(key.position);
        h = h * kMultiplier ^ std::uint32_t(key.normal);
        h = h * kMultiplier ^ std::uint32_t(key.uv);
        return std::size_t(h ^ (h >> 32));
    }
};

class MeshBuilder {
public:
    MeshBuilder(const ObjContents& obj, const ObjLoader::TextureLoader& loadTexture,
                std::vector<std::string>& warnings)
        : obj_(obj),
          positionCount_(obj.attrib.vertices.size() / 3),
          normalCount_(obj.attrib.normals.size() / 3),
          uvCount_(obj.attrib.texcoords.size() / 2),
          materials_(loadTexture, warnings),
          mesh_(std::make_shared<TriangleMesh>()) {}

    // A face of `count` corners, with an index into the OBJ's materials (-1: none).
    void addFace(const tinyobj::index_t* corners, std::size_t count, int material) {
        ++faces_;
        faceKeys_.clear();
        facePositions_.clear();
        bool badNormal = false, badUv = false;
        for (std::size_t i = 0; i < count; ++i) {
            const tinyobj::index_t& corner = corners[i];
            if (corner.vertex_index < 0 || std::size_t(corner.vertex_index) >= positionCount_) {
                ++facesWithBadPositions_;
                return;
            }
            const Vec3 position = positionAt(corner.vertex_index);
            if (!isFinite(position)) {
                ++facesWithNonFinitePositions_;
                return;
            }
            faceKeys_.push_back({corner.vertex_index,
                                 checkedIndex(corner.normal_index, normalCount_, badNormal),
                                 checkedIndex(corner.texcoord_index, uvCount_, badUv)});
            facePositions_.push_back(position);
        }
        facesWithBadNormals_ += badNormal;
        facesWithBadUvs_ += badUv;
        std::vector<CornerTriple> triangles = triangulate(facePositions_);
        std::erase_if(triangles, [&](const CornerTriple& t) {
            const Vec3& p0 = facePositions_[t[0]];
            const bool zeroArea =
                !(length(cross(facePositions_[t[1]] - p0, facePositions_[t[2]] - p0)) > 0);
            zeroAreaTriangles_ += zeroArea;
            return zeroArea;
        });
        if (triangles.empty()) return;
        const std::uint32_t slot = materialSlot(material);
        for (const CornerTriple& triangle : triangles) {
            for (const std::size_t corner : triangle)
                mesh_->indices.push_back(vertex(faceKeys_[corner]));
            mesh_->faceMaterials.push_back(slot);
        }
    }

    // Faces dropped by the parser, counted among the faces.
    void addShortFaces(std::size_t count) {
        faces_ += count;
        shortFaces_ += count;
    }
    void addPointsOrLines() { pointsOrLines_ = true; }

    std::shared_ptr<TriangleMesh> finish(const fs::path& objPath,
                                         std::vector<std::string>& warnings) {
        const auto report = [&](std::size_t count, const std::string& noun,
                                const std::string& what) {
            if (count > 0) warn(warnings, objPath, countOf(count, noun) + " " + what);
        };
        report(shortFaces_, "face", "with fewer than 3 vertices ignored");
        report(facesWithBadPositions_, "face", "with vertex indices out of range dropped");
        report(facesWithNonFinitePositions_, "face", "with non-finite vertex coordinates dropped");
        report(facesWithBadNormals_, "face",
               "with normal (vn) indices out of range: those are ignored (flat shading)");
        report(facesWithBadUvs_, "face",
               "with texture coordinate (vt) indices out of range: those are ignored (uv 0, 0)");
        report(zeroAreaTriangles_, "zero-area triangle", "dropped");
        if (pointsOrLines_)
            warn(warnings, objPath, "points (p) and lines (l) are not rendered; they were ignored");
        if (mesh_->triangleCount() == 0)
            throw InputError(objPath.string(),
                             faces_ == 0
                                 ? "no faces (f) to render"
                                 : "none of its " + countOf(faces_, "face") + " can be rendered");
        if (!hasNormals_) mesh_->normals.clear();
        if (!hasUvs_) mesh_->uvs.clear();
        return mesh_;
    }

private:
    Vec3 positionAt(int index) const {
        const tinyobj::real_t* v = &obj_.attrib.vertices[3 * std::size_t(index)];
        return {v[0], v[1], v[2]};
    }

    // An attribute index, or -1 when there is none or it is out of range (noted in `bad`).
    static int checkedIndex(int index, std::size_t count, bool& bad) {
        if (index == -1) return -1;
        if (index >= 0 && std::size_t(index) < count) return index;
        bad = true;
        return -1;
    }

    std::uint32_t vertex(const CornerKey& key) {
        const auto [found, isNew] =
            vertices_.try_emplace(key, std::uint32_t(mesh_->positions.size()));
        if (!isNew) return found->second;
        mesh_->positions.push_back(positionAt(key.position));
        Vec3 normal;
        if (key.normal >= 0) {
            const tinyobj::real_t* n = &obj_.attrib.normals[3 * std::size_t(key.normal)];
            const Vec3 given(n[0], n[1], n[2]);
            // A zero or broken normal stays zero: "none", shaded flat.
            if (isFinite(given) && length(given) > 0) normal = normalize(given);
        }
        hasNormals_ |= normal != Vec3();
        mesh_->normals.push_back(normal);
        Vec2 uv;
        if (key.uv >= 0) {
            const tinyobj::real_t* t = &obj_.attrib.texcoords[2 * std::size_t(key.uv)];
            if (std::isfinite(t[0]) && std::isfinite(t[1])) uv = {t[0], t[1]};
            hasUvs_ = true;
        }
        mesh_->uvs.push_back(uv);
        return found->second;
    }

    // Materials are converted when a face first uses them, so that unused ones load no texture.
    std::uint32_t materialSlot(int material) {
        const bool defined = material >= 0 && std::size_t(material) < obj_.materials.size();
        const auto [slot, isNew] = slots_.try_emplace(defined ? material : -1, 0);
        if (!isNew) return slot->second;
        slot->second = std::uint32_t(mesh_->materials.size());
        if (!defined) {
            mesh_->materials.push_back(std::make_shared<BlinnPhongMaterial>());
        } else {
            const std::size_t index = std::size_t(material);
            mesh_->materials.push_back(
                materials_.convert(obj_.materials[index], obj_.libraries.fileOf(index)));
        }
        return slot->second;
    }

    const ObjContents& obj_;
    const std::size_t positionCount_, normalCount_, uvCount_;
    MaterialConverter materials_;
    std::shared_ptr<TriangleMesh> mesh_;
    std::unordered_map<CornerKey, std::uint32_t, CornerKeyHash> vertices_;
    std::map<int, std::uint32_t> slots_;  // OBJ material index (-1: the default) -> mesh's
    bool hasNormals_ = false, hasUvs_ = false, pointsOrLines_ = false;
    std::size_t faces_ = 0, shortFaces_ = 0, facesWithBadPositions_ = 0,
                facesWithNonFinitePositions_ = 0, facesWithBadNormals_ = 0, facesWithBadUvs_ = 0,
                zeroAreaTriangles_ = 0;
    std::vector<CornerKey> faceKeys_;  // of the face being added
    std::vector<Vec3> facePositions_;
};

}  // namespace

std::shared_ptr<TriangleMesh> ObjLoader::load(const fs::path& objPath,
                                              const TextureLoader& loadTexture,
                                              std::vector<std::string>& warnings) {
    std::ifstream file = openObj(objPath);
    ObjContents obj = parseObj(file, objPath, /*triangulate=*/false);
    if (hasTruncatedFaceSizes(obj.shapes)) {
        file.clear();
        file.seekg(0);
        obj = parseObj(file, objPath, /*triangulate=*/true);
        warn(warnings, objPath,
             "a face has more than 255 vertices, which tinyobjloader cannot pass on whole: the "
             "file was triangulated by tinyobjloader, which gets concave faces wrong");
    }
    const ParserFindings findings = readParserWarnings(obj.parserWarnings);
    reportMaterialProblems(obj, findings, objPath, warnings);

    MeshBuilder builder(obj, loadTexture, warnings);
    builder.addShortFaces(findings.shortFaces);
    for (const tinyobj::shape_t& shape : obj.shapes) {
        const tinyobj::mesh_t& faces = shape.mesh;
        std::size_t first = 0;
        for (std::size_t face = 0; face < faces.num_face_vertices.size(); ++face) {
            const std::size_t count = faces.num_face_vertices[face];
            builder.addFace(&faces.indices[first], count, faces.material_ids[face]);
            first += count;
        }
        if (!shape.lines.indices.empty() || !shape.points.indices.empty())
            builder.addPointsOrLines();
    }
    return builder.finish(objPath, warnings);
}

}  // namespace lancer
