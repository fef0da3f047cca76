#pragma once

#include <cstddef>
#include <optional>
#include <string>

namespace lancer {

// The leniency and the plain words the scene reader adds to JSON with comments: commas before a
// closing bracket are accepted, and a syntax error is told as the mistake that most likely
// caused it rather than as the parser's state.
class JsonSyntax {
public:
    // The innermost array or object still open where the error was found.
    struct OpenContainer {
        char opening;  // '[' or '{'
        int line;
    };

    // `text` with each comma that ends an array or an object (after a value, before its ']' or
    // '}') replaced by a space, so that every other character keeps its line and column.
    static std::string withoutTrailingCommas(std::string text);

    // The message for a syntax error shown at `offset` of `text`, of which the parser said
    // `parserMessage` (without its prefix); the parser's words when no explanation fits.
    static std::string explain(const std::string& text, std::size_t offset,
                               const std::string& parserMessage,
                               const std::optional<OpenContainer>& innermostOpen);
};

}  // namespace lancer
