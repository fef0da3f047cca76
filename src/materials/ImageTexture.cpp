#include "materials/ImageTexture.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "io/ImageReader.h"

namespace lancer {

ImageTexture::ImageTexture(std::shared_ptr<const MipMap> mipmap) : mipmap_(std::move(mipmap)) {}

std::shared_ptr<const ImageTexture> ImageTexture::load(const std::filesystem::path& path) {
    return std::make_shared<const ImageTexture>(
        std::make_shared<const MipMap>(ImageReader::read(path)));
}

Color ImageTexture::evaluate(const Hit& hit) const {
    const float width = std::max(std::hypot(hit.dudx, hit.dvdx), std::hypot(hit.dudy, hit.dvdy));
    return mipmap_->trilinear(hit.uv, width);
}

}  // namespace lancer
