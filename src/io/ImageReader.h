#pragma once

#include <cstddef>
#include <filesystem>
#include <memory>
#include <string>

#include "image/Image.h"
#include "materials/ImageTexture.h"

namespace lancer {

// Loads image files through FreeImage as linear RGB: PNG, JPEG (baseline and progressive), TGA,
// BMP, TIFF, EXR, HDR, PFM and the other formats FreeImage reads. The format is recognised from
// the file's contents, or from its extension when the contents have no signature (TGA).
// Integer images (8 or 16 bits per channel, palettized, greyscale) of colour hold sRGB-encoded
// colour and are decoded to linear; those of data (normal and bump maps) are taken as they are,
// scaled to [0, 1]. Float images (EXR, HDR, PFM, float TIFF) are linear already and kept.
// Alpha is ignored, but for Content::Alpha.
class ImageReader {
public:
    // What an integer image's values are.
    enum class Content {
        Color,  // sRGB-encoded colour (textures of colours)
        Data,   // linear numbers (normal maps, height maps): never sRGB-decoded
        // A coverage mask (opacity, MTL's map_d): the alpha channel of an image that has one
        // (RGBA, or a palette with transparency), else its values as Data; grey either way.
        Alpha,
    };

    // The largest image read: beyond it a damaged or hostile header would have FreeImage allocate
    // gigabytes. The size a file declares is checked before its pixels are decoded (for the few
    // formats FreeImage cannot read the header of alone, GIF, JPEG 2000, DDS, SGI and some rarer
    // ones, after).
    static constexpr unsigned kMaxSide = 32768;
    static constexpr unsigned long long kMaxPixels = 1ull << 28;

    // Throws InputError naming the file when it is missing, unreadable, corrupt, larger than the
    // limits above or holds pixels that are not colour (complex or 32-bit integer data, for
    // example).
    static Image read(const std::filesystem::path& path, Content content = Content::Color);
    // For images decoded by another library (glTF's, by tinygltf): throws InputError naming
    // `name` when the encoded image in `bytes` declares a size beyond the limits above, read from
    // its header alone as read() does before decoding. Bytes FreeImage does not recognise, or
    // whose header it cannot read alone, pass: the decoder reports those.
    static void checkDeclaredSize(const unsigned char* bytes, std::size_t size,
                                  const std::string& name);
    // The image of the file as a texture: read, then its mip-map pyramid built.
    static std::shared_ptr<const ImageTexture> readTexture(const std::filesystem::path& path,
                                                           Content content = Content::Color);
};

}  // namespace lancer
