#include "io/Keyframes.h"

#include <stdexcept>
#include <utility>

namespace lancer {

namespace {

using json = nlohmann::json;

// Whether `b` can be interpolated with `a`: numbers where `a` has numbers, the same arrays and
// keys, and everything else equal.
bool sameShape(const json& a, const json& b) {
    if (a.is_number() || b.is_number()) return a.is_number() && b.is_number();
    if (a.type() != b.type()) return false;
    if (a.is_array()) {
        if (a.size() != b.size()) return false;
        for (std::size_t i = 0; i < a.size(); ++i)
            if (!sameShape(a[i], b[i])) return false;
        return true;
    }
    if (a.is_object()) {
        if (a.size() != b.size()) return false;
        for (const auto& [key, value] : a.items())
            if (!b.contains(key) || !sameShape(value, b[key])) return false;
        return true;
    }
    return a == b;
}

// A weighted sum of values of one shape: numbers summed with their weights, the rest taken from
// the first.
using Term = std::pair<const json*, double>;
json weightedSum(const std::vector<Term>& terms) {
    const json& first = *terms.front().first;
    if (first.is_number()) {
        double sum = 0;
        for (const auto& [value, weight] : terms)
            if (weight != 0) sum += weight * value->get<double>();
        return sum;
    }
    const auto members = [&](const auto& memberOf) {
        std::vector<Term> parts;
        parts.reserve(terms.size());
        for (const auto& [value, weight] : terms)
            parts.emplace_back(&memberOf(*value), weight);
        return weightedSum(parts);
    };
    if (first.is_array()) {
        json sum = json::array();
        for (std::size_t i = 0; i < first.size(); ++i)
            sum.push_back(members([i](const json& v) -> const json& { return v[i]; }));
        return sum;
    }
    if (first.is_object()) {
        json sum = json::object();
        for (const auto& item : first.items()) {
            const std::string& key = item.key();
            sum[key] = members([&key](const json& v) -> const json& { return v[key]; });
        }
        return sum;
    }
    return first;
}

}  // namespace

void Keyframes::add(int frame, json value, std::string pointer) {
    if (!keys_.empty()) {
        const Keyframe& last = keys_.back();
        if (frame <= last.frame)
            throw std::invalid_argument("keyframes must come in the order of their frames: frame " +
                                        std::to_string(frame) + " follows frame " +
                                        std::to_string(last.frame));
        if (!sameShape(keys_.front().value, value))
            throw std::invalid_argument(
                "a keyframed value must have the shape of its first keyframe's (at frame " +
                std::to_string(keys_.front().frame) +
                "): the same arrays, keys and strings, numbers where it has numbers, so that "
                "they can be interpolated number by number");
    }
    keys_.push_back({frame, std::move(value), std::move(pointer)});
}

Keyframes::Value Keyframes::at(int frame, Interpolation interpolation) const {
    // The keyframes i and i + 1 around the frame.
    std::size_t i = 0;
    while (i + 1 < keys_.size() && keys_[i + 1].frame <= frame)
        ++i;
    const Keyframe& from = keys_[i];
    if (frame <= from.frame || i + 1 == keys_.size()) return {from.value, from.pointer};
    const Keyframe& to = keys_[i + 1];
    const double span = to.frame - from.frame;
    const double t = (frame - from.frame) / span;
    if (interpolation == Interpolation::Linear)
        return {weightedSum({{&from.value, 1 - t}, {&to.value, t}}), from.pointer};

    // Cubic Hermite: p(t) = h00 p_i + h10 span d_i + h01 p_i+1 + h11 span d_i+1, with the slope
    // d_k = (p_k+1 - p_k-1) / (frame_k+1 - frame_k-1) at an inner keyframe and 0 at the ends.
    const double t2 = t * t, t3 = t2 * t;
    const double h00 = 2 * t3 - 3 * t2 + 1, h10 = t3 - 2 * t2 + t, h01 = -2 * t3 + 3 * t2,
                 h11 = t3 - t2;
    std::vector<Term> terms{{&from.value, h00}, {&to.value, h01}};
    const auto addSlope = [&](std::size_t k, double scale) {
        if (k == 0 || k + 1 == keys_.size()) return;
        const double c = scale * span / (keys_[k + 1].frame - keys_[k - 1].frame);
        terms.emplace_back(&keys_[k + 1].value, c);
        terms.emplace_back(&keys_[k - 1].value, -c);
    };
    addSlope(i, h10);
    addSlope(i + 1, h11);
    return {weightedSum(terms), from.pointer};
}

}  // namespace lancer
