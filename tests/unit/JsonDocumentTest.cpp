// JSON with comments, and the line and column of every value and key, for error messages.

#include <gtest/gtest.h>

#include <string>

#include "io/JsonDocument.h"
#include "scene/InputError.h"

namespace lancer {
namespace {

// Columns below are counted by hand from the text; both count from 1.
const char* const kDocument = R"({
  "a": 1,
  "b": [true, false, null],
  "c": {"d": "x\"y", "e": -2.5e3},
  // a comment before a member
  "f": /* inline */ [ {"g": 0} ]
})";

testing::AssertionResult isAt(const SourceLocation& location, int line, int column) {
    if (location.line == line && location.column == column) return testing::AssertionSuccess();
    return testing::AssertionFailure() << "at " << location.line << ":" << location.column
                                       << ", expected " << line << ":" << column;
}

TEST(JsonDocumentTest, ParsesValuesWithCommentsIgnored) {
    const JsonDocument doc = JsonDocument::parse(kDocument, "doc.json");
    EXPECT_EQ(doc.fileName(), "doc.json");
    EXPECT_EQ(doc.root()["a"], 1);
    EXPECT_EQ(doc.root()["b"][1], false);
    EXPECT_EQ(doc.root()["c"]["d"], "x\"y");
    EXPECT_EQ(doc.root()["c"]["e"], -2500.0);
    EXPECT_EQ(doc.root()["f"][0]["g"], 0);
}

TEST(JsonDocumentTest, LocatesTheRoot) {
    const JsonDocument doc = JsonDocument::parse(kDocument, "doc.json");
    EXPECT_TRUE(isAt(doc.valueLocation(""), 1, 1));
    EXPECT_TRUE(isAt(doc.keyLocation(""), 1, 1));
}

TEST(JsonDocumentTest, LocatesScalarValues) {
    const JsonDocument doc = JsonDocument::parse(kDocument, "doc.json");
    EXPECT_TRUE(isAt(doc.valueLocation("/a"), 2, 8));
    EXPECT_TRUE(isAt(doc.valueLocation("/b/0"), 3, 9));   // true
    EXPECT_TRUE(isAt(doc.valueLocation("/b/1"), 3, 15));  // false
    EXPECT_TRUE(isAt(doc.valueLocation("/b/2"), 3, 22));  // null
    EXPECT_TRUE(isAt(doc.valueLocation("/c/d"), 4, 14));  // the string's opening quote
    EXPECT_TRUE(isAt(doc.valueLocation("/c/e"), 4, 27));  // the number's sign
    EXPECT_TRUE(isAt(doc.valueLocation("/f/0/g"), 6, 29));
}

TEST(JsonDocumentTest, LocatesContainers) {
    const JsonDocument doc = JsonDocument::parse(kDocument, "doc.json");
    EXPECT_TRUE(isAt(doc.valueLocation("/b"), 3, 8));
    EXPECT_TRUE(isAt(doc.valueLocation("/c"), 4, 8));
    EXPECT_TRUE(isAt(doc.valueLocation("/f"), 6, 21));  // after the comments
    EXPECT_TRUE(isAt(doc.valueLocation("/f/0"), 6, 23));
}

TEST(JsonDocumentTest, LocatesKeys) {
    const JsonDocument doc = JsonDocument::parse(kDocument, "doc.json");
    EXPECT_TRUE(isAt(doc.keyLocation("/a"), 2, 3));
    EXPECT_TRUE(isAt(doc.keyLocation("/c"), 4, 3));
    EXPECT_TRUE(isAt(doc.keyLocation("/c/d"), 4, 9));
    EXPECT_TRUE(isAt(doc.keyLocation("/c/e"), 4, 22));  // after a string with an escaped quote
    EXPECT_TRUE(isAt(doc.keyLocation("/f"), 6, 3));     // after a comment line
    EXPECT_TRUE(isAt(doc.keyLocation("/f/0/g"), 6, 24));
    // An array element has no key: its value's place stands in.
    EXPECT_TRUE(isAt(doc.keyLocation("/b/1"), 3, 15));
}

