// PLY models are read here, header and body. They were read by Assimp's PLY importer, which trusts
// the header (a 300-byte file declaring 10^9 vertices took 11 GB) and, in the version Debian
// ships (5.2.5), writes outside its buffers on some malformed files (fuzz_ply found the heap
// corrupted; upstream fixed several such overflows in its PLY importer since). The format is small:
// a header of elements and their typed properties, then the elements' values, as text or as
// binary of either byte order. So every count here is bounded by the file's size before anything
// is allocated for it, and every read by the bytes left.

#include "io/PlyLoader.h"

#include <algorithm>
#include <bit>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <span>
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
// The header

enum class PlyFormat { Ascii, BinaryLittleEndian, BinaryBigEndian };

enum class ScalarType { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

struct PlyProperty {
    std::string name;
    ScalarType type = ScalarType::Float32;  // the value's, or a list item's
    bool isList = false;
    ScalarType countType = ScalarType::UInt8;  // a list's count
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
    int bodyLine = 0;           // and its line number
};

// Every scalar type of the PLY specification, under both its old and its sized names.
bool parseType(const std::string& name, ScalarType& type) {
    static const std::pair<const char*, ScalarType> kTypes[] = {
        {"char", ScalarType::Int8},      {"int8", ScalarType::Int8},
        {"uchar", ScalarType::UInt8},    {"uint8", ScalarType::UInt8},
        {"short", ScalarType::Int16},    {"int16", ScalarType::Int16},
        {"ushort", ScalarType::UInt16},  {"uint16", ScalarType::UInt16},
        {"int", ScalarType::Int32},      {"int32", ScalarType::Int32},
        {"uint", ScalarType::UInt32},    {"uint32", ScalarType::UInt32},
        {"float", ScalarType::Float32},  {"float32", ScalarType::Float32},
        {"double", ScalarType::Float64}, {"float64", ScalarType::Float64}};
    for (const auto& [typeName, value] : kTypes)
        if (name == typeName) {
            type = value;
            return true;
        }
    return false;
}

std::size_t bytesOf(ScalarType type) {
    switch (type) {
        case ScalarType::Int8:
        case ScalarType::UInt8:
            return 1;
        case ScalarType::Int16:
        case ScalarType::UInt16:
            return 2;
        case ScalarType::Int32:
        case ScalarType::UInt32:
        case ScalarType::Float32:
            return 4;
        case ScalarType::Float64:
            return 8;
    }
    return 8;
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
        header.bodyLine = lineNumber_ + 1;
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
            property.isList = true;
            std::string countType;
            words >> countType >> type;
            if (!parseType(countType, property.countType))
                fail("unknown list count type " + inQuotes(countType));
        }
        if (!parseType(type, property.type)) fail("unknown property type " + inQuotes(type));
        words >> property.name;
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

// ---------------------------------------------------------------------------------------------
// The body

// What a vertex property is to lancer.
enum class VertexRole { Ignored, X, Y, Z, NormalX, NormalY, NormalZ, U, V, Colour };
constexpr std::size_t kVertexRoles = std::size_t(VertexRole::Colour) + 1;

VertexRole roleOf(const PlyProperty& property) {
    static const std::pair<const char*, VertexRole> kRoles[] = {
        {"x", VertexRole::X},          {"y", VertexRole::Y},         {"z", VertexRole::Z},
        {"nx", VertexRole::NormalX},   {"ny", VertexRole::NormalY},  {"nz", VertexRole::NormalZ},
        {"u", VertexRole::U},          {"s", VertexRole::U},         {"texture_u", VertexRole::U},
        {"texture_s", VertexRole::U},  {"v", VertexRole::V},         {"t", VertexRole::V},
        {"texture_v", VertexRole::V},  {"texture_t", VertexRole::V}, {"red", VertexRole::Colour},
        {"green", VertexRole::Colour}, {"blue", VertexRole::Colour}};
    if (property.isList) return VertexRole::Ignored;
    for (const auto& [name, role] : kRoles)
        if (property.name == name) return role;
    return VertexRole::Ignored;
}

// The faces' corners, face after face.
struct PlyFaces {
    std::vector<std::uint32_t> corners;
    std::vector<std::size_t> ends;  // of each face's corners in `corners`
};

// Reads the body element by element into the mesh's vertices and the faces; other elements are
// read past. A count is refused (as a truncated body) before anything is allocated for it when
// the bytes left cannot hold it.
class BodyReader {
public:
    BodyReader(const fs::path& path, const std::string& data, const PlyHeader& header,
               TriangleMesh& mesh)
        : path_(path),
          data_(data),
          header_(header),
          mesh_(mesh),
          at_(header.bodyStart),
          line_(header.bodyLine),
          lineStart_(header.bodyStart) {}

