#include "io/JsonDocument.h"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <iterator>
#include <vector>

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

// SAX handler for nlohmann::json that builds no tree, only the map from JSON pointer to position.
class JsonPositionRecorder {
public:
    using json = nlohmann::json;
    using number_integer_t = json::number_integer_t;
    using number_unsigned_t = json::number_unsigned_t;
    using number_float_t = json::number_float_t;
    using string_t = json::string_t;
    using binary_t = json::binary_t;

    JsonPositionRecorder(const std::string& text, const std::size_t& lastRead, JsonDocument& doc)
        : text_(text), lastRead_(lastRead), doc_(doc) {
        lineStarts_.push_back(0);
        for (std::size_t i = 0; i < text.size(); ++i)
            if (text[i] == '\n') lineStarts_.push_back(i + 1);
    }

    // Line and column (from 1) of the byte at `offset`.
    SourceLocation locate(std::size_t offset) const {
        const auto line = std::upper_bound(lineStarts_.begin(), lineStarts_.end(), offset) - 1;
        return {static_cast<int>(line - lineStarts_.begin()) + 1,
                static_cast<int>(offset - *line) + 1};
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
        c.pendingKey = escapePointerToken(k);
        doc_.positions_[childOf(c.id, c.pendingKey)].key = locate(openingQuote(lastRead_));
        return true;
    }
    bool parse_error(std::size_t position, const std::string&,
                     const nlohmann::detail::exception& e) {
        errorMessage = withoutNlohmannPrefix(e.what());
        errorOffset = errorPlace(position);
        return false;
    }

    std::string errorMessage;
    std::size_t errorOffset = 0;

private:
    struct Container {
        std::size_t id;  // the container's number in the document's positions
        bool isArray;
        std::size_t nextIndex = 0;
        std::string pendingKey;  // escaped
    };

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

    // The number of the value named `token` in the container numbered `parent`, made if new.
    std::size_t childOf(std::size_t parent, const std::string& token) {
        const auto [it, added] =
            doc_.children_.try_emplace({parent, token}, doc_.positions_.size());
        if (added) doc_.positions_.emplace_back();
        return it->second;
    }

    // The number of the value the parser reports next.
    std::size_t nextValue() {
        if (stack_.empty()) {
            if (doc_.positions_.empty()) doc_.positions_.emplace_back();
            return 0;
        }
        Container& c = stack_.back();
        return childOf(c.id, c.isArray ? std::to_string(c.nextIndex++) : c.pendingKey);
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
        const std::size_t id = nextValue();
        doc_.positions_[id].value = locate(lastRead_);
        stack_.push_back({id, isArray, 0, {}});
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
    std::vector<std::size_t> lineStarts_;
};

JsonDocument JsonDocument::parse(const std::string& text, const std::string& fileName) {
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
    doc.root_ =
        nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/true, /*ignore_comments=*/true);
    return doc;
}

const JsonDocument::Position* JsonDocument::find(const std::string& pointer) const {
    if (positions_.empty()) return nullptr;
    std::size_t id = 0;
    // Each token follows a '/'; the root's pointer is "".
    for (std::size_t start = 0; start < pointer.size();) {
        const std::size_t end = std::min(pointer.find('/', start + 1), pointer.size());
        const auto it = children_.find({id, pointer.substr(start + 1, end - start - 1)});
        if (it == children_.end()) return nullptr;
        id = it->second;
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
