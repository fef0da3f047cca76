#pragma once

#include <map>
#include <string>

#include <nlohmann/json.hpp>

#include "scene/InputError.h"

namespace lancer {

// A parsed JSON file (comments allowed) that remembers where each value and each object key
// stands in the text, so that errors found later can name the line and column.
// Values are addressed by JSON pointer ("/objects/2/radius"); the root is "".
class JsonDocument {
public:
    // Throws InputError naming `fileName` and the position of a syntax error.
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

    nlohmann::json root_;
    std::string fileName_;
    std::map<std::string, Position> positions_;

    friend class JsonPositionRecorder;
};

}  // namespace lancer