    PlyFaces read() {
        bool verticesRead = false, facesRead = false;
        for (const PlyElement& element : header_.elements) {
            element_ = &element;
            const std::uint64_t least = minimumBytes(element);
            if (least == 0) continue;  // no properties: nothing to read, however many
            // The last ASCII value needs no separator after it.
            if (element.count > (data_.size() - at_ + 1) / least) truncated();
            if (element.name == "vertex" && !verticesRead) {
                readVertices(element);
                verticesRead = true;
            } else if (element.name == "face" && !facesRead) {
                readFaces(element);
                facesRead = true;
            } else {
                for (std::uint64_t i = 0; i < element.count; ++i)
                    for (const PlyProperty& property : element.properties)
                        skip(property);
            }
        }
        return std::move(faces_);
    }

    bool hasColours() const { return hasColours_; }

private:
    void readVertices(const PlyElement& element) {
        std::vector<VertexRole> roles;
        bool present[kVertexRoles] = {};
        for (const PlyProperty& property : element.properties) {
            roles.push_back(roleOf(property));
            present[int(roles.back())] = true;
        }
        const auto has = [&](VertexRole role) { return present[int(role)]; };
        if (!has(VertexRole::X) || !has(VertexRole::Y) || !has(VertexRole::Z))
            headerFault("the \"vertex\" element has no x, y and z properties");
        hasNormals_ =
            has(VertexRole::NormalX) && has(VertexRole::NormalY) && has(VertexRole::NormalZ);
        hasUvs_ = has(VertexRole::U) && has(VertexRole::V);
        hasColours_ = has(VertexRole::Colour);

        const auto count = std::size_t(element.count);
        mesh_.positions.reserve(count);
        if (hasNormals_) mesh_.normals.reserve(count);
        if (hasUvs_) mesh_.uvs.reserve(count);
        float values[kVertexRoles] = {};
        for (std::size_t i = 0; i < count; ++i) {
            for (std::size_t p = 0; p < roles.size(); ++p) {
                const PlyProperty& property = element.properties[p];
                if (roles[p] == VertexRole::Ignored || roles[p] == VertexRole::Colour)
                    skip(property);
                else
                    values[int(roles[p])] = readValue<float>(property);
            }
            const auto value = [&](VertexRole role) { return values[int(role)]; };
            mesh_.positions.emplace_back(value(VertexRole::X), value(VertexRole::Y),
                                         value(VertexRole::Z));
            if (hasNormals_) {
                mesh_.normals.push_back(
                    usableNormal(Vec3(value(VertexRole::NormalX), value(VertexRole::NormalY),
                                      value(VertexRole::NormalZ))));
            }
            if (hasUvs_) {
                const Vec2 uv(value(VertexRole::U), value(VertexRole::V));
                mesh_.uvs.push_back(std::isfinite(uv.x) && std::isfinite(uv.y) ? uv : Vec2());
            }
        }
    }

    void readFaces(const PlyElement& element) {
        const auto corners = std::find_if(
            element.properties.begin(), element.properties.end(), [](const PlyProperty& property) {
                return property.name == "vertex_indices" || property.name == "vertex_index";
            });
        if (corners == element.properties.end() || !corners->isList)
            headerFault("the \"face\" element has no vertex_indices list");
        faces_.ends.reserve(std::size_t(element.count));
        for (std::uint64_t i = 0; i < element.count; ++i) {
            for (const PlyProperty& property : element.properties) {
                if (&property != &*corners) {
                    skip(property);
                    continue;
                }
                const std::uint64_t count = readCount(property);
                for (std::uint64_t k = 0; k < count; ++k) {
                    const double index = readValue<double>(property);
                    // Whether it names a vertex is known once every element is read.
                    if (!(index >= 0 && index <= double(UINT32_MAX) && index == std::floor(index)))
                        throw InputError(path_.string(), location(),
                                         "a face's vertex index is out of range: face " +
                                             std::to_string(i) + " names vertex " +
                                             numberText(index));
                    faces_.corners.push_back(std::uint32_t(index));
                }
                faces_.ends.push_back(faces_.corners.size());
            }
        }
    }

    void skip(const PlyProperty& property) {
        const std::uint64_t count = property.isList ? readCount(property) : 1;
        for (std::uint64_t k = 0; k < count; ++k) {
            if (ascii())
                nextToken();
            else
                advance(bytesOf(property.type));
        }
    }

