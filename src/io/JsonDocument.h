#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "scene/InputError.h"

namespace lancer {

// A parsed JSON file (comments allowed) that remembers where each value and each object key
// stands in the text, so that errors found later can name the line and column.
// Values are addressed by JSON pointer ("/objects/2/radius"); the root is "".
class JsonDocument {
public:
    // The most arrays and objects that may be open at once: a scene needs a handful, and
    // deeper text is an attack on the parser rather than a scene.
    static constexpr std::size_t kMaxNesting = 256;

    // Throws InputError naming `fileName` and the position of a syntax error or of the container
    // nested deeper than kMaxNesting.
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

    // The value a pointer names, by walking its tokens down from the root; none if unknown.
    const Position* find(const std::string& pointer) const;

    nlohmann::json root_;
    std::string fileName_;
    // The positions as a tree, so that memory grows with the text and not with its nesting: each
    // value is numbered (the root is 0) and found from its parent's number and its escaped
    // pointer token (a key, or an array index in decimal).
    std::vector<Position> positions_;
    std::map<std::pair<std::size_t, std::string>, std::size_t> children_;

    friend class JsonPositionRecorder;
};

}  // namespace lancer
