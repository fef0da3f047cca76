#include "materials/ImageTexture.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace lancer {

ImageTexture::ImageTexture(std::shared_ptr<const MipMap> mipmap) : mipmap_(std::move(mipmap)) {}

Color ImageTexture::evaluate(const Hit& hit) const {
    const float width = std::max(std::hypot(hit.dudx, hit.dvdx), std::hypot(hit.dudy, hit.dvdy));
    return mipmap_->trilinear(hit.uv(), width);
}

Color ImageTexture::average() const {
    return mipmap_->texel(mipmap_->levelCount() - 1, 0, 0);
}

}  // namespace lancer
