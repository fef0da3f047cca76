#include "io/JsonDocument.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstring>
#include <iterator>
#include <limits>
#include <optional>
#include <vector>

#include "io/InputFile.h"
#include "io/JsonSyntax.h"

namespace lancer {

namespace {

// A character iterator that remembers the offset of the last character read through it. The
// JSON lexer reads through it, so when the parser reports a value, the reader is just past that
// value's last character (or on the character after a number, which the lexer reads ahead).
class TrackingIterator {
public:
    using iterator_category = std::input_iterator_tag;
    using value_type = char;
    using difference_type = std::ptrdiff_t;
    using pointer = const char*;
    using reference = const char&;

    TrackingIterator(const char* begin, const char* p, std::size_t* lastRead)
        : begin_(begin), p_(p), lastRead_(lastRead) {}

    const char& operator*() const {
        *lastRead_ = static_cast<std::size_t>(p_ - begin_);
        return *p_;
    }
    TrackingIterator& operator++() {
        ++p_;
        return *this;
    }
    TrackingIterator operator++(int) {
        TrackingIterator old = *this;
        ++p_;
        return old;
    }
    bool operator==(const TrackingIterator& o) const { return p_ == o.p_; }
    bool operator!=(const TrackingIterator& o) const { return p_ != o.p_; }

private:
    const char* begin_;
    const char* p_;
    std::size_t* lastRead_;
};

std::string escapePointerToken(const std::string& key) {
    std::string out;
    for (char c : key) {
        if (c == '~')
            out += "~0";
        else if (c == '/')
            out += "~1";
        else
            out += c;
    }
    return out;
}

}  // namespace

std::string JsonDocument::child(const std::string& parent, const std::string& key) {
    return parent + "/" + escapePointerToken(key);
}

std::string JsonDocument::child(const std::string& parent, std::size_t index) {
    return parent + "/" + std::to_string(index);
}

// SAX handler for nlohmann::json that builds no tree, only the positions of the values and keys.
class JsonPositionRecorder {
public:
    using json = nlohmann::json;
    using number_integer_t = json::number_integer_t;
    using number_unsigned_t = json::number_unsigned_t;
    using number_float_t = json::number_float_t;
    using string_t = json::string_t;
    using binary_t = json::binary_t;

    JsonPositionRecorder(const std::string& text, const std::size_t& lastRead, JsonDocument& doc)
        : text_(text), lastRead_(lastRead), doc_(doc) {}

    // Line and column (from 1) of the byte at `offset`. The parser reports values in the order
    // of the text, so the lines are counted once as it goes, with no table of them (an error's
    // place, which may lie behind, is counted again from the start).
    SourceLocation locate(std::size_t offset) {
        if (offset < counted_) {
            counted_ = lineStart_ = 0;
            line_ = 1;
        }
        for (; counted_ < offset; ++counted_)
            if (text_[counted_] == '\n') {
                ++line_;
                lineStart_ = counted_ + 1;
            }
        return {line_, static_cast<int>(offset - lineStart_) + 1};
    }

    bool null() { return scalar(lastRead_ + 1 - 4); }
    bool boolean(bool v) { return scalar(lastRead_ + 1 - (v ? 4 : 5)); }
    bool number_integer(number_integer_t) { return number(); }
    bool number_unsigned(number_unsigned_t) { return number(); }
    bool number_float(number_float_t, const string_t&) { return number(); }
    bool string(string_t&) { return scalar(openingQuote(lastRead_)); }
    bool binary(binary_t&) { return true; }
    bool start_object(std::size_t) { return open(false); }
    bool start_array(std::size_t) { return open(true); }
    bool end_object() { return close(); }
    bool end_array() { return close(); }
    bool key(string_t& k) {
        Container& c = stack_.back();
        c.memberValue = newMember(c.id, keyToken(escapePointerToken(k)));
        doc_.positions_[c.memberValue].key = locate(openingQuote(lastRead_));
        return true;
    }
    bool parse_error(std::size_t position, const std::string&,
                     const nlohmann::detail::exception& e) {
        errorOffset = errorPlace(position);
        errorMessage = JsonSyntax::explain(text_, errorOffset, withoutNlohmannPrefix(e.what()),
                                           innermostOpen());
        return false;
    }

