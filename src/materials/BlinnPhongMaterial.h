#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "materials/ConstantTexture.h"
#include "materials/Material.h"
#include "materials/MaterialParameters.h"
#include "materials/Optics.h"

namespace lancer {

// The scene format's material: Blinn-Phong with mirror reflection and refraction. Its BSDF is a
// Lambertian lobe kd, a normalized Blinn-Phong lobe ks and shininess, a mirror kr (a conductor's
// Fresnel reflectance with `metal` or `conductor`) and a smooth dielectric kt / ior, whose local
// responses and specular rays give Whitted's equation; with `roughness` > 0 the mirror and the
// dielectric are GGX microfacet lobes instead.
class BlinnPhongMaterial final : public Material {
public:
    // The scene file's keys.
    struct Parameters {
        std::shared_ptr<const Texture> diffuse =
            std::make_shared<ConstantTexture>(Color(0.8f));  // kd
        std::shared_ptr<const Texture> ambient = diffuse;    // ka (by default the diffuse texture)
        Color specular{0};                                   // ks
        float shininess = 32;                                // Blinn-Phong exponent n
        Color reflection{0};                                 // kr
        Color transmission{0};                               // kt
        float ior = 1.5f;                                    // index of refraction inside
        Color emission{0};                                   // emitted radiance
        float roughness = 0;                                 // GGX alpha of kr and kt; 0: smooth
        std::optional<ConductorIor> conductor;               // Fresnel of kr: none is 1
        // Textures that multiply the factors above where given (the scene's {"texture": ...} for
        // these keys, whose factor is then 1; MTL's map_Ks; glTF's emissive texture); null: the
        // factor alone. A roughness map's value is the mean of its three channels.
        std::shared_ptr<const Texture> specularMap, reflectionMap, roughnessMap, emissionMap;
    };

    // A named metal of the scene file's `metal` key.
    struct Metal {
        const char* name;
        ConductorIor ior;
    };
    static const std::vector<Metal>& metals();

    BlinnPhongMaterial() = default;
    explicit BlinnPhongMaterial(Parameters parameters);
    // The scene file's "blinn_phong" material, every key optional.
    static std::vector<std::string> keys() {
        return {"diffuse", "ambient",  "specular",  "shininess", "reflection", "transmission",
                "ior",     "emission", "roughness", "metal",     "conductor"};
    }
    static std::unique_ptr<Material> create(const MaterialParameters& parameters);

    void addLobes(const Hit& hit, Bsdf& bsdf) const override;
    Color diffuseReflectance(const Hit& hit) const override;
    bool reflectsDiffusely() const override;
    bool reflectsGlossily() const override { return !parameters_.specular.isBlack(); }
    Color ambientReflectance(const Hit& hit) const override;
    Color emission(const Hit& hit) const override;
    Color emission() const override;
    bool hasTexturedEmission() const override { return parameters_.emissionMap != nullptr; }
    Color transmission() const override { return parameters_.transmission; }

    const Parameters& parameters() const { return parameters_; }

private:
    Parameters parameters_;
};

}  // namespace lancer
