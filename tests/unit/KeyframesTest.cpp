// Keyframes: a keyframed value interpolated number by number, linearly or by the eased cubic,
// held before the first keyframe and after the last; keyframes out of order or of another shape
// refused.

#include <gtest/gtest.h>

#include <stdexcept>

#include "io/Keyframes.h"

namespace lancer {
namespace {

using json = nlohmann::json;
using Interpolation = Keyframes::Interpolation;

constexpr double kTolerance = 1e-12;

double numberAt(const Keyframes& keyframes, int frame, Interpolation interpolation) {
    return keyframes.at(frame, interpolation).value.get<double>();
}

TEST(KeyframesTest, OneKeyframeHoldsEverywhere) {
    Keyframes keyframes;
    keyframes.add(5, 2.5, "/k/0");
    for (const int frame : {1, 5, 9})
        for (const Interpolation i : {Interpolation::Linear, Interpolation::Smooth}) {
            EXPECT_EQ(numberAt(keyframes, frame, i), 2.5);
            EXPECT_EQ(keyframes.at(frame, i).pointer, "/k/0");
        }
}

TEST(KeyframesTest, LinearGoesStraightAndHoldsOutside) {
    Keyframes keyframes;
    keyframes.add(2, 10.0, "/k/0");
    keyframes.add(6, 30.0, "/k/1");
    EXPECT_EQ(numberAt(keyframes, 1, Interpolation::Linear), 10);  // before the first
    EXPECT_EQ(numberAt(keyframes, 2, Interpolation::Linear), 10);
    EXPECT_NEAR(numberAt(keyframes, 3, Interpolation::Linear), 15, kTolerance);
    EXPECT_NEAR(numberAt(keyframes, 5, Interpolation::Linear), 25, kTolerance);
    EXPECT_EQ(numberAt(keyframes, 6, Interpolation::Linear), 30);  // exactly the keyframe's
    EXPECT_EQ(numberAt(keyframes, 9, Interpolation::Linear), 30);  // after the last
    // Reported at the keyframe at or before the frame.
    EXPECT_EQ(keyframes.at(1, Interpolation::Linear).pointer, "/k/0");
    EXPECT_EQ(keyframes.at(5, Interpolation::Linear).pointer, "/k/0");
    EXPECT_EQ(keyframes.at(6, Interpolation::Linear).pointer, "/k/1");
}

TEST(KeyframesTest, SmoothBetweenTwoKeyframesEasesInAndOut) {
    Keyframes keyframes;
    keyframes.add(1, 0.0, "/k/0");
    keyframes.add(5, 1.0, "/k/1");
    // At rest at both ends: smoothstep, 3 t^2 - 2 t^3.
    for (const int frame : {2, 3, 4}) {
        const double t = (frame - 1) / 4.0;
        EXPECT_NEAR(numberAt(keyframes, frame, Interpolation::Smooth), 3 * t * t - 2 * t * t * t,
                    kTolerance)
            << "frame " << frame;
    }
    EXPECT_NEAR(numberAt(keyframes, 2, Interpolation::Smooth), 0.15625, kTolerance);
}

TEST(KeyframesTest, SmoothThroughUnevenKeyframesUsesCatmullRomSlopes) {
    // Keyframes at frames 1, 3, 9 with values 0, 4, 6: the slope at frame 3 is
    // (6 - 0) / (9 - 1) = 0.75 a frame; 0 at the ends.
    Keyframes keyframes;
    keyframes.add(1, 0.0, "/k/0");
    keyframes.add(3, 4.0, "/k/1");
    keyframes.add(9, 6.0, "/k/2");
    // Frame 2, in the span 1-3 (2 frames, t = 1/2): h00 p0 + h01 p1 + h11 * 2 * 0.75.
    EXPECT_NEAR(numberAt(keyframes, 2, Interpolation::Smooth), 0.5 * 4 + (-0.125) * 2 * 0.75,
                kTolerance);
    // Frame 5, in the span 3-9 (6 frames, t = 1/3): h00 p1 + h10 * 6 * 0.75 + h01 p2.
    const double t = 1.0 / 3, h00 = 2 * t * t * t - 3 * t * t + 1, h10 = t * t * t - 2 * t * t + t,
                 h01 = -2 * t * t * t + 3 * t * t;
    EXPECT_NEAR(numberAt(keyframes, 5, Interpolation::Smooth), h00 * 4 + h10 * 6 * 0.75 + h01 * 6,
                kTolerance);
    // Through every keyframe exactly.
    EXPECT_EQ(numberAt(keyframes, 3, Interpolation::Smooth), 4);
    EXPECT_EQ(numberAt(keyframes, 9, Interpolation::Smooth), 6);
}

TEST(KeyframesTest, InterpolatesArraysAndObjectsNumberByNumber) {
    Keyframes keyframes;
    keyframes.add(1, json{{"rotate", {0, 1, 0, 0}}, {"translate", {0, 0, 0}}}, "/k/0");
    keyframes.add(3, json{{"rotate", {0, 1, 0, 90}}, {"translate", {2, -4, 6}}}, "/k/1");
    const json middle = keyframes.at(2, Interpolation::Linear).value;
    EXPECT_EQ(middle, (json{{"rotate", {0.0, 1.0, 0.0, 45.0}}, {"translate", {1.0, -2.0, 3.0}}}));
}

TEST(KeyframesTest, KeepsStringsAndFlagsThatAllKeyframesShare) {
    Keyframes keyframes;
    keyframes.add(1, json{{"name", "a"}, {"on", true}, {"x", 0}}, "/k/0");
    keyframes.add(3, json{{"name", "a"}, {"on", true}, {"x", 4}}, "/k/1");
    EXPECT_EQ(keyframes.at(2, Interpolation::Smooth).value,
              (json{{"name", "a"}, {"on", true}, {"x", 2.0}}));
}

TEST(KeyframesTest, RefusesKeyframesOutOfOrder) {
    Keyframes keyframes;
    keyframes.add(4, 1.0, "/k/0");
    EXPECT_THROW(keyframes.add(4, 2.0, "/k/1"), std::invalid_argument);
    EXPECT_THROW(keyframes.add(2, 2.0, "/k/1"), std::invalid_argument);
}

TEST(KeyframesTest, RefusesAKeyframeOfAnotherShape) {
    const json first{{"translate", {0, 0, 0}}, {"name", "a"}};
    for (const json& other :
         {json{{"translate", {0, 0}}, {"name", "a"}},
          json{{"translate", {0, 0, "1"}}, {"name", "a"}},
          json{{"translate", {0, 0, 0}}, {"name", "b"}}, json{{"translate", {0, 0, 0}}},
          json{{"scale", {0, 0, 0}}, {"name", "a"}}, json(3.0)}) {
        Keyframes keyframes;
        keyframes.add(1, first, "/k/0");
        EXPECT_THROW(keyframes.add(2, other, "/k/1"), std::invalid_argument) << other.dump();
    }
}

}  // namespace
}  // namespace lancer
