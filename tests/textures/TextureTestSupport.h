#pragma once

// Helpers shared by the texture tests: a scratch folder, images built from a formula, and
// image files written through FreeImage to be read back.

#include <FreeImage.h>

#include <filesystem>
#include <functional>
#include <memory>
#include <string>

#include "image/Image.h"

#include "PfmFile.h"
#include "TempFolder.h"

namespace lancer::test {

namespace fs = std::filesystem;

// The folder of the small real textures copied into the test sources (see data/SOURCES.md).
fs::path dataFolder();

std::string readBytes(const fs::path& path);
void writeBytes(const fs::path& path, const std::string& bytes);

Image makeImage(int width, int height, const std::function<Color(int x, int y)>& texel);

struct BitmapDeleter {
    void operator()(FIBITMAP* b) const { FreeImage_Unload(b); }
};
using Bitmap = std::unique_ptr<FIBITMAP, BitmapDeleter>;

// FreeImage's RGBQUAD from named channels (its field order depends on the platform).
inline RGBQUAD rgb(int red, int green, int blue) {
    RGBQUAD c{};
    c.rgbRed = static_cast<BYTE>(red);
    c.rgbGreen = static_cast<BYTE>(green);
    c.rgbBlue = static_cast<BYTE>(blue);
    return c;
}

// An 8-bit RGB bitmap whose texel (x, y), row 0 at the top, has the codes code(x, y).
Bitmap makeBitmap8(int width, int height, const std::function<RGBQUAD(int x, int y)>& code);
// A 32-bit float RGB bitmap with the image's values.
Bitmap makeBitmapFloat(const Image& image);

// Saves through FreeImage; throws when it fails, so that a test never reads a file it did not
// write.
void save(const Bitmap& bitmap, const fs::path& path, FREE_IMAGE_FORMAT format, int flags = 0);

}  // namespace lancer::test
