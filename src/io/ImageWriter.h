#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

#include "image/Image.h"

namespace lancer {

// Saves a film through FreeImage, in the format the file extension names: .png .jpg .bmp .tga
// .tif as 8-bit sRGB (clamped), .exr .hdr .pfm as linear 32-bit float. The image is encoded in
// memory, its bytes written to a temporary file in the same folder with every system call checked
// and flushed to the disk, then renamed into place, so that a failure (a full disk) never leaves a
// damaged file behind.
class ImageWriter {
public:
    // Whether the path's extension (case-insensitive) is one of the formats above.
    static bool supports(const std::filesystem::path& path);
    // Whether the path's format stores linear float radiance (.exr .hdr .pfm) rather than 8-bit
    // sRGB.
    static bool storesLinear(const std::filesystem::path& path);
    // The supported extensions, for messages: ".png, .jpg, ...".
    static std::string supportedExtensions();

    // Throws std::runtime_error naming the file when it cannot be written.
    static void write(const Image& film, const std::filesystem::path& path);
    // About the most memory write() takes for an image of this size in the path's format: the
    // bitmap and the encoded file (at most about as large), in bytes.
    static std::uint64_t memoryNeeded(const std::filesystem::path& path, int width, int height);
};

}  // namespace lancer
