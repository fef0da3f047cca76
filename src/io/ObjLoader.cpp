// OBJ models are parsed by tinyobjloader; faces are triangulated here (by PolygonTriangulator),
// and MTL materials mapped by MtlMaterialConverter.
//
// Triangulation: tinyobjloader 2.0.0rc10 splits a quad along its shorter diagonal and clips the
// ears of larger polygons with a wrong convexity test, so its triangles of a concave face overlap
// and spill outside it (the concave 66-gon of assimp's concave_polygon.obj becomes 44 triangles
// covering 7 times its area). So faces are read whole and split by ear clipping. tinyobjloader
// stores a face's vertex count in one byte, though: a file with a face of more than 255 vertices is
// read again with tinyobjloader's own triangulation, and a warning.

#include "io/ObjLoader.h"

#include <tiny_obj_loader.h>

#include <algorithm>
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

#include "geometry/PolygonTriangulator.h"
#include "io/Fingerprint.h"
#include "io/InputFile.h"
#include "io/MtlMaterialConverter.h"
#include "io/ObjSupport.h"
#include "materials/BlinnPhongMaterial.h"
#include "scene/InputError.h"

namespace lancer {

namespace fs = std::filesystem;

namespace {

std::string quotedList(const std::vector<std::string>& names) {
    std::string list;
    for (const std::string& name : names)
        list += (list.empty() ? "" : ", ") + inQuotes(name);
    return list;
}

// ---------------------------------------------------------------------------------------------
// Reading the files

// Opens the MTL files that `mtllib` lines name, relative to the OBJ's folder, and remembers the
// file each material comes from (its texture paths are relative to it) and the files not found.
class MaterialLibraries final : public tinyobj::MaterialReader {
public:
    explicit MaterialLibraries(fs::path objFolder) : objFolder_(std::move(objFolder)) {}

    bool operator()(const std::string& name, std::vector<tinyobj::material_t>* materials,
                    std::map<std::string, int>* materialIds, std::string* mtlWarnings,
                    std::string* mtlErrors) override {
        tried_.push_back(name);
        const fs::path path = resolvePath(objFolder_, name);
        triedFiles_.addFile(path);  // before reading it, as sourceFiles() sees it
        try {
            InputFile::check(path, "an MTL file", "MTL files", InputFile::kMaxModelBytes);
        } catch (const InputError& e) {
            throw InputError(path.string(), "mtllib " + inQuotes(name) + ": " + e.message());
        }
        std::error_code error;
        std::ifstream file(path, std::ios::binary);
        if (!file || fs::is_directory(path, error)) {
            if (std::find(missing_.begin(), missing_.end(), path) == missing_.end())
                missing_.push_back(path);
            return false;
        }
        std::istringstream text(MtlMaterialConverter::markAbsentKeys(file));
        tinyobj::LoadMtl(materialIds, materials, &text, mtlWarnings, mtlErrors);
        files_.resize(materials->size(), path);
        read_.push_back(path);
        return true;
    }