TEST(JsonDocumentTest, UnknownPointerHasNoLocation) {
    const JsonDocument doc = JsonDocument::parse(kDocument, "doc.json");
    EXPECT_TRUE(isAt(doc.valueLocation("/nothing"), 0, 0));
    EXPECT_TRUE(isAt(doc.keyLocation("/b/7"), 0, 0));
}

TEST(JsonDocumentTest, LocatesNumbersWrittenWithoutSpaces) {
    const JsonDocument doc = JsonDocument::parse("[1,-20,3.5e-1,[0]]", "n.json");
    EXPECT_TRUE(isAt(doc.valueLocation("/0"), 1, 2));
    EXPECT_TRUE(isAt(doc.valueLocation("/1"), 1, 4));
    EXPECT_TRUE(isAt(doc.valueLocation("/2"), 1, 8));
    EXPECT_TRUE(isAt(doc.valueLocation("/3"), 1, 15));
    EXPECT_TRUE(isAt(doc.valueLocation("/3/0"), 1, 16));
}

TEST(JsonDocumentTest, LocatesValuesAfterCommentsOnEarlierLines) {
    const std::string text = "{\"radius\": // the size\n   /* still\n coming */ 2.5, \"x\": 1}";
    const JsonDocument doc = JsonDocument::parse(text, "c.json");
    EXPECT_TRUE(isAt(doc.keyLocation("/radius"), 1, 2));
    EXPECT_TRUE(isAt(doc.valueLocation("/radius"), 3, 12));
    EXPECT_TRUE(isAt(doc.keyLocation("/x"), 3, 17));
}

TEST(JsonDocumentTest, KeysWithEscapesAndPointerCharacters) {
    const std::string text = R"({"say \"hi\"": 1, "a/b": 2, "c~d": {"e\\": 3}})";
    const JsonDocument doc = JsonDocument::parse(text, "k.json");
    EXPECT_EQ(JsonDocument::child("", "say \"hi\""), "/say \"hi\"");
    EXPECT_EQ(JsonDocument::child("", "a/b"), "/a~1b");
    EXPECT_EQ(JsonDocument::child("/x", "c~d"), "/x/c~0d");
    EXPECT_EQ(JsonDocument::child("/list", std::size_t{3}), "/list/3");
    EXPECT_TRUE(isAt(doc.keyLocation(JsonDocument::child("", "say \"hi\"")), 1, 2));
    EXPECT_TRUE(isAt(doc.valueLocation(JsonDocument::child("", "say \"hi\"")), 1, 16));
    EXPECT_TRUE(isAt(doc.keyLocation("/a~1b"), 1, 19));
    EXPECT_TRUE(isAt(doc.keyLocation("/c~0d"), 1, 29));
    EXPECT_TRUE(isAt(doc.keyLocation("/c~0d/e\\"), 1, 37));
    EXPECT_TRUE(isAt(doc.valueLocation("/c~0d/e\\"), 1, 44));
}

// The message of the InputError that parsing `text` throws.
std::string parseError(const std::string& text) {
    try {
        JsonDocument::parse(text, "bad.json");
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no error)";
}

// Checks that the message starts with "bad.json:line:column: error: ".
testing::AssertionResult reportsAt(const std::string& message, int line, int column) {
    const std::string prefix =
        "bad.json:" + std::to_string(line) + ":" + std::to_string(column) + ": error: ";
    if (message.rfind(prefix, 0) == 0 && message.size() > prefix.size())
        return testing::AssertionSuccess();
    return testing::AssertionFailure()
           << "message \"" << message << "\" does not start with \"" << prefix << "\" and go on";
}

