// Suggestions for misspelt names and keys.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "util/DidYouMean.h"

namespace lancer {
namespace {

const std::vector<std::string> kMaterials{"glass", "mirror", "floor", "red"};
const std::vector<std::string> kSphereKeys{"type", "center", "radius", "material"};

std::string suggestion(const std::string& name) {
    return " (did you mean \"" + name + "\"?)";
}

TEST(DidYouMeanTest, SuggestsTheClosestCandidateForATypo) {
    EXPECT_EQ(didYouMean("glas", kMaterials), suggestion("glass"));     // a letter missing
    EXPECT_EQ(didYouMean("mirorr", kMaterials), suggestion("mirror"));  // two edits
    EXPECT_EQ(didYouMean("flor", kMaterials), suggestion("floor"));
    EXPECT_EQ(didYouMean("raduis", kSphereKeys), suggestion("radius"));  // letters swapped
    EXPECT_EQ(didYouMean("centre", kSphereKeys), suggestion("center"));  // British spelling
    EXPECT_EQ(didYouMean("materail", kSphereKeys), suggestion("material"));
}

TEST(DidYouMeanTest, IgnoresCase) {
    EXPECT_EQ(didYouMean("GLASS", kMaterials), suggestion("glass"));
    EXPECT_EQ(didYouMean("Radius", kSphereKeys), suggestion("radius"));
}

TEST(DidYouMeanTest, AllowsMoreEditsInLongWords) {
    // A third of the word: four edits in a twelve-letter word still read as a typo.
    const std::vector<std::string> candidates{"transmission"};
    EXPECT_EQ(didYouMean("trnsmisin", candidates), suggestion("transmission"));  // 3 edits
    EXPECT_EQ(didYouMean("tarnsmision", candidates), suggestion("transmission"));
    EXPECT_EQ(didYouMean("xyzxyzxyzxyz", candidates), "");
}

TEST(DidYouMeanTest, SuggestsNothingForUnrelatedWords) {
    EXPECT_EQ(didYouMean("banana", kMaterials), "");
    EXPECT_EQ(didYouMean("wood", kMaterials), "");
    EXPECT_EQ(didYouMean("colour", kSphereKeys), "");
    EXPECT_EQ(didYouMean("ab", kMaterials), "");  // short words: "red" is as far as a new word
    EXPECT_EQ(didYouMean("", kMaterials), "");
}

TEST(DidYouMeanTest, SuggestsNothingWithoutCandidates) {
    EXPECT_EQ(didYouMean("glass", {}), "");
}

TEST(DidYouMeanTest, NearestNameIsTheIndexOfTheSuggestion) {
    EXPECT_EQ(nearestName("flor", kMaterials), 2u);
    EXPECT_EQ(nearestName("banana", kMaterials), std::nullopt);
}

TEST(DidYouMeanTest, UnknownNameSuggestsAndListsTheValidOnes) {
    EXPECT_EQ(unknownName("material", "glas", kMaterials),
              R"(unknown material "glas" (did you mean "glass"?); expected "glass", "mirror", )"
              R"("floor" or "red")");
    EXPECT_EQ(unknownName("material", "wood", kMaterials),
              R"(unknown material "wood"; expected "glass", "mirror", "floor" or "red")");
}

}  // namespace
}  // namespace lancer
