#pragma once

#include <filesystem>

#include "materials/Image.h"

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
};

}  // namespace lancer
