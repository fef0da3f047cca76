#include "io/ImageReader.h"

#include <FreeImage.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <system_error>

#include "io/InputError.h"
#include "math/Srgb.h"

namespace lancer {

namespace {

// FreeImage reports failures through a global callback; keep the last message for ours.
thread_local std::string lastFreeImageMessage;
void recordFreeImageMessage(FREE_IMAGE_FORMAT, const char* message) {
    lastFreeImageMessage = message ? message : "";
}

struct BitmapDeleter {
    void operator()(FIBITMAP* b) const { FreeImage_Unload(b); }
};
using Bitmap = std::unique_ptr<FIBITMAP, BitmapDeleter>;

// Why the file cannot be opened for reading, or "" when it can: FreeImage itself only says that
// it failed.
std::string openError(const std::filesystem::path& path) {
    std::error_code ignored;
    if (std::filesystem::is_directory(path, ignored)) return "a folder, not an image file";
    std::FILE* file = std::fopen(path.string().c_str(), "rb");
    if (!file) return std::generic_category().message(errno);
    std::fclose(file);
    return "";
}

FREE_IMAGE_FORMAT formatOf(const std::string& file) {
    const FREE_IMAGE_FORMAT fromContents = FreeImage_GetFileType(file.c_str(), 0);
    return fromContents != FIF_UNKNOWN ? fromContents : FreeImage_GetFIFFromFilename(file.c_str());
}

int loadFlags(FREE_IMAGE_FORMAT format) {
    switch (format) {
        case FIF_JPEG:
            return JPEG_ACCURATE;  // exact inverse DCT and chroma upsampling
        case FIF_RAW:
            return RAW_DISPLAY;  // developed to display (sRGB-like) colour, not linear sensor data
        default:
            return 0;  // PNG: a gAMA chunk is honoured, re-encoding to display gamma like sRGB
    }
}

bool isFloat(FREE_IMAGE_TYPE type) {
    return type == FIT_FLOAT || type == FIT_RGBF || type == FIT_RGBAF;
}

// NaN and infinities in a float file are no colour; they would spread through every filter.
float finiteOrZero(float v) {
    return std::isfinite(v) ? v : 0.0f;
}

}  // namespace

Image ImageReader::read(const std::filesystem::path& path) {
    const std::string file = path.string();
    if (const std::string error = openError(path); !error.empty())
        throw InputError(file, "cannot open the image (" + error + ")");

    const FREE_IMAGE_FORMAT format = formatOf(file);
    if (format == FIF_UNKNOWN || !FreeImage_FIFSupportsReading(format))
        throw InputError(file, "cannot read the image (unknown or corrupt format)");

    FreeImage_SetOutputMessage(recordFreeImageMessage);
    lastFreeImageMessage.clear();
    const Bitmap bitmap(FreeImage_Load(format, file.c_str(), loadFlags(format)));
    if (!bitmap || FreeImage_GetWidth(bitmap.get()) == 0 || FreeImage_GetHeight(bitmap.get()) == 0)
        throw InputError(
            file, std::string("cannot read the image (corrupt or truncated ") +
                      FreeImage_GetFormatFromFIF(format) + " file" +
                      (lastFreeImageMessage.empty() ? "" : ": " + lastFreeImageMessage) + ")");

    // FreeImage's conversion handles every bit depth, palette, greyscale and alpha layout; it
    // scales integer data to [0, 1] and leaves float data as it is.
    const bool linear = isFloat(FreeImage_GetImageType(bitmap.get()));
    const Bitmap rgb(FreeImage_ConvertToRGBF(bitmap.get()));
    if (!rgb) throw InputError(file, "cannot read the image (its pixels are not colour data)");

    const int width = static_cast<int>(FreeImage_GetWidth(rgb.get()));
    const int height = static_cast<int>(FreeImage_GetHeight(rgb.get()));
    const auto decode = [linear](float v) { return linear ? finiteOrZero(v) : srgbToLinear(v); };
    Image image(width, height);
    for (int y = 0; y < height; ++y) {
        // FreeImage stores rows bottom-up: image row y is scanline height - 1 - y.
        const auto* row =
            reinterpret_cast<const FIRGBF*>(FreeImage_GetScanLine(rgb.get(), height - 1 - y));
        for (int x = 0; x < width; ++x)
            image.at(x, y) = {decode(row[x].red), decode(row[x].green), decode(row[x].blue)};
    }
    return image;
}

}  // namespace lancer
