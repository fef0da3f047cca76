// PLY models are parsed by Assimp's PLY importer, given the file from memory so that no other
// importer sees it. Assimp trusts the header: it allocates for the element counts it declares
// before reading a byte of the body (a 300-byte file declaring 10^9 vertices took 11 GB and over a
// minute) and reads a truncated ASCII body on as if it were whole. So the header is read here
// first and the body walked against it, element by element, before Assimp is called: what Assimp
// then allocates is bounded by the file's size.

#include "io/PlyLoader.h"

#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/Importer.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <exception>
#include <fstream>
#include <limits>
#include <sstream>
#include <string_view>
#include <utility>

#include "geometry/PolygonTriangulator.h"
#include "io/InputFile.h"
#include "io/ObjSupport.h"
#include "materials/BlinnPhongMaterial.h"
#include "scene/InputError.h"

namespace lancer {

namespace fs = std::filesystem;

namespace {

// ---------------------------------------------------------------------------------------------
// The header, and the body checked against it

enum class PlyFormat { Ascii, BinaryLittleEndian, BinaryBigEndian };

struct PlyProperty {
    std::size_t countBytes = 0;  // a list's count type; 0: not a list
    std::size_t valueBytes = 0;  // the value's type, or a list item's
};

struct PlyElement {
    std::string name;
    std::uint64_t count = 0;
    std::vector<PlyProperty> properties;
};

struct PlyHeader {
    PlyFormat format = PlyFormat::Ascii;
    std::vector<PlyElement> elements;
    std::size_t bodyStart = 0;  // the offset of the byte after end_header's line
};

// Every scalar type of the PLY specification, under both its old and its sized names.
std::size_t typeBytes(const std::string& type) {
    static const std::pair<const char*, std::size_t> kTypes[] = {
        {"char", 1},  {"uchar", 1},   {"int8", 1},   {"uint8", 1},  {"short", 2}, {"ushort", 2},
        {"int16", 2}, {"uint16", 2},  {"int", 4},    {"uint", 4},   {"int32", 4}, {"uint32", 4},
        {"float", 4}, {"float32", 4}, {"double", 8}, {"float64", 8}};
    for (const auto& [name, bytes] : kTypes)
        if (type == name) return bytes;
    return 0;
}

class HeaderReader {
public:
    HeaderReader(const fs::path& path, const std::string& data) : path_(path), data_(data) {}

    PlyHeader read() {
        PlyHeader header;
        nextLine();  // "ply", checked by the caller
        bool formatGiven = false;
        for (;;) {
            if (at_ >= data_.size()) fail("the header has no end_header line");
            std::istringstream words(nextLine());
            std::string keyword;
            words >> keyword;
            if (keyword == "end_header") break;
            if (keyword == "format") {
                std::string format;
                words >> format;
                if (format == "ascii")
                    header.format = PlyFormat::Ascii;
                else if (format == "binary_little_endian")
                    header.format = PlyFormat::BinaryLittleEndian;
                else if (format == "binary_big_endian")
                    header.format = PlyFormat::BinaryBigEndian;
                else
                    fail("unknown format " + inQuotes(format));
                formatGiven = true;
            } else if (keyword == "element") {
                PlyElement element;
                if (!(words >> element.name >> element.count))
                    fail("an element line is not \"element NAME COUNT\"");
                header.elements.push_back(std::move(element));
            } else if (keyword == "property") {
                if (header.elements.empty()) fail("a property comes before any element");
                header.elements.back().properties.push_back(readProperty(words));
            } else if (!keyword.empty() && keyword != "comment" && keyword != "obj_info") {
                fail("unknown header line " + inQuotes(keyword));
            }
        }
        if (!formatGiven) fail("the header has no format line");
        for (const PlyElement& element : header.elements)
            if (element.count > 0 && element.properties.empty())
                fail("element " + inQuotes(element.name) + " has no properties");
        header.bodyStart = at_;
        return header;
    }

private:
    std::string nextLine() {
        const std::size_t end = std::min(data_.find('\n', at_), data_.size());
        std::string line = data_.substr(at_, end - at_);
        if (!line.empty() && line.back() == '\r') line.pop_back();
        at_ = std::min(end + 1, data_.size());
        ++lineNumber_;
        // Text and tabs only: Assimp's header parser loops for ever on a line that starts with a
        // carriage return, a vertical tab or a form feed (found by fuzz_ply).
        for (const char c : line)
            if (static_cast<unsigned char>(c) < 0x20 && c != '\t') {
                char code[8];
                std::snprintf(code, sizeof code, "0x%02X", static_cast<unsigned char>(c));
                fail("header line " + std::to_string(lineNumber_) +
                     " holds the control character " + code);
            }
        return line;
    }

