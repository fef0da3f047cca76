#pragma once

#include <string_view>

#include "image/Image.h"
#include "math/Color.h"
#include "util/Registry.h"

namespace lancer {

// What an output shows of the film: every output is scaled by 2^exposure; an 8-bit output (and
// the live window) also goes through a tone operator, per channel, into [0, 1] before its sRGB
// encoding. Linear outputs keep their range.
class ToneMapper {
public:
    // A tone operator the scene's "tonemap" can name: a curve from radiance >= 0 to display
    // values (clamped to [0, 1] afterwards).
    struct Operator {
        const char* name;
        float (*curve)(float c);
    };
    // The operators, by name: one registration line each.
    static const Registry<Operator>& operators();

    // Throws std::invalid_argument for an operator not in operators().
    ToneMapper(float exposure, std::string_view operatorName);
    // No exposure, the "clamp" operator: the film as it is.
    ToneMapper() : ToneMapper(0, "clamp") {}

    // The film's radiance times 2^exposure: what linear outputs store.
    Color exposed(const Color& radiance) const { return radiance * scale_; }
    // The exposed radiance through the operator, each channel in [0, 1]: what 8-bit outputs
    // encode as sRGB.
    Color display(const Color& radiance) const;

    // Turns a film into what an output stores: exposed, and for an 8-bit output (not `linear`)
    // mapped for display. In place: a film may take gigabytes.
    void mapForOutput(Image& film, bool linear) const;

private:
    float scale_;
    const Operator* operator_;
};

}  // namespace lancer