    std::string errorMessage;
    std::size_t errorOffset = 0;

private:
    struct Container {
        std::uint32_t id;  // the container's number in the document's positions
        bool isArray;
        std::uint32_t nextIndex = 0;
        std::uint32_t memberValue = 0;  // an object's: the number of the member whose key was read
    };

    std::optional<JsonSyntax::OpenContainer> innermostOpen() const {
        if (stack_.empty()) return std::nullopt;
        const Container& c = stack_.back();
        return JsonSyntax::OpenContainer{c.isArray ? '[' : '{', doc_.positions_[c.id].value.line};
    }

    // nlohmann's messages read "[json.exception.parse_error.101] parse error at line L, column C:
    // what" or "[json.exception.out_of_range.406] what": keep only "what", the position is given
    // in our own format.
    static std::string withoutNlohmannPrefix(std::string message) {
        const std::size_t column = message.find("column");
        if (column != std::string::npos) {
            const std::size_t colon = message.find(": ", column);
            if (colon != std::string::npos) return message.substr(colon + 2);
        }
        const std::size_t bracket = message.find("] ");
        if (message.rfind("[json.exception.", 0) == 0 && bracket != std::string::npos)
            return message.substr(bracket + 2);
        return message;
    }

    // Where a syntax error is shown. `position` counts the characters the lexer consumed; the
    // last of them ends either a token the parser did not expect, shown from its first
    // character, or the text the lexer could not read, shown where it stopped. Past the end of
    // the text (which counts one more), its last character stands in.
    std::size_t errorPlace(std::size_t position) const {
        if (text_.empty()) return 0;
        if (position == 0 || position > text_.size()) return text_.size() - 1;
        const std::size_t last = position - 1;
        if (text_[last] == '"') return openingQuote(last);
        const bool inWord = std::isalpha(static_cast<unsigned char>(text_[last])) != 0;
        const char* tokenCharacters =
            inWord ? "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ" : "0123456789+-.eE";
        if (!inWord && !std::isdigit(static_cast<unsigned char>(text_[last]))) return last;
        std::size_t start = last;
        while (start > 0 && std::strchr(tokenCharacters, text_[start - 1]) != nullptr)
            --start;
        return start;
    }

    // A string ends with the quote at `closingQuote`: find its unescaped opening quote.
    std::size_t openingQuote(std::size_t closingQuote) const {
        std::size_t i = closingQuote;
        while (i > 0) {
            --i;
            if (text_[i] != '"') continue;
            std::size_t backslashes = 0;
            while (i > backslashes && text_[i - 1 - backslashes] == '\\')
                ++backslashes;
            if (backslashes % 2 == 0) return i;
        }
        return 0;
    }

    // The lexer has read one character past the number: walk back over the number's characters.
    bool number() {
        std::size_t i = lastRead_;
        while (i > 0 && std::strchr("0123456789+-.eE", text_[i - 1]) != nullptr)
            --i;
        return scalar(i);
    }

    // The token of an escaped key, numbering the key if it is new.
    std::uint32_t keyToken(std::string escapedKey) {
        const auto [it, added] = doc_.keyNumbers_.try_emplace(
            std::move(escapedKey), static_cast<std::uint32_t>(doc_.keyNumbers_.size()));
        return it->second | JsonDocument::kKeyToken;
    }

    // Numbers a new value, the member `token` of the container numbered `parent`.
    std::uint32_t newMember(std::uint32_t parent, std::uint32_t token) {
        const auto value = static_cast<std::uint32_t>(doc_.positions_.size());
        doc_.positions_.emplace_back();
        doc_.members_.push_back({parent, token, value});
        return value;
    }

    // The number of the value the parser reports next.
    std::uint32_t nextValue() {
        if (stack_.empty()) {
            if (doc_.positions_.empty()) doc_.positions_.emplace_back();
            return 0;
        }
        Container& c = stack_.back();
        return c.isArray ? newMember(c.id, c.nextIndex++) : c.memberValue;
    }

