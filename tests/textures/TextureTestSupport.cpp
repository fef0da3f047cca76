#include "TextureTestSupport.h"

#include <atomic>
#include <fstream>
#include <iterator>
#include <random>
#include <stdexcept>
#include <system_error>

namespace lancer::test {

fs::path dataFolder() {
    return LANCER_TEXTURE_TEST_DATA;
}

std::string readBytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error("cannot read " + path.string());
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void writeBytes(const fs::path& path, const std::string& bytes) {
    std::ofstream out(path, std::ios::binary);
    out << bytes;
    if (!out) throw std::runtime_error("cannot write " + path.string());
}

Image makeImage(int width, int height, const std::function<Color(int x, int y)>& texel) {
    Image image(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            image.at(x, y) = texel(x, y);
    return image;
}

// FreeImage stores rows bottom-up: image row y is scanline height - 1 - y.
Bitmap makeBitmap8(int width, int height, const std::function<RGBQUAD(int x, int y)>& code) {
    Bitmap bitmap(FreeImage_Allocate(width, height, 24));
    for (int y = 0; y < height; ++y) {
        BYTE* row = FreeImage_GetScanLine(bitmap.get(), height - 1 - y);
        for (int x = 0; x < width; ++x, row += 3) {
            const RGBQUAD c = code(x, y);
            row[FI_RGBA_RED] = c.rgbRed;
            row[FI_RGBA_GREEN] = c.rgbGreen;
            row[FI_RGBA_BLUE] = c.rgbBlue;
        }
    }
    return bitmap;
}

Bitmap makeBitmapFloat(const Image& image) {
    Bitmap bitmap(FreeImage_AllocateT(FIT_RGBF, image.width(), image.height()));
    for (int y = 0; y < image.height(); ++y) {
        auto* row =
            reinterpret_cast<FIRGBF*>(FreeImage_GetScanLine(bitmap.get(), image.height() - 1 - y));
        for (int x = 0; x < image.width(); ++x) {
            const Color& c = image.at(x, y);
            row[x] = {c.r, c.g, c.b};
        }
    }
    return bitmap;
}

void save(const Bitmap& bitmap, const fs::path& path, FREE_IMAGE_FORMAT format, int flags) {
    if (!bitmap || !FreeImage_Save(format, bitmap.get(), path.string().c_str(), flags))
        throw std::runtime_error("cannot write the test image " + path.string());
}

}  // namespace lancer::test
