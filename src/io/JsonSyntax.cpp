#include "io/JsonSyntax.h"

#include <algorithm>
#include <cctype>
#include <vector>

namespace lancer {

namespace {

// A character of the text that is neither space nor comment; a string is one token, at its
// opening quote.
struct Token {
    std::size_t offset;
    char first;
};

// The tokens that start before `end`.
std::vector<Token> tokensBefore(const std::string& text, std::size_t end) {
    std::vector<Token> tokens;
    end = std::min(end, text.size());
    for (std::size_t i = 0; i < end; ++i) {
        const char c = text[i];
        if (std::isspace(static_cast<unsigned char>(c))) continue;
        if (c == '/' && i + 1 < text.size() && text[i + 1] == '/') {
            i = std::min(text.find('\n', i), text.size());
            continue;
        }
        if (c == '/' && i + 1 < text.size() && text[i + 1] == '*') {
            i = std::min(text.find("*/", i + 2), text.size()) + 1;
            continue;
        }
        tokens.push_back({i, c});
        if (c != '"') continue;
        for (++i; i < text.size() && text[i] != '"' && text[i] != '\n'; ++i)
            if (text[i] == '\\') ++i;
    }
    return tokens;
}

int lineOf(const std::string& text, std::size_t offset) {
    const auto end = text.begin() + static_cast<long>(std::min(offset, text.size()));
    return static_cast<int>(std::count(text.begin(), end, '\n')) + 1;
}

bool contains(const std::string& message, const char* fragment) {
    return message.find(fragment) != std::string::npos;
}

bool startsWord(char c) {
    return std::isalpha(static_cast<unsigned char>(c)) != 0 || c == '_';
}

std::string wordAt(const std::string& text, std::size_t offset) {
    std::size_t end = offset;
    while (end < text.size() &&
           (std::isalnum(static_cast<unsigned char>(text[end])) != 0 || text[end] == '_'))
        ++end;
    return text.substr(offset, end - offset);
}

char closingOf(char opening) {
    return opening == '[' ? ']' : '}';
}

std::string quoted(char c) {
    return std::string("'") + c + "'";
}

}  // namespace

std::string JsonSyntax::withoutTrailingCommas(std::string text) {
    const std::vector<Token> tokens = tokensBefore(text, text.size());
    for (std::size_t i = 2; i < tokens.size(); ++i) {
        const bool closes = tokens[i].first == ']' || tokens[i].first == '}';
        // "[,]" and "[1,,]" stay errors: the comma must follow a value.
        const char before = tokens[i - 2].first;
        const bool afterValue = before != '[' && before != '{' && before != ',' && before != ':';
        if (closes && tokens[i - 1].first == ',' && afterValue) text[tokens[i - 1].offset] = ' ';
    }
    return text;
}

std::string JsonSyntax::explain(const std::string& text, std::size_t offset,
                                const std::string& parserMessage,
                                const std::optional<OpenContainer>& innermostOpen) {
    const std::vector<Token> before = tokensBefore(text, offset);
    const char here = offset < text.size() ? text[offset] : '\0';
    const std::string previousLine =
        before.empty() ? std::string("1") : std::to_string(lineOf(text, before.back().offset));
    const bool atEnd = contains(parserMessage, "unexpected end of input");

    if (contains(parserMessage, "missing closing quote") ||
        contains(parserMessage, "U+000A (LF) must be escaped"))
        return "missing '\"' at the end of the text that starts on line " + previousLine + "?";
    if (atEnd && innermostOpen)
        return "missing " + quoted(closingOf(innermostOpen->opening)) + " to close the " +
               quoted(innermostOpen->opening) + " on line " + std::to_string(innermostOpen->line) +
               "? (the file ends before it is closed)";
    if (here == '\'') return "JSON text goes in double quotes (\"...\"), not single quotes";
    if (contains(parserMessage, "object key") && startsWord(here))
        return "keys go in double quotes: \"" + wordAt(text, offset) + "\" instead of " +
               wordAt(text, offset);
    if (contains(parserMessage, "unexpected ','"))
        return "a comma with no value before it: one comma too many?";
    if (contains(parserMessage, "; expected end of input"))
        return "text after the end of the scene, whose outer brackets closed on line " +
               previousLine + ": a bracket too many, or text outside them?";
    if (contains(parserMessage, "; expected '}'") || contains(parserMessage, "; expected ']'")) {
        if ((here == ']' || here == '}') && innermostOpen)
            return quoted(here) + " cannot close the " + quoted(innermostOpen->opening) +
                   " on line " + std::to_string(innermostOpen->line) + ": missing " +
                   quoted(closingOf(innermostOpen->opening)) + "?";
        return "missing comma after the value on line " + previousLine + "?";
    }
    if (contains(parserMessage, "; expected ':'"))
        return "missing ':' after the key on line " + previousLine + "?";
    if (contains(parserMessage, "expected '[', '{', or a literal") && !before.empty() &&
        before.back().first == ':')
        return "missing value after the ':' on line " + previousLine + "?";
    if (contains(parserMessage, "invalid literal") && startsWord(here)) {
        const std::string word = wordAt(text, offset);
        return "unknown word " + word + ": text goes in double quotes (\"" + word +
               "\"), and true, false and null are the only words without them";
    }
    return parserMessage;
}

}  // namespace lancer