    // A list's length, refused as a truncated body when the bytes left cannot hold its items.
    std::uint64_t readCount(const PlyProperty& property) {
        std::uint64_t count = 0;
        if (ascii()) {
            const std::string_view token = nextToken();
            const auto [end, error] =
                std::from_chars(token.data(), token.data() + token.size(), count);
            if (error != std::errc() || end != token.data() + token.size())
                fail("a list's count " + quoted(token) + " is not a count");
        } else {
            // A count typed float can hold a fraction, or a value beyond any integer's range.
            const double value = decode(property.countType);
            if (!(value >= 0 && value == std::floor(value)))
                fail("a list's count " + numberText(value) + " is not a count");
            if (value > double(data_.size())) truncated();
            count = std::uint64_t(value);
        }
        const std::size_t itemBytes = ascii() ? 2 : bytesOf(property.type);
        if (count > (data_.size() - at_ + 1) / itemBytes) truncated();
        return count;
    }

    // A scalar as T (float or double): text is parsed straight to T, rounded once.
    template <class T>
    T readValue(const PlyProperty& property) {
        if (!ascii()) return T(decode(property.type));
        std::string_view token = nextToken();
        if (token.size() > 1 && token.front() == '+') token.remove_prefix(1);
        T value = 0;
        const char* const last = token.data() + token.size();
        std::from_chars_result result = std::from_chars(token.data(), last, value);
        if (result.ec == std::errc::result_out_of_range) {
            // Beyond float's range (a tiny normal's component written by a double's printf):
            // the double's value, rounded to T, is 0 or infinite as it should be.
            double wide = 0;
            result = std::from_chars(token.data(), last, wide);
            value = T(wide);
        }
        if (result.ec != std::errc() || result.ptr != last)
            fail(quoted(token) + " is not a number (the " + inQuotes(property.name) +
                 " property of a " + inQuotes(element_->name) + " element)");
        return value;
    }

    // A binary value of the given type, in the file's byte order.
    double decode(ScalarType type) {
        const std::size_t bytes = bytesOf(type);
        unsigned char raw[8] = {};
        advance(bytes);
        std::memcpy(raw, data_.data() + at_ - bytes, bytes);
        const bool bigEndian = header_.format == PlyFormat::BinaryBigEndian;
        if (bigEndian != (std::endian::native == std::endian::big)) std::reverse(raw, raw + bytes);
        const auto as = [&raw](auto value) {
            std::memcpy(&value, raw, sizeof value);
            return double(value);
        };
        switch (type) {
            case ScalarType::Int8:
                return as(std::int8_t{});
            case ScalarType::UInt8:
                return as(std::uint8_t{});
            case ScalarType::Int16:
                return as(std::int16_t{});
            case ScalarType::UInt16:
                return as(std::uint16_t{});
            case ScalarType::Int32:
                return as(std::int32_t{});
            case ScalarType::UInt32:
                return as(std::uint32_t{});
            case ScalarType::Float32:
                return as(float{});
            case ScalarType::Float64:
                return as(double{});
        }
        return 0;
    }

    void advance(std::size_t bytes) {
        if (data_.size() - at_ < bytes) truncated();
        at_ += bytes;
    }

    // The next whitespace-separated word of an ASCII body; none left is a truncated body.
    std::string_view nextToken() {
        const auto isSpace = [](char c) { return std::isspace(static_cast<unsigned char>(c)); };
        while (at_ < data_.size() && isSpace(data_[at_])) {
            if (data_[at_] == '\n') {
                ++line_;
                lineStart_ = at_ + 1;
            }
            ++at_;
        }
        tokenStart_ = at_;
        while (at_ < data_.size() && !isSpace(data_[at_]))
            ++at_;
        if (at_ == tokenStart_) truncated();
        return std::string_view(data_).substr(tokenStart_, at_ - tokenStart_);
    }

    // Of one element (never 0: it has properties): a value takes a digit and a separator in
    // ASCII; in binary its type's bytes, a list its count's.
    std::uint64_t minimumBytes(const PlyElement& element) const {
        std::uint64_t bytes = 0;
        for (const PlyProperty& property : element.properties)
            bytes += ascii()           ? 2
                     : property.isList ? bytesOf(property.countType)
                                       : bytesOf(property.type);
        return bytes;
    }

    bool ascii() const { return header_.format == PlyFormat::Ascii; }

    static std::string numberText(double value) {
        char text[32];
        std::snprintf(text, sizeof text, "%.17g", value);
        return text;
    }

    // An ASCII body's faults name the line and column of the word at fault.
    SourceLocation location() const {
        return ascii() ? SourceLocation{line_, int(tokenStart_ - lineStart_) + 1}
                       : SourceLocation{};
    }

    [[noreturn]] void fail(const std::string& message) const {
        throw InputError(path_.string(), location(), "not a valid PLY file: " + message);
    }