// A token in the wrong place is shown from its first character.
TEST(JsonDocumentTest, UnexpectedTokensAreShownFromTheirStart) {
    EXPECT_TRUE(reportsAt(parseError("[1,\n,]"), 2, 1));    // a comma too many
    EXPECT_TRUE(reportsAt(parseError("{\"a\" 1}"), 1, 6));  // missing colon
    EXPECT_TRUE(reportsAt(parseError("{\"a\" 123}"), 1, 6));
    EXPECT_TRUE(reportsAt(parseError("[1, 2\n  -3.5]"), 2, 3));         // missing comma
    EXPECT_TRUE(reportsAt(parseError("{\"a\": 1\n \"b\": 2}"), 2, 2));  // before a key
    EXPECT_TRUE(reportsAt(parseError("{\"a\": \"x\\\"y\" \"z\"}"), 1, 14));
    EXPECT_TRUE(reportsAt(parseError("[1 true]"), 1, 4));
    EXPECT_TRUE(reportsAt(parseError("[1e999]"), 1, 2));  // out of range
}

// Text that is not JSON is shown where the reading stopped.
TEST(JsonDocumentTest, UnreadableTextIsShownWhereReadingStopped) {
    EXPECT_TRUE(reportsAt(parseError("{\"a\": tru }"), 1, 10));
    EXPECT_TRUE(reportsAt(parseError("{} x"), 1, 4));  // text after the end
    EXPECT_TRUE(reportsAt(parseError("[\"bad \\q escape\"]"), 1, 8));
    EXPECT_TRUE(reportsAt(parseError("// only\n/* comments */"), 2, 14));
}

TEST(JsonDocumentTest, ErrorsAtTheEndOfTheTextPointAtItsLastCharacter) {
    EXPECT_TRUE(reportsAt(parseError("{\"a\": 1"), 1, 7));
    EXPECT_TRUE(reportsAt(parseError("{\"a\": \"abc"), 1, 10));
}

TEST(JsonDocumentTest, ErrorMessagesKeepOnlyTheirOwnPosition) {
    // nlohmann's "[json.exception.parse_error.101] parse error at line 1, column 8" is replaced
    // by the position in front (an error JsonSyntax leaves in the parser's words).
    const std::string message = parseError("[\"bad \\q escape\"]");
    EXPECT_EQ(message.find("json.exception"), std::string::npos) << message;
    EXPECT_EQ(message.find("line 1"), std::string::npos) << message;
}

TEST(JsonDocumentTest, NumbersOutOfRangeAreReportedWithoutNlohmannsPrefix) {
    // nlohmann's "[json.exception.out_of_range.406] number overflow parsing '1e999'".
    EXPECT_EQ(parseError("[1e999]"), "bad.json:1:2: error: number overflow parsing '1e999'");
}

TEST(JsonDocumentTest, NestingUpToTheLimitIsRead) {
    const std::size_t depth = JsonDocument::kMaxNesting;
    const JsonDocument doc =
        JsonDocument::parse(std::string(depth, '[') + std::string(depth, ']'), "deep.json");
    // The innermost array is element 0 of element 0 ... of the root.
    std::string pointer;
    for (std::size_t i = 1; i < depth; ++i)
        pointer = JsonDocument::child(pointer, std::size_t{0});
    EXPECT_TRUE(isAt(doc.valueLocation(pointer), 1, static_cast<int>(depth)));
}

TEST(JsonDocumentTest, NestingBeyondTheLimitIsAnErrorAtTheFirstContainerTooMany) {
    // Unclosed: reading to the end would report the end of the text instead. Without the limit,
    // memory for positions grew with the square of the depth (8 GB for 200 KB).
    const std::string message = parseError(std::string(2000, '['));
    EXPECT_TRUE(reportsAt(message, 1, static_cast<int>(JsonDocument::kMaxNesting) + 1));
    EXPECT_NE(message.find("nested more than 256 deep"), std::string::npos) << message;
}