    bool anyNamed() const { return !tried_.empty(); }
    const std::vector<std::string>& namesTried() const { return tried_; }
    const std::vector<fs::path>& missingFiles() const { return missing_; }
    const fs::path& fileOf(std::size_t material) const { return files_[material]; }
    const std::vector<fs::path>& filesRead() const { return read_; }
    std::uint64_t triedFilesFingerprint() const { return triedFiles_.value(); }

private:
    fs::path objFolder_;
    std::vector<std::string> tried_;
    std::vector<fs::path> missing_;
    std::vector<fs::path> files_;  // per material
    std::vector<fs::path> read_;
    Fingerprint triedFiles_;
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
    InputFile::check(path, "an OBJ file", "OBJ files", InputFile::kMaxModelBytes);
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
// Building the mesh

using CornerTriple = PolygonTriangulator::CornerTriple;

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
    MeshBuilder(const ObjContents& obj, std::vector<int>& materialSources)
        : obj_(obj),
          positionCount_(obj.attrib.vertices.size() / 3),
          normalCount_(obj.attrib.normals.size() / 3),
          uvCount_(obj.attrib.texcoords.size() / 2),
          materialSources_(materialSources),
          mesh_(std::make_shared<TriangleMesh>()),
          firstVertexAt_(positionCount_, kNoVertex) {}

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
        zeroAreaTriangles_ += triangulateLessZeroArea(facePositions_, faceTriangles_);
        if (faceTriangles_.empty()) return;
        const std::uint32_t slot = materialSlot(material);
        for (const CornerTriple& triangle : faceTriangles_) {
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

    // The vertex of a corner: the one made for the first corner with its position, normal and
    // uv, or a new one. Most models give a position one normal and one uv, so the vertex first
    // made for the position is looked at before the hash map, which then holds only the others.
    std::uint32_t vertex(const CornerKey& key) {
        const auto position = std::size_t(key.position);
        std::uint32_t& first = firstVertexAt_[position];
        if (first == kNoVertex) return first = newVertex(key);
        const CornerKey& firstKey = vertexKeys_[first];
        if (firstKey.normal == key.normal && firstKey.uv == key.uv) return first;
        const auto [found, isNew] = vertices_.try_emplace(key, 0);
        if (isNew) found->second = newVertex(key);
        return found->second;
    }

    std::uint32_t newVertex(const CornerKey& key) {
        vertexKeys_.push_back(key);
        mesh_->positions.push_back(positionAt(key.position));
        Vec3 normal;
        if (key.normal >= 0) {
            const tinyobj::real_t* n = &obj_.attrib.normals[3 * std::size_t(key.normal)];
            normal = usableNormal(Vec3(n[0], n[1], n[2]));
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
        return std::uint32_t(mesh_->positions.size() - 1);
    }

    // The mesh's materials are the OBJ's that faces use, in the order they are first used, so
    // that unused ones load no texture.
    std::uint32_t materialSlot(int material) {
        const bool defined = material >= 0 && std::size_t(material) < obj_.materials.size();
        const auto [slot, isNew] = slots_.try_emplace(defined ? material : -1, 0);
        if (!isNew) return slot->second;
        slot->second = std::uint32_t(materialSources_.size());
        materialSources_.push_back(defined ? material : -1);
        return slot->second;
    }

    const ObjContents& obj_;
    const std::size_t positionCount_, normalCount_, uvCount_;
    std::vector<int>& materialSources_;
    std::shared_ptr<TriangleMesh> mesh_;
    static constexpr std::uint32_t kNoVertex = ~std::uint32_t{0};
    std::vector<std::uint32_t> firstVertexAt_;  // per position: its first vertex, or kNoVertex
    std::vector<CornerKey> vertexKeys_;         // per vertex: the corner it was made for
    std::unordered_map<CornerKey, std::uint32_t, CornerKeyHash> vertices_;  // the others
    std::map<int, std::uint32_t> slots_;  // OBJ material index (-1: the default) -> mesh's
    bool hasNormals_ = false, hasUvs_ = false, pointsOrLines_ = false;
    std::size_t faces_ = 0, shortFaces_ = 0, facesWithBadPositions_ = 0,
                facesWithNonFinitePositions_ = 0, facesWithBadNormals_ = 0, facesWithBadUvs_ = 0,
                zeroAreaTriangles_ = 0;
    std::vector<CornerKey> faceKeys_;  // of the face being added
    std::vector<Vec3> facePositions_;
    std::vector<CornerTriple> faceTriangles_;
};

}  // namespace

ObjLoader::Geometry ObjLoader::readGeometry(const fs::path& objPath) {
    SourceFiles sources;
    sources.obj = Fingerprint().addFile(objPath).value();
    std::ifstream file = openObj(objPath);
    ObjContents obj = parseObj(file, objPath, /*triangulate=*/false);
    ObjCompletion completion;
    if (hasTruncatedFaceSizes(obj.shapes)) {
        file.clear();
        file.seekg(0);
        obj = parseObj(file, objPath, /*triangulate=*/true);
        warn(completion.warningsBeforeMaterials, objPath,
             "a face has more than 255 vertices, which tinyobjloader cannot pass on whole: the "
             "file was triangulated by tinyobjloader, which gets concave faces wrong");
    }
    const ParserFindings findings = readParserWarnings(obj.parserWarnings);
    reportMaterialProblems(obj, findings, objPath, completion.warningsBeforeMaterials);
    completion.libraryNames = obj.libraries.namesTried();
    sources.libraries = obj.libraries.triedFilesFingerprint();

    MeshBuilder builder(obj, completion.materialSources);
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
    std::shared_ptr<TriangleMesh> triangles =
        builder.finish(objPath, completion.warningsAfterMaterials);
    return {std::move(triangles), std::move(completion), sources};
}

std::vector<std::shared_ptr<const Material>> ObjLoader::complete(
    const fs::path& objPath, const ObjCompletion& completion, const TextureLoader& loadTexture,
    std::vector<std::string>& warnings, std::vector<fs::path>* materialFiles) {
    warnings.insert(warnings.end(), completion.warningsBeforeMaterials.begin(),
                    completion.warningsBeforeMaterials.end());
    // The libraries are read again as tinyobjloader read them, which gives the same materials
    // in the same order (the model cache checks that the files have not changed).
    MaterialLibraries libraries(objPath.parent_path());
    std::vector<tinyobj::material_t> defined;
    std::map<std::string, int> ids;
    for (const std::string& name : completion.libraryNames) {
        std::string mtlWarnings, mtlErrors;
        libraries(name, &defined, &ids, &mtlWarnings, &mtlErrors);
    }
    if (materialFiles)
        materialFiles->insert(materialFiles->end(), libraries.filesRead().begin(),
                              libraries.filesRead().end());
    MtlMaterialConverter converter(loadTexture, warnings);
    std::vector<std::shared_ptr<const Material>> materials;
    for (const int source : completion.materialSources) {
        if (source < 0 || std::size_t(source) >= defined.size())
            materials.push_back(std::make_shared<BlinnPhongMaterial>());
        else
            materials.push_back(converter.convert(defined[std::size_t(source)],
                                                  libraries.fileOf(std::size_t(source))));
    }
    warnings.insert(warnings.end(), completion.warningsAfterMaterials.begin(),
                    completion.warningsAfterMaterials.end());
    return materials;
}

ObjLoader::SourceFiles ObjLoader::sourceFiles(const fs::path& objPath,
                                              const ObjCompletion& completion) {
    // As readGeometry and MaterialLibraries fingerprint them.
    Fingerprint libraries;
    for (const std::string& name : completion.libraryNames)
        libraries.addFile(resolvePath(objPath.parent_path(), name));
    return {Fingerprint().addFile(objPath).value(), libraries.value()};
}

std::shared_ptr<TriangleMesh> ObjLoader::load(const fs::path& objPath,
                                              const TextureLoader& loadTexture,
                                              std::vector<std::string>& warnings,
                                              std::vector<fs::path>* materialFiles) {
    Geometry geometry = readGeometry(objPath);
    geometry.triangles->materials =
        complete(objPath, geometry.completion, loadTexture, warnings, materialFiles);
    return geometry.triangles;
}

}  // namespace lancer
