#pragma once

#include <vector>

#include "image/Image.h"
#include "math/Color.h"
#include "math/Vec2.h"

namespace lancer {

// An image pyramid for filtered texture lookups. Level 0 is the image itself; each next level
// halves the width and the height (rounding down, never below 1) down to 1x1, every texel the
// exact average of the area it covers in the level above.
//
// Lookups use repeat (wrap) addressing. In uv, texel i of a level n texels wide is centred at
// u = (i + 0.5) / n, and v = 0 is the bottom of the image (the OBJ convention): image row
// (1 - v) * height, so row 0, the top, is at v = 1.
class MipMap {
public:
    explicit MipMap(Image image);

    int levelCount() const { return static_cast<int>(levels_.size()); }
    // Level `level` in [0, levelCount()).
    const Image& image(int level) const { return levels_[level]; }

    // The texel at integer coordinates (row 0 at the top), wrapped into the level.
    Color texel(int level, int x, int y) const;
    // Bilinear interpolation between the four texel centres around uv.
    Color bilinear(int level, Vec2 uv) const;
    // Blends bilinear lookups in the two levels around log2(width * resolution), whose texels
    // are about as large as the footprint; `width` is the footprint's size in uv units and the
    // resolution is level 0's larger side. A zero (or NaN) width reads level 0, a footprint as
    // large as the image reads the 1x1 level.
    Color trilinear(Vec2 uv, float width) const;

private:
    std::vector<Image> levels_;
};

}  // namespace lancer
