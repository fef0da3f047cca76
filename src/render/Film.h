#pragma once

#include <vector>

#include "math/Color.h"

namespace lancer {

// The image being rendered: linear RGB radiance per pixel, row by row from the top-left corner.
class Film {
public:
    Film(int width, int height);

    int width() const { return width_; }
    int height() const { return height_; }

    const Color& pixel(int x, int y) const { return pixels_[index(x, y)]; }
    void setPixel(int x, int y, const Color& c) { pixels_[index(x, y)] = c; }

private:
    std::size_t index(int x, int y) const {
        return static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) +
               static_cast<std::size_t>(x);
    }

    int width_, height_;
    std::vector<Color> pixels_;
};

}  // namespace lancer
