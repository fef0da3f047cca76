// Trailing commas are accepted, and syntax errors are told as the mistake a newcomer made.

#include <gtest/gtest.h>

#include <string>

#include "io/JsonDocument.h"
#include "io/JsonSyntax.h"
#include "scene/InputError.h"

namespace lancer {
namespace {

std::string parseError(const std::string& text) {
    try {
        JsonDocument::parse(text, "scene.json");
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no error)";
}

TEST(JsonSyntaxTest, BlanksOnlyTheCommasBeforeAClosingBracket) {
    EXPECT_EQ(JsonSyntax::withoutTrailingCommas("[1, 2,]"), "[1, 2 ]");
    EXPECT_EQ(JsonSyntax::withoutTrailingCommas("{\"a\": [1,\n],\n}"), "{\"a\": [1 \n] \n}");
    // Between the comma and the bracket, comments and spaces.
    EXPECT_EQ(JsonSyntax::withoutTrailingCommas("[1, // one\n /* x */ ]"),
              "[1  // one\n /* x */ ]");
    // Inside strings and comments, nothing.
    EXPECT_EQ(JsonSyntax::withoutTrailingCommas("[\"a,]\", \"\\\",]\"]"), "[\"a,]\", \"\\\",]\"]");
    EXPECT_EQ(JsonSyntax::withoutTrailingCommas("[1 /* ,] */]"), "[1 /* ,] */]");
    // A comma that follows no value stays, and stays an error.
    EXPECT_EQ(JsonSyntax::withoutTrailingCommas("[,]"), "[,]");
    EXPECT_EQ(JsonSyntax::withoutTrailingCommas("{,}"), "{,}");
    EXPECT_EQ(JsonSyntax::withoutTrailingCommas("[1,,]"), "[1,,]");
    EXPECT_EQ(JsonSyntax::withoutTrailingCommas("{\"a\":,}"), "{\"a\":,}");
}

TEST(JsonSyntaxTest, DocumentsWithTrailingCommasAreReadWithTheirPositions) {
    const JsonDocument doc =
        JsonDocument::parse("{\n  \"a\": [1, 2,],\n  \"b\": {\"c\": true,},\n}", "scene.json");
    EXPECT_EQ(doc.root()["a"].size(), 2u);
    EXPECT_EQ(doc.root()["b"]["c"], true);
    EXPECT_EQ(doc.valueLocation("/b/c").line, 3);
    EXPECT_EQ(doc.valueLocation("/b/c").column, 14);
    EXPECT_EQ(parseError("[1, 2,,]"),
              "scene.json:1:7: error: a comma with no value before it: "
              "one comma too many?");
    EXPECT_EQ(parseError("[,]"),
              "scene.json:1:2: error: a comma with no value before it: "
              "one comma too many?");
}

TEST(JsonSyntaxTest, MissingCommaNamesTheLineOfTheValueBefore) {
    EXPECT_EQ(parseError("{\n  \"a\": 1\n  \"b\": 2\n}"),
              "scene.json:3:3: error: missing comma after the value on line 2?");
    EXPECT_EQ(parseError("[1 2]"),
              "scene.json:1:4: error: missing comma after the value on line 1?");
    EXPECT_EQ(parseError("[\n  {\"a\": 1}\n  // a comment\n  {\"b\": 2}\n]"),
              "scene.json:4:3: error: missing comma after the value on line 2?");
    EXPECT_EQ(parseError("{\"a\": \"x,y\" \"b\": 2}"),
              "scene.json:1:13: error: missing comma after the value on line 1?");
}

TEST(JsonSyntaxTest, MissingClosingBracketNamesTheOpeningOne) {
    EXPECT_EQ(parseError("{\n  \"a\": [1, 2\n"),
              "scene.json:2:13: error: missing ']' to close the '[' on line 2? (the file ends "
              "before it is closed)");
    EXPECT_EQ(parseError("{\n  \"a\": {\"b\": 1}\n"),
              "scene.json:2:16: error: missing '}' to close the '{' on line 1? (the file ends "
              "before it is closed)");
    EXPECT_EQ(parseError("{\n  \"a\": [1, 2\n}"),
              "scene.json:3:1: error: '}' cannot close the '[' on line 2: missing ']'?");
}

TEST(JsonSyntaxTest, UnquotedKeysAndSingleQuotes) {
    EXPECT_EQ(parseError("{\"a\": 1, radius: 2}"),
              "scene.json:1:10: error: keys go in double quotes: \"radius\" instead of radius");
    EXPECT_EQ(
        parseError("{'radius': 2}"),
        "scene.json:1:2: error: JSON text goes in double quotes (\"...\"), not single quotes");
    EXPECT_EQ(
        parseError("{\"type\": 'sphere'}"),
        "scene.json:1:10: error: JSON text goes in double quotes (\"...\"), not single quotes");
    EXPECT_EQ(parseError("{\"type\": sphere}"),
              "scene.json:1:10: error: unknown word sphere: text goes in double quotes "
              "(\"sphere\"), and true, false and null are the only words without them");
}

TEST(JsonSyntaxTest, StrayTextAndMissingParts) {
    EXPECT_EQ(parseError("{\n  \"a\": 1\n}\n}"),
              "scene.json:4:1: error: text after the end of the scene, whose outer brackets "
              "closed on line 3: a bracket too many, or text outside them?");
    EXPECT_EQ(parseError("{\"a\": 1} x"),
              "scene.json:1:10: error: text after the end of the scene, whose outer brackets "
              "closed on line 1: a bracket too many, or text outside them?");
    EXPECT_EQ(parseError("{\"a\" 1}"),
              "scene.json:1:6: error: missing ':' after the key on line 1?");
    EXPECT_EQ(parseError("{\"a\": }"),
              "scene.json:1:7: error: missing value after the ':' on line 1?");
    EXPECT_EQ(parseError("{\n\"a\": \"abc\n}"),
              "scene.json:2:10: error: missing '\"' at the end of the text that starts on line 2?");
}

TEST(JsonSyntaxTest, OtherErrorsKeepTheParsersWords) {
    EXPECT_EQ(parseError("[1e999]"), "scene.json:1:2: error: number overflow parsing '1e999'");
    EXPECT_EQ(parseError("[\"bad \\q escape\"]"),
              "scene.json:1:8: error: syntax error while parsing value - invalid string: "
              "forbidden character after backslash; last read: '\"bad \\q'");
}

}  // namespace
}  // namespace lancer
