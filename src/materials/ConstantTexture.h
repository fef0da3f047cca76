#pragma once

#include "materials/Texture.h"

namespace lancer {

class ConstantTexture final : public Texture {
public:
    explicit ConstantTexture(const Color& color) : color_(color) {}
    Color evaluate(const Hit&) const override { return color_; }
    Color average() const override { return color_; }
    bool isBlack() const override { return color_.isBlack(); }

private:
    Color color_;
};

}  // namespace lancer