    PlyProperty readProperty(std::istringstream& words) {
        std::string type;
        words >> type;
        PlyProperty property;
        if (type == "list") {
            std::string countType;
            words >> countType >> type;
            property.countBytes = typeBytes(countType);
            if (property.countBytes == 0) fail("unknown list count type " + inQuotes(countType));
        }
        property.valueBytes = typeBytes(type);
        if (property.valueBytes == 0) fail("unknown property type " + inQuotes(type));
        return property;
    }

    [[noreturn]] void fail(const std::string& message) const {
        throw InputError(path_.string(), "not a valid PLY file: " + message);
    }

    const fs::path& path_;
    const std::string& data_;
    std::size_t at_ = 0;
    int lineNumber_ = 0;  // of the line last read
};

// Walks the body element by element, so that a body shorter than its header says is an error
// here rather than garbage (or a huge allocation) in Assimp.
class BodyChecker {
public:
    BodyChecker(const fs::path& path, const std::string& data, const PlyHeader& header)
        : path_(path), data_(data), header_(header), at_(header.bodyStart) {}

    void check() {
        for (const PlyElement& element : header_.elements) {
            // A count beyond what the bytes left can hold is refused before the walk, which is
            // then bounded by them (the last ASCII value needs no separator after it).
            const std::uint64_t least = minimumBytes(element);
            if (least == 0) continue;  // no properties: nothing to read, however many
            if (element.count > (data_.size() - at_ + 1) / least) truncated(element);
            for (std::uint64_t i = 0; i < element.count; ++i)
                for (const PlyProperty& property : element.properties)
                    if (!skip(property)) truncated(element);
        }
    }

private:
    // Of one element (never 0: it has properties): a value takes a digit and a separator in
    // ASCII; in binary its type's bytes, a list its count's.
    std::uint64_t minimumBytes(const PlyElement& element) const {
        const bool ascii = header_.format == PlyFormat::Ascii;
        std::uint64_t bytes = 0;
        for (const PlyProperty& property : element.properties)
            bytes += ascii                     ? 2
                     : property.countBytes > 0 ? property.countBytes
                                               : property.valueBytes;
        return bytes;
    }

    bool skip(const PlyProperty& property) {
        if (header_.format == PlyFormat::Ascii) {
            std::string_view token;
            if (!nextToken(token)) return false;
            if (property.countBytes == 0) return true;
            std::uint64_t count = 0;
            for (const char c : token) {
                if (!std::isdigit(static_cast<unsigned char>(c)) || count > data_.size())
                    throw InputError(path_.string(), "not a valid PLY file: a list's count " +
                                                         inQuotes(std::string(token)) +
                                                         " is not a count");
                count = count * 10 + std::uint64_t(c - '0');
            }
            for (std::uint64_t i = 0; i < count; ++i)
                if (!nextToken(token)) return false;
            return true;
        }
        if (property.countBytes == 0) return advance(property.valueBytes);
        if (data_.size() - at_ < property.countBytes) return false;
        const std::uint64_t count = readUnsigned(property.countBytes);
        at_ += property.countBytes;
        return count <= (data_.size() - at_) / property.valueBytes &&
               advance(count * property.valueBytes);
    }

    bool advance(std::uint64_t bytes) {
        if (data_.size() - at_ < bytes) return false;
        at_ += std::size_t(bytes);
        return true;
    }

    // A list's count; its sign is not looked at, as a negative count is refused as too large.
    std::uint64_t readUnsigned(std::size_t bytes) const {
        std::uint64_t value = 0;
        for (std::size_t i = 0; i < bytes; ++i) {
            const std::size_t byte =
                header_.format == PlyFormat::BinaryBigEndian ? i : bytes - 1 - i;
            value = value << 8 | static_cast<unsigned char>(data_[at_ + byte]);
        }
        return value;
    }

