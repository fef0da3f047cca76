#include "render/Aov.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace lancer {
namespace {

std::vector<std::string> namesOf(const std::vector<const Aov*>& aovs) {
    std::vector<std::string> names;
    for (const Aov* aov : aovs)
        names.emplace_back(aov->name);
    return names;
}

TEST(Aov, ParseListKeepsTheListsOrder) {
    EXPECT_EQ(namesOf(Aov::parseList("depth,albedo")),
              (std::vector<std::string>{"depth", "albedo"}));
    EXPECT_EQ(namesOf(Aov::parseList("normal")), (std::vector<std::string>{"normal"}));
    EXPECT_EQ(namesOf(Aov::parseList("albedo,normal,depth")), Aov::types().names());
}

TEST(Aov, ParseListRefusesEmptyUnknownAndRepeatedNames) {
    for (const char* list : {"", ",", "albedo,", ",depth", "albedo,,depth", "Albedo", "albedo ",
                             "normals", "depth,depth"})
        EXPECT_THROW(Aov::parseList(list), std::invalid_argument) << '"' << list << '"';
}

TEST(Aov, FilesGoBesideTheOutputInPlaceOfItsExtension) {
    const Aov& albedo = *Aov::types().find("albedo");
    EXPECT_EQ(albedo.pathBeside("out.png"), "out.albedo.exr");
    EXPECT_EQ(albedo.pathBeside("renders/v1.2/out.final.pfm"), "renders/v1.2/out.final.albedo.exr");
    EXPECT_EQ(Aov::types().find("depth")->pathBeside("/tmp/out.exr"), "/tmp/out.depth.exr");
}

TEST(Aov, EachStoresItsPartOfTheSample) {
    const AovSample sample{{0.1f, 0.2f, 0.3f}, {0, -1, 0.5f}, 7};
    EXPECT_EQ(Aov::types().find("albedo")->value(sample), Color(0.1f, 0.2f, 0.3f));
    EXPECT_EQ(Aov::types().find("normal")->value(sample), Color(0, -1, 0.5f));
    EXPECT_EQ(Aov::types().find("depth")->value(sample), Color(7));
}

}  // namespace
}  // namespace lancer
