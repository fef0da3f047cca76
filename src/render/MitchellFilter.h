#pragma once

#include "render/Filter.h"

namespace lancer {

// Mitchell and Netravali's cubic (1988) with B = C = 1/3, the pair they recommend: sharper than a
// Gaussian, with small negative lobes. Their kernel spans [-2, 2]; here it is stretched to
// [-radius, radius] (and scaled by 2 / radius, so that it still integrates to 1).
class MitchellFilter : public Filter {
public:
    explicit MitchellFilter(float radius);

    float profile(float x) const override;
};

}  // namespace lancer