    bool nextToken(std::string_view& token) {
        const auto isSpace = [](char c) { return std::isspace(static_cast<unsigned char>(c)); };
        while (at_ < data_.size() && isSpace(data_[at_]))
            ++at_;
        const std::size_t start = at_;
        while (at_ < data_.size() && !isSpace(data_[at_]))
            ++at_;
        token = std::string_view(data_).substr(start, at_ - start);
        return !token.empty();
    }

    [[noreturn]] void truncated(const PlyElement& element) const {
        throw InputError(path_.string(),
                         "is truncated: its header declares " +
                             countOf(element.count, inQuotes(element.name) + " element") +
                             ", more than its body holds");
    }

    const fs::path& path_;
    const std::string& data_;
    const PlyHeader& header_;
    std::size_t at_;
};

// ---------------------------------------------------------------------------------------------
// Reading the file, and the mesh

bool startsWithMagic(std::string_view data) {
    return data.size() >= 4 && data.substr(0, 3) == "ply" && (data[3] == '\n' || data[3] == '\r');
}

std::string readWhole(const fs::path& path) {
    InputFile::check(path, "a PLY file", "PLY files", InputFile::kMaxModelBytes);
    std::ifstream file(path, std::ios::binary);
    if (!file) throw InputError(path.string(), "cannot open the PLY file (does it exist?)");
    // Read in blocks up to the limit, which a pipe (that check passes) would not stop at.
    std::string data;
    constexpr std::size_t kBlock = std::size_t{1} << 20;
    while (file) {
        if (data.size() > InputFile::kMaxModelBytes)
            throw InputFile::tooLarge(path, "PLY files", InputFile::kMaxModelBytes);
        const std::size_t size = data.size();
        data.resize(size + kBlock);
        file.read(data.data() + size, std::streamsize(kBlock));
        data.resize(size + std::size_t(file.gcount()));
    }
    if (file.bad()) throw InputError(path.string(), "cannot read the PLY file");
    if (data.empty()) throw InputError(path.string(), "is empty, not a PLY file");
    if (!startsWithMagic(data))
        throw InputError(path.string(), "is not a PLY file (its first line is not \"ply\")");
    return data;
}

// Assimp's validation messages, said in PLY's terms where the fault is the file's.
InputError importError(const fs::path& path, const std::string& message) {
    if (message.find("contains no faces") != std::string::npos)
        return InputError(path.string(), "no faces to render");
    if (message.find("is out of range") != std::string::npos)
        return InputError(path.string(),
                          "a face's vertex index is out of range (Assimp: " + message + ")");
    return InputError(path.string(), "not a valid PLY file: " + message);
}

class MeshConverter {
public:
    explicit MeshConverter(std::shared_ptr<TriangleMesh> mesh) : mesh_(std::move(mesh)) {}

    void add(const aiMesh& source) {
        const auto first = std::uint32_t(mesh_->positions.size());
        const bool hasUvs = source.HasTextureCoords(0);
        hasNormals_ |= source.HasNormals();
        hasUvs_ |= hasUvs;
        hasColours_ |= source.HasVertexColors(0);
        for (unsigned i = 0; i < source.mNumVertices; ++i) {
            const aiVector3D& p = source.mVertices[i];
            mesh_->positions.emplace_back(p.x, p.y, p.z);
            Vec3 normal;
            if (source.HasNormals()) {
                const aiVector3D& n = source.mNormals[i];
                const Vec3 given(n.x, n.y, n.z);
                // A zero or broken normal stays zero: "none", shaded flat.
                if (isFinite(given) && length(given) > 0) normal = normalize(given);
            }
            mesh_->normals.push_back(normal);
            Vec2 uv;
            if (hasUvs) {
                const aiVector3D& t = source.mTextureCoords[0][i];
                if (std::isfinite(t.x) && std::isfinite(t.y)) uv = {t.x, t.y};
            }
            mesh_->uvs.push_back(uv);
        }
        for (unsigned f = 0; f < source.mNumFaces; ++f) {
            const aiFace& face = source.mFaces[f];
            if (face.mNumIndices < 3) {
                ++pointsAndLines_;
                continue;
            }
            facePositions_.clear();
            for (unsigned k = 0; k < face.mNumIndices; ++k)
                facePositions_.push_back(mesh_->positions[first + face.mIndices[k]]);
            if (!std::all_of(facePositions_.begin(), facePositions_.end(),
                             [](const Vec3& p) { return isFinite(p); })) {
                ++nonFinite_;
                continue;
            }
            addTriangles(face, first);
        }
    }

