#pragma once

#include <memory>

#include "materials/Texture.h"
#include "math/Color.h"

namespace lancer {

// A Blinn-Phong material with mirror reflection and refraction: the scene format's material.
// Its fields are the scene file's keys; the integrators decide how to use them.
class Material {
public:
    Material();

    std::shared_ptr<const Texture> diffuse;  // kd
    std::shared_ptr<const Texture> ambient;  // ka (by default the diffuse texture)
    Color specular{0};                       // ks
    float shininess = 32;                    // Blinn-Phong exponent n
    Color reflection{0};                     // kr
    Color transmission{0};                   // kt
    float ior = 1.5f;                        // index of refraction inside the surface
    Color emission{0};                       // emitted radiance

    bool isTransmissive() const { return !transmission.isBlack(); }
};

}  // namespace lancer
