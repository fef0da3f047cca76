#pragma once

#include <memory>
#include <string>

#include "materials/Texture.h"
#include "util/Parameters.h"

namespace lancer {

// The keys of a material of the scene file, for the material class to read itself: numbers and
// colours as any object's, and textures.
class MaterialParameters : public Parameters {
public:
    // A colour, or a texture the loader knows ({"texture": FILE}, {"checker": {...}}).
    virtual std::shared_ptr<const Texture> texture(const std::string& key) const = 0;
    // The same for a map of numbers (roughness): an image is read as linear data, not sRGB.
    virtual std::shared_ptr<const Texture> dataTexture(const std::string& key) const = 0;
    // Whether the key holds a texture object rather than a colour or a number.
    virtual bool isTexture(const std::string& key) const = 0;
};

}  // namespace lancer