    // A face split as the OBJ loader splits its faces (concave ones right), less zero-area
    // triangles; facePositions_ holds its corners.
    void addTriangles(const aiFace& face, std::uint32_t first) {
        PolygonTriangulator::triangulate(facePositions_, faceTriangles_);
        for (const PolygonTriangulator::CornerTriple& t : faceTriangles_) {
            const Vec3& p0 = facePositions_[t[0]];
            if (!(length(cross(facePositions_[t[1]] - p0, facePositions_[t[2]] - p0)) > 0)) {
                ++zeroArea_;
                continue;
            }
            for (const std::size_t corner : t)
                mesh_->indices.push_back(first + face.mIndices[corner]);
            mesh_->faceMaterials.push_back(0);
        }
    }

    std::shared_ptr<TriangleMesh> finish(const fs::path& path, std::vector<std::string>& warnings) {
        if (hasColours_)
            warn(warnings, path, "vertex colours are not used; the object's material applies");
        if (pointsAndLines_ > 0)
            warn(warnings, path,
                 countOf(pointsAndLines_, "face") +
                     " with fewer than 3 vertices (points, lines) ignored");
        if (nonFinite_ > 0)
            warn(warnings, path,
                 countOf(nonFinite_, "face") + " with non-finite vertex coordinates dropped");
        if (zeroArea_ > 0)
            warn(warnings, path, countOf(zeroArea_, "zero-area triangle") + " dropped");
        if (mesh_->triangleCount() == 0) throw InputError(path.string(), "no faces to render");
        if (!hasNormals_) mesh_->normals.clear();
        if (!hasUvs_) mesh_->uvs.clear();
        mesh_->materials.push_back(std::make_shared<BlinnPhongMaterial>());
        return mesh_;
    }

private:
    std::shared_ptr<TriangleMesh> mesh_;
    bool hasNormals_ = false, hasUvs_ = false, hasColours_ = false;
    std::size_t pointsAndLines_ = 0, nonFinite_ = 0, zeroArea_ = 0;
    std::vector<Vec3> facePositions_;                               // of the face being added
    std::vector<PolygonTriangulator::CornerTriple> faceTriangles_;  // and its triangles
};

}  // namespace

bool PlyLoader::isPly(const fs::path& path) {
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    if (extension == ".ply") return true;
    // Only a regular file is peeked at: a pipe could block, a device never end.
    std::error_code error;
    if (!fs::is_regular_file(path, error)) return false;
    std::ifstream file(path, std::ios::binary);
    char magic[4] = {};
    file.read(magic, 4);
    return startsWithMagic(std::string_view(magic, std::size_t(file.gcount())));
}

std::shared_ptr<TriangleMesh> PlyLoader::load(const fs::path& path,
                                              std::vector<std::string>& warnings) {
    const std::string data = readWhole(path);
    const PlyHeader header = HeaderReader(path, data).read();
    BodyChecker(path, data, header).check();

    // Assimp logs nothing unless a logger is created, which lancer never does. Its validation
    // catches the indices out of range. Faces are triangulated here, as OBJ's are: Assimp's
    // triangulation aborts the process (an assertion) on faces of no vertices, and gets concave
    // faces wrong. No other step is asked for: the file's vertices are the mesh's.
    Assimp::Importer importer;
    const aiScene* scene = nullptr;
    try {
        scene = importer.ReadFileFromMemory(data.data(), data.size(),
                                            aiProcess_ValidateDataStructure, "ply");
    } catch (const std::exception& e) {  // Assimp catches its own, but not in every build
        throw importError(path, e.what());
    }
    if (!scene) throw importError(path, importer.GetErrorString());
    MeshConverter converter(std::make_shared<TriangleMesh>());
    for (unsigned m = 0; m < scene->mNumMeshes; ++m)
        converter.add(*scene->mMeshes[m]);
    return converter.finish(path, warnings);
}

}  // namespace lancer
