#pragma once

#include <cstddef>
#include <stdexcept>
#include <vector>

#include "math/Color.h"

namespace lancer {

// A picture as a grid of linear RGB texels, row 0 at the top, stored row by row.
class Image {
public:
    // Every texel `fill`; the size must be at least 1x1.
    Image(int width, int height, const Color& fill = Color{})
        : width_(width), height_(height), texels_(checkedCount(width, height), fill) {}

    int width() const { return width_; }
    int height() const { return height_; }

    // (x, y) within [0, width) x [0, height).
    const Color& at(int x, int y) const { return texels_[index(x, y)]; }
    Color& at(int x, int y) { return texels_[index(x, y)]; }

private:
    static std::size_t checkedCount(int width, int height) {
        if (width < 1 || height < 1)
            throw std::invalid_argument("an image needs at least 1x1 texels");
        return static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
    }
    std::size_t index(int x, int y) const {
        return static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) +
               static_cast<std::size_t>(x);
    }

    int width_, height_;
    std::vector<Color> texels_;
};

}  // namespace lancer
