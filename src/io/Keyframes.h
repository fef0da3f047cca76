#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace lancer {

// One value of a scene file that its "animation" block keyframes (a camera key, an object's
// transform): the keyframes' values, in the order of their frames, and the value at any frame
// between them, interpolated number by number. Before the first keyframe the value is the first
// keyframe's, after the last the last's; so keyframes of one value must have the same shape
// (the same arrays, keys and strings, numbers where the first has numbers).
class Keyframes {
public:
    enum class Interpolation {
        Linear,  // straight from one keyframe to the next
        // A cubic through the keyframes (Catmull-Rom tangents, for keyframes unevenly spaced),
        // at rest at the first and the last: a move that eases in and out.
        Smooth
    };

    // A value at one frame, and the place to report it at: the `pointer` given with the keyframe
    // at or before the frame (the first, before it).
    struct Value {
        nlohmann::json value;
        std::string pointer;
    };

    // Appends a keyframe; throws std::invalid_argument, saying why, if `frame` is not after the
    // last keyframe's or `value` is not shaped as the first keyframe's.
    void add(int frame, nlohmann::json value, std::string pointer);

    // The value at `frame`. At least one keyframe must have been added.
    Value at(int frame, Interpolation interpolation) const;

private:
    struct Keyframe {
        int frame;
        nlohmann::json value;
        std::string pointer;
    };
    std::vector<Keyframe> keys_;
};

}  // namespace lancer
