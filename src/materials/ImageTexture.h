#pragma once

#include <memory>

#include "materials/MipMap.h"
#include "materials/Texture.h"

namespace lancer {

// An image tiled over the surface's uv (repeat addressing, v = 0 at the bottom of the image),
// filtered trilinearly over the mip level that matches the hit's footprint.
class ImageTexture final : public Texture {
public:
    // The pyramid is shared, so that one file used by several materials is stored once.
    explicit ImageTexture(std::shared_ptr<const MipMap> mipmap);
    // The footprint picks the MIP level.
    bool readsFootprint() const override { return true; }

    // The footprint is the longer side of the parallelogram that one pixel covers in uv,
    // max(|(dudx, dvdx)|, |(dudy, dvdy)|): the scale factor of the OpenGL specification, which
    // picks the level whose texels are one pixel apart. (pbrt's 2 * max of the four components
    // reads about one level blurrier.) No derivatives, no footprint: bilinear on level 0.
    Color evaluate(const Hit& hit) const override;
    // The 1 x 1 level of the pyramid.
    Color average() const override;

    const MipMap& mipmap() const { return *mipmap_; }

private:
    std::shared_ptr<const MipMap> mipmap_;
};

}  // namespace lancer