    bool scalar(std::size_t startOffset) {
        doc_.positions_[nextValue()].value = locate(startOffset);
        return true;
    }

    bool open(bool isArray) {
        if (stack_.size() >= JsonDocument::kMaxNesting) {
            errorMessage = "arrays and objects are nested more than " +
                           std::to_string(JsonDocument::kMaxNesting) + " deep";
            errorOffset = lastRead_;
            return false;
        }
        const std::uint32_t id = nextValue();
        doc_.positions_[id].value = locate(lastRead_);
        stack_.push_back({id, isArray});
        return true;
    }

    bool close() {
        stack_.pop_back();
        return true;
    }

    const std::string& text_;
    const std::size_t& lastRead_;
    JsonDocument& doc_;
    std::vector<Container> stack_;
    std::size_t counted_ = 0;  // the characters before it are counted in line_ and lineStart_
    int line_ = 1;
    std::size_t lineStart_ = 0;
};

JsonDocument JsonDocument::parse(const std::string& original, const std::string& fileName) {
    // The value numbers are 32-bit (see positions_).
    if (original.size() > InputFile::kMaxSceneBytes)
        throw InputFile::tooLarge(fileName, "scene files", InputFile::kMaxSceneBytes);
    const std::string text = JsonSyntax::withoutTrailingCommas(original);
    JsonDocument doc;
    doc.fileName_ = fileName;
    std::size_t lastRead = 0;
    JsonPositionRecorder recorder(text, lastRead, doc);
    const char* begin = text.data();
    const bool ok =
        nlohmann::json::sax_parse(TrackingIterator(begin, begin, &lastRead),
                                  TrackingIterator(begin, begin + text.size(), &lastRead),
                                  &recorder, nlohmann::json::input_format_t::json,
                                  /*strict=*/true, /*ignore_comments=*/true);
    if (!ok)
        throw InputError(fileName, recorder.locate(recorder.errorOffset), recorder.errorMessage);
    // By value too, so that of a key given twice the last is found (as nlohmann keeps the last).
    std::sort(doc.members_.begin(), doc.members_.end());
    doc.root_ =
        nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/true, /*ignore_comments=*/true);
    return doc;
}

bool JsonDocument::findMember(std::uint32_t parent, const std::string& token,
                              std::uint32_t& value) const {
    const auto search = [&](std::uint32_t memberToken) {
        const Member last{parent, memberToken, std::numeric_limits<std::uint32_t>::max()};
        const auto after = std::upper_bound(members_.begin(), members_.end(), last);
        if (after == members_.begin()) return false;
        const Member& found = *std::prev(after);
        if (found.parent != parent || found.token != memberToken) return false;
        value = found.value;
        return true;
    };
    if (const auto key = keyNumbers_.find(token);
        key != keyNumbers_.end() && search(key->second | kKeyToken))
        return true;
    // An array index, written in decimal without leading zeros.
    std::uint32_t index = 0;
    const auto [end, error] = std::from_chars(token.data(), token.data() + token.size(), index);
    return error == std::errc{} && end == token.data() + token.size() && index < kKeyToken &&
           token == std::to_string(index) && search(index);
}

const JsonDocument::Position* JsonDocument::find(const std::string& pointer) const {
    if (positions_.empty()) return nullptr;
    std::uint32_t id = 0;
    // Each token follows a '/'; the root's pointer is "".
    for (std::size_t start = 0; start < pointer.size();) {
        const std::size_t end = std::min(pointer.find('/', start + 1), pointer.size());
        if (!findMember(id, pointer.substr(start + 1, end - start - 1), id)) return nullptr;
        start = end;
    }
    return &positions_[id];
}

SourceLocation JsonDocument::valueLocation(const std::string& pointer) const {
    const Position* position = find(pointer);
    return position ? position->value : SourceLocation{};
}

SourceLocation JsonDocument::keyLocation(const std::string& pointer) const {
    const Position* position = find(pointer);
    if (!position) return {};
    return position->key.line > 0 ? position->key : position->value;
}

}  // namespace lancer
