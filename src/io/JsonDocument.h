#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <tuple>
#include <unordered_map>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene/InputError.h"

namespace lancer {

// A parsed JSON file (comments and trailing commas allowed) that remembers where each value and
// each object key stands in the text, so that errors found later can name the line and column.
// Values are addressed by JSON pointer ("/objects/2/radius"); the root is "".
class JsonDocument {
public:
    // The most arrays and objects that may be open at once: a scene needs a handful, and
    // deeper text is an attack on the parser rather than a scene.
    static constexpr std::size_t kMaxNesting = 256;

    // Throws InputError naming `fileName` and the position of a syntax error (in the words of
    // JsonSyntax::explain) or of the container nested deeper than kMaxNesting.
    static JsonDocument parse(const std::string& text, const std::string& fileName);

    const nlohmann::json& root() const { return root_; }
    const std::string& fileName() const { return fileName_; }

    // Where the value at `pointer` starts.
    SourceLocation valueLocation(const std::string& pointer) const;
    // Where the key of the object member at `pointer` starts (the value's place for an array
    // element or the root).
    SourceLocation keyLocation(const std::string& pointer) const;

    // `parent` + "/" + the escaped `key`.
    static std::string child(const std::string& parent, const std::string& key);
    static std::string child(const std::string& parent, std::size_t index);

private:
    struct Position {
        SourceLocation key;
        SourceLocation value;
    };
    // A value inside a container: the container's number, the value's token and its number.
    // The token is an array element's index, or an object member's key number with kKeyToken
    // set (so that "0" as a key and 0 as an index never meet).
    struct Member {
        std::uint32_t parent;
        std::uint32_t token;
        std::uint32_t value;

        bool operator<(const Member& o) const {
            return std::tie(parent, token, value) < std::tie(o.parent, o.token, o.value);
        }
    };
    static constexpr std::uint32_t kKeyToken = std::uint32_t{1} << 31;

    // The value a pointer names, by walking its tokens down from the root; none if unknown.
    const Position* find(const std::string& pointer) const;
    // The number of the value `token` (a pointer token) names in the container `parent`.
    bool findMember(std::uint32_t parent, const std::string& token, std::uint32_t& value) const;

    nlohmann::json root_;
    std::string fileName_;
    // Flat, so that memory grows with the number of values and not with their keys or nesting
    // (28 bytes a value): each value is numbered in the order it is parsed (the root is 0), its
    // positions at its number; the members, sorted by (parent, token, value) once parsed, are
    // searched by halving. Numbers fit 32 bits: a value takes a character, and the text is at
    // most InputFile::kMaxSceneBytes. Each distinct key is stored once (escaped as in a pointer).
    std::vector<Position> positions_;
    std::vector<Member> members_;
    std::unordered_map<std::string, std::uint32_t> keyNumbers_;

    friend class JsonPositionRecorder;
};

}  // namespace lancer