TEST(JsonDocumentTest, PositionsOfManyValuesDeepDown) {
    // Siblings deep in the tree each find their own place.
    std::string text(100, '[');
    text += "1, 2, 3";
    text += std::string(100, ']');
    const JsonDocument doc = JsonDocument::parse(text, "wide.json");
    std::string pointer;
    for (int i = 1; i < 100; ++i)
        pointer = JsonDocument::child(pointer, std::size_t{0});
    EXPECT_TRUE(isAt(doc.valueLocation(JsonDocument::child(pointer, std::size_t{0})), 1, 101));
    EXPECT_TRUE(isAt(doc.valueLocation(JsonDocument::child(pointer, std::size_t{2})), 1, 107));
    EXPECT_TRUE(isAt(doc.valueLocation(JsonDocument::child(pointer, std::size_t{3})), 0, 0));
}

// A key given twice: nlohmann keeps the last value, and its place is the one reported.
TEST(JsonDocumentTest, OfAKeyGivenTwiceTheLastIsLocated) {
    const JsonDocument doc = JsonDocument::parse(R"({"a": 1, "b": 2, "a": [3]})", "twice.json");
    EXPECT_EQ(doc.root()["a"], nlohmann::json::array({3}));
    EXPECT_TRUE(isAt(doc.keyLocation("/a"), 1, 18));
    EXPECT_TRUE(isAt(doc.valueLocation("/a"), 1, 23));
    EXPECT_TRUE(isAt(doc.valueLocation("/a/0"), 1, 24));
}

// Keys that read as numbers are keys, indices are written in decimal without leading zeros, and
// a key of one object is not found in another.
TEST(JsonDocumentTest, KeysAndIndicesDoNotMeet) {
    const JsonDocument doc =
        JsonDocument::parse(R"({"0": [5, 6], "1": {"0": 7}, "x": {"y": 8}})", "n.json");
    EXPECT_TRUE(isAt(doc.valueLocation("/0"), 1, 7));
    EXPECT_TRUE(isAt(doc.valueLocation("/0/1"), 1, 11));
    EXPECT_TRUE(isAt(doc.valueLocation("/1/0"), 1, 26));
    EXPECT_TRUE(isAt(doc.valueLocation("/0/01"), 0, 0));
    EXPECT_TRUE(isAt(doc.valueLocation("/0/-1"), 0, 0));
    EXPECT_TRUE(isAt(doc.valueLocation("/0/4294967297"), 0, 0));
    EXPECT_TRUE(isAt(doc.valueLocation("/2"), 0, 0));
    EXPECT_TRUE(isAt(doc.valueLocation("/y"), 0, 0));
    EXPECT_TRUE(isAt(doc.valueLocation("/1/y"), 0, 0));
}

// A scene of many objects: each of 100,000 elements (on lines of their own) finds its line, and
// the members of the last one their columns.
TEST(JsonDocumentTest, LocatesEveryElementOfALongArray) {
    constexpr std::size_t kCount = 100000;
    std::string text = "[\n";
    for (std::size_t i = 0; i < kCount; ++i)
        text += R"({"type": "sphere", "radius": )" + std::to_string(i) + "},\n";
    text += "{}]";
    const JsonDocument doc = JsonDocument::parse(text, "many.json");
    for (std::size_t i = 0; i < kCount; i += 997)
        ASSERT_TRUE(isAt(doc.valueLocation(JsonDocument::child("", i)), static_cast<int>(i) + 2, 1))
            << i;
    const std::string last = JsonDocument::child("", kCount - 1);
    EXPECT_TRUE(isAt(doc.keyLocation(JsonDocument::child(last, "radius")), kCount + 1, 20));
    EXPECT_TRUE(isAt(doc.valueLocation(JsonDocument::child(last, "radius")), kCount + 1, 30));
    EXPECT_TRUE(isAt(doc.valueLocation(JsonDocument::child("", kCount)), kCount + 2, 1));
}

TEST(JsonDocumentTest, EmptyTextIsAnError) {
    EXPECT_TRUE(reportsAt(parseError(""), 1, 1));
}

}  // namespace
}  // namespace lancer