    [[noreturn]] void headerFault(const std::string& message) const {
        throw InputError(path_.string(), "not a valid PLY file: " + message);
    }

    // A word of the body in a message: quoted, cut short, its control characters as codes.
    static std::string quoted(std::string_view token) {
        std::string text;
        for (const char c : token.substr(0, 32)) {
            if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7F) {
                char code[8];
                std::snprintf(code, sizeof code, "\\x%02X", static_cast<unsigned char>(c));
                text += code;
            } else {
                text += c;
            }
        }
        return inQuotes(token.size() > 32 ? text + "..." : text);
    }

    [[noreturn]] void truncated() const {
        throw InputError(path_.string(),
                         "is truncated: its header declares " +
                             countOf(element_->count, inQuotes(element_->name) + " element") +
                             ", more than its body holds");
    }

    const fs::path& path_;
    const std::string& data_;
    const PlyHeader& header_;
    TriangleMesh& mesh_;
    PlyFaces faces_;
    const PlyElement* element_ = nullptr;  // being read
    bool hasNormals_ = false, hasUvs_ = false, hasColours_ = false;
    std::size_t at_;
    int line_;               // of the ASCII body's byte at_
    std::size_t lineStart_;  // and that line's first byte
    std::size_t tokenStart_ = 0;
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

// The faces, triangulated as the OBJ loader triangulates its faces (concave ones right), less
// zero-area triangles, into a mesh that holds the file's vertices.
class FaceTriangulator {
public:
    FaceTriangulator(const fs::path& path, TriangleMesh& mesh) : path_(path), mesh_(mesh) {}

    void add(const PlyFaces& faces) {
        const std::size_t vertexCount = mesh_.positions.size();
        mesh_.indices.reserve(3 * faces.ends.size());
        std::size_t begin = 0;
        for (std::size_t f = 0; f < faces.ends.size(); ++f) {
            const std::span<const std::uint32_t> face(faces.corners.data() + begin,
                                                      faces.ends[f] - begin);
            begin = faces.ends[f];
            for (const std::uint32_t index : face)
                if (index >= vertexCount)
                    throw InputError(path_.string(),
                                     "a face's vertex index is out of range: face " +
                                         std::to_string(f) + " names vertex " +
                                         std::to_string(index) + " of " +
                                         std::to_string(vertexCount) +
                                         (vertexCount == 1 ? " vertex" : " vertices"));
            if (face.size() < 3) {
                ++pointsAndLines_;
                continue;
            }
            corners_.clear();
            for (const std::uint32_t index : face)
                corners_.push_back(mesh_.positions[index]);
            if (!std::all_of(corners_.begin(), corners_.end(),
                             [](const Vec3& p) { return isFinite(p); })) {
                ++nonFinite_;
                continue;
            }
            addTriangles(face);
        }
    }

    void finish(std::vector<std::string>& warnings, bool hasColours) {
        if (hasColours)
            warn(warnings, path_, "vertex colours are not used; the object's material applies");
        if (pointsAndLines_ > 0)
            warn(warnings, path_,
                 countOf(pointsAndLines_, "face") +
                     " with fewer than 3 vertices (points, lines) ignored");
        if (nonFinite_ > 0)
            warn(warnings, path_,
                 countOf(nonFinite_, "face") + " with non-finite vertex coordinates dropped");
        if (zeroArea_ > 0)
            warn(warnings, path_, countOf(zeroArea_, "zero-area triangle") + " dropped");
        if (mesh_.triangleCount() == 0) throw InputError(path_.string(), "no faces to render");
    }

private:
    void addTriangles(std::span<const std::uint32_t> face) {
        zeroArea_ += triangulateLessZeroArea(corners_, triangles_);
        for (const PolygonTriangulator::CornerTriple& t : triangles_) {
            for (const std::size_t corner : t)
                mesh_.indices.push_back(face[corner]);
            mesh_.faceMaterials.push_back(0);
        }
    }

    const fs::path& path_;
    TriangleMesh& mesh_;
    std::size_t pointsAndLines_ = 0, nonFinite_ = 0, zeroArea_ = 0;
    std::vector<Vec3> corners_;                                 // of the face being added
    std::vector<PolygonTriangulator::CornerTriple> triangles_;  // and its triangles
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
    auto mesh = std::make_shared<TriangleMesh>();
    BodyReader body(path, data, header, *mesh);
    const PlyFaces faces = body.read();
    FaceTriangulator triangulator(path, *mesh);
    triangulator.add(faces);
    triangulator.finish(warnings, body.hasColours());
    mesh->materials.push_back(std::make_shared<BlinnPhongMaterial>());
    return mesh;
}

}  // namespace lancer
