#pragma once

#include <filesystem>
#include <memory>

#include "image/Image.h"
#include "materials/ImageTexture.h"

namespace lancer {

// Loads image files through FreeImage as linear RGB: PNG, JPEG (baseline and progressive), TGA,
// BMP, TIFF, EXR, HDR, PFM and the other formats FreeImage reads. The format is recognised from
// the file's contents, or from its extension when the contents have no signature (TGA).
// Integer images (8 or 16 bits per channel, palettized, greyscale) hold sRGB-encoded colour and
// are decoded to linear; float images (EXR, HDR, PFM, float TIFF) are linear already and kept.
// Alpha is ignored.
class ImageReader {
public:
    // Throws InputError naming the file when it is missing, unreadable, corrupt or holds pixels
    // that are not colour (complex or 32-bit integer data, for example).
    static Image read(const std::filesystem::path& path);
    // The image of the file as a texture: read, then its mip-map pyramid built.
    static std::shared_ptr<const ImageTexture> readTexture(const std::filesystem::path& path);
};

}  // namespace lancer
