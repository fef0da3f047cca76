#include "io/ImageReader.h"

#include <FreeImage.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <exception>
#include <memory>
#include <string>
#include <system_error>

#include "io/FreeImageSupport.h"
#include "math/Srgb.h"
#include "scene/InputError.h"

namespace lancer {

namespace {

struct FileCloser {
    void operator()(std::FILE* f) const { std::fclose(f); }
};
using File = std::unique_ptr<std::FILE, FileCloser>;

// FreeImage reads through these.
unsigned readFile(void* buffer, unsigned size, unsigned count, fi_handle handle) {
    return static_cast<unsigned>(std::fread(buffer, size, count, static_cast<std::FILE*>(handle)));
}
// For OpenEXR, reading past the end of the file yields zeros rather than leaving the buffer as it
// was: FreeImage's OpenEXR stream ignores short reads, and OpenEXR, rereading stale bytes where it
// expects the null that ends a list (of attributes, of channels), would loop forever; zeros end
// the list, and OpenEXR reports the damage. Only for OpenEXR: other decoders ask for more than
// their buffer holds where the file is short (fuzz_image: FreeImage's ICO decoder asked for 3.2
// MB into 2560 bytes), and filling what they asked for wrote past the buffer.
unsigned readZeroFilled(void* buffer, unsigned size, unsigned count, fi_handle handle) {
    const std::size_t read = readFile(buffer, size, count, handle);
    std::memset(static_cast<char*>(buffer) + read * size, 0, (count - read) * size);
    return static_cast<unsigned>(read);
}
unsigned writeNothing(void*, unsigned, unsigned, fi_handle) {
    return 0;
}
int seek(fi_handle handle, long offset, int origin) {
    return std::fseek(static_cast<std::FILE*>(handle), offset, origin);
}
long tell(fi_handle handle) {
    return std::ftell(static_cast<std::FILE*>(handle));
}
FreeImageIO fileIO{readFile, writeNothing, seek, tell};
FreeImageIO exrFileIO{readZeroFilled, writeNothing, seek, tell};

FreeImageIO* ioFor(FREE_IMAGE_FORMAT format) {
    return format == FIF_EXR ? &exrFileIO : &fileIO;
}

// From the file's signature, or failing that (TGA has none) from its extension.
FREE_IMAGE_FORMAT formatOf(std::FILE* file, const std::string& name) {
    const FREE_IMAGE_FORMAT fromContents = FreeImage_GetFileTypeFromHandle(&fileIO, file, 0);
    return fromContents != FIF_UNKNOWN ? fromContents : FreeImage_GetFIFFromFilename(name.c_str());
}

// ---- Damage that FreeImage 3.18's decoders do not survive, found before they see the file.

std::uint32_t littleEndian(const unsigned char* bytes, int count) {
    std::uint32_t value = 0;
    for (int i = count - 1; i >= 0; --i)
        value = value << 8 | bytes[i];
    return value;
}

// The `count` (at most 4) bytes at `offset` as a little-endian integer, as FreeImage's decoders
// see them: zeros past the end of the file.
std::uint32_t readLittleEndian(std::FILE* file, long offset, int count) {
    unsigned char bytes[4] = {};
    const bool inFile = std::fseek(file, offset, SEEK_SET) == 0 &&
                        std::fread(bytes, 1, static_cast<std::size_t>(count), file) > 0;
    return inFile ? littleEndian(bytes, count) : 0;
}

long fileSize(std::FILE* file) {
    std::fseek(file, 0, SEEK_END);
    return std::ftell(file);
}

// Skips a null-terminated name of at most 255 characters (OpenEXR's longest); false when the
// file ends first or the name is longer. `empty` tells whether it was "".
bool skipExrName(std::FILE* file, bool& empty) {
    for (int length = 0; length <= 255; ++length) {
        const int c = std::fgetc(file);
        if (c == EOF) return false;
        if (c == 0) {
            empty = length == 0;
            return true;
        }
    }
    return false;
}

// OpenEXR trusts the sizes in a file's header: a damaged one makes it allocate gigabytes. Checks
// that every attribute of every header (one, or a list of them in a multi-part file) lies within
// the file.
bool exrHeadersFitInFile(std::FILE* file) {
    const long size = fileSize(file);
    const bool multipart = readLittleEndian(file, 4, 4) & 0x1000;  // the version field's flags
    bool fits = std::fseek(file, 8, SEEK_SET) == 0;
    for (bool moreHeaders = true; fits && moreHeaders;) {
        int attributes = 0;
        for (bool endOfHeader = false; fits && !endOfHeader;) {
            fits = skipExrName(file, endOfHeader);
            if (!fits || endOfHeader) break;
            ++attributes;
            bool emptyType = false;
            unsigned char lengthBytes[4];
            fits = skipExrName(file, emptyType) && std::fread(lengthBytes, 1, 4, file) == 4;
            const long length = static_cast<std::int32_t>(littleEndian(lengthBytes, 4));
            fits = fits && length >= 0 && length <= size - std::ftell(file) &&
                   std::fseek(file, length, SEEK_CUR) == 0;
        }
        moreHeaders = multipart && attributes > 0;  // an empty header ends the list
    }
    return fits;
}

// The TGA header's image type (1-3 uncompressed, 9-11 run-length encoded), pixel depth and colour
// map entry size must be the specification's: FreeImage 3.18 takes others as they come, and on a
// 25-byte file of type 0 (no image) and 78 bits a pixel asked malloc for 18 exabytes (fuzz_image).
bool tgaHeaderIsValid(std::FILE* file) {
    const auto byteAt = [file](long offset) { return readLittleEndian(file, offset, 1); };
    const std::uint32_t imageType = byteAt(2), depth = byteAt(16);
    const bool typeKnown =
        (imageType >= 1 && imageType <= 3) || (imageType >= 9 && imageType <= 11);
    const bool depthKnown = depth == 8 || depth == 15 || depth == 16 || depth == 24 || depth == 32;
    const std::uint32_t mapType = byteAt(1), entryBits = byteAt(7);
    const bool mapKnown = mapType == 0 || (mapType == 1 && (entryBits == 15 || entryBits == 16 ||
                                                            entryBits == 24 || entryBits == 32));
    return typeKnown && depthKnown && mapKnown;
}

// FreeImage's TGA decoder sizes its run-length read cache as (bytes of pixel data) / rows: when
// that is less than a pixel it reads out of bounds, and when it is zero it frees the bitmap and
// still returns it. A TGA 2.0 postage stamp (thumbnail) claiming more pixels than its space holds
// is copied from beyond its buffer. Both mean a damaged file: run-length packets never cross rows,
// so each row takes at least one packet, a header byte and a pixel. An uncompressed file must hold
// all its pixels.
bool tgaIsSafeToDecode(std::FILE* file) {
    const long size = fileSize(file);
    const auto byteAt = [file](long offset) { return readLittleEndian(file, offset, 1); };
    const auto wordAt = [file](long offset) { return readLittleEndian(file, offset, 2); };
    const std::uint32_t depth = byteAt(16);
    const std::uint32_t imageType = byteAt(2);
    const std::uint32_t colourMap = byteAt(1) != 0 ? wordAt(5) * ((byteAt(7) + 7) / 8) : 0;
    const long pixelData = 18 + static_cast<long>(byteAt(0) + colourMap);
    if (imageType >= 9 && imageType <= 11) {
        const long smallestRuns = static_cast<long>((1 + (depth + 7) / 8) * wordAt(14));
        if (size - pixelData < smallestRuns) return false;
    }
    // Uncompressed: the decoder reads missing pixels as zeros and succeeds, a black part.
    if (imageType >= 1 && imageType <= 3) {
        const long pixelBytes = static_cast<long>(wordAt(12)) * static_cast<long>(wordAt(14)) *
                                static_cast<long>((depth + 7) / 8);
        if (size - pixelData < pixelBytes) return false;
    }
    // The TGA 2.0 footer: extension area offset, developer area offset, signature.
    const long footer = size - 26;
    const char signature[18] = "TRUEVISION-XFILE.";
    char found[18] = {};
    if (footer < 0 || std::fseek(file, footer + 8, SEEK_SET) != 0 ||
        std::fread(found, 1, 18, file) != 18 || std::memcmp(found, signature, 18) != 0)
        return true;
    const std::uint32_t extension = readLittleEndian(file, footer, 4);
    const long stamp = extension != 0 ? readLittleEndian(file, extension + 486L, 4) : 0;
    if (stamp == 0 || stamp >= footer) return true;  // no postage stamp, as FreeImage reads it
    const long stampBytes = static_cast<long>(byteAt(stamp) * byteAt(stamp + 1) * depth / 8);
    return stamp + 2 + stampBytes <= footer;
}

// FreeImage's ICO decoder trusts the icon directory: a 46-byte file claiming 8387 icons, the
// first at offset 0, had it take 6 GB and 39 s (fuzz_image). Checks that the directory and every
// icon's data lie within the file, and that a bitmap icon's pixels (its XOR mask: rows padded to
// 4 bytes, half the declared height, the other half being the AND mask) fit in its data.
bool icoFitsInFile(std::FILE* file) {
    const long size = fileSize(file);
    const long count = readLittleEndian(file, 4, 2);
    const long directoryEnd = 6 + 16 * count;
    if (count == 0 || directoryEnd > size) return false;
    for (long entry = 6; entry < directoryEnd; entry += 16) {
        const long bytes = readLittleEndian(file, entry + 8, 4);
        const long offset = readLittleEndian(file, entry + 12, 4);
        if (bytes < 8 || offset < directoryEnd || offset > size - bytes) return false;
        if (readLittleEndian(file, offset, 4) == 0x474e5089) continue;  // a PNG: libpng checks it
        const long headerSize = readLittleEndian(file, offset, 4);
        const double width = static_cast<std::int32_t>(readLittleEndian(file, offset + 4, 4));
        const double height = static_cast<std::int32_t>(readLittleEndian(file, offset + 8, 4));
        const double bitsPerPixel = readLittleEndian(file, offset + 14, 2);
        const double rowBytes = std::ceil(width * bitsPerPixel / 32) * 4;
        if (headerSize < 40 || headerSize > bytes || !(width > 0) || !(height > 0) ||
            rowBytes * std::floor(height / 2) > static_cast<double>(bytes - headerSize))
            return false;
    }
    return true;
}

// FreeImage's BMP decoder reads the rows of an uncompressed file past its end as zeros, and
// succeeds: a truncated file would render as a picture with black rows. Checks that the rows the
// header declares (each padded to 4 bytes) fit between the pixel data's offset and the end.
bool bmpPixelsFitInFile(std::FILE* file) {
    const long size = fileSize(file);
    const std::uint32_t headerSize = readLittleEndian(file, 14, 4);
    std::int64_t width = 0, height = 0;
    std::uint32_t bitsPerPixel = 0, compression = 0;
    if (headerSize == 12) {  // OS/2 1.x: 16-bit sizes, never compressed
        width = readLittleEndian(file, 18, 2);
        height = readLittleEndian(file, 20, 2);
        bitsPerPixel = readLittleEndian(file, 24, 2);
    } else if (headerSize >= 40) {
        width = static_cast<std::int32_t>(readLittleEndian(file, 18, 4));
        height = static_cast<std::int32_t>(readLittleEndian(file, 22, 4));  // < 0: top-down
        bitsPerPixel = readLittleEndian(file, 28, 2);
        compression = readLittleEndian(file, 30, 4);
    }
    constexpr std::uint32_t kUncompressed = 0, kBitFields = 3;
    // Other headers, sizes and compressions FreeImage refuses or decodes with its own checks.
    if (width <= 0 || height == 0 || bitsPerPixel == 0 ||
        (compression != kUncompressed && compression != kBitFields))
        return true;
    const std::int64_t rowBytes = (width * bitsPerPixel + 31) / 32 * 4;
    const std::int64_t pixelData =
        std::max<std::int64_t>(readLittleEndian(file, 10, 4), 14 + std::int64_t{headerSize});
    const std::int64_t room = size - pixelData;
    return room >= 0 && (height < 0 ? -height : height) <= room / rowBytes;
}

// FreeImage's PFM decoder allocates the bitmap its header declares and reads what the file
// holds: 60 bytes declaring 10000 x 10000 pixels took 1.2 GB and 10 s to give a black image.
// The rows of 32-bit floats (one or three a pixel) must fit in the file.
bool pfmPixelsFitInFile(std::FILE* file, FIBITMAP* header) {
    const std::uint64_t floats = FreeImage_GetImageType(header) == FIT_FLOAT ? 1 : 3;
    const std::uint64_t pixelBytes = std::uint64_t{FreeImage_GetWidth(header)} *
                                     FreeImage_GetHeight(header) * floats * sizeof(float);
    return pixelBytes <= static_cast<std::uint64_t>(fileSize(file));
}

// FreeImage's PNM decoders (PBM, PGM, PPM) allocate the bitmap the header declares and read on
// past the end of the file: 43 bytes declaring 9000 x 10000 grey pixels took 10 s under the
// sanitizers (fuzz_image, in CI). The samples declared must fit in what follows the header: in a
// binary file, their bytes; in a text file, a character and a separator each (FreeImage reads a
// separator after every value, the last included, and between P1's bits too). A header that is
// not PNM's is left to FreeImage.
bool pnmPixelsFitInFile(std::FILE* file) {
    std::rewind(file);
    char magic[2] = {};
    if (std::fread(magic, 1, 2, file) != 2 || magic[0] != 'P' || magic[1] < '1' || magic[1] > '6')
        return true;
    const int kind = magic[1] - '0';
    // A header number as FreeImage reads it: the digits after anything else, # comments skipped,
    // held at 10^18 (the character after it is consumed).
    const auto number = [file](double& value) {
        int c = std::fgetc(file);
        while (c != EOF && !std::isdigit(c)) {
            if (c == '#')
                while (c != EOF && c != '\n' && c != '\r')
                    c = std::fgetc(file);
            c = std::fgetc(file);
        }
        bool digits = false;
        for (value = 0; c != EOF && std::isdigit(c); c = std::fgetc(file)) {
            value = std::min(1e18, value * 10 + (c - '0'));
            digits = true;
        }
        return digits;
    };
    double w = 0, h = 0, maxValue = 1;
    if (!number(w) || !number(h) || ((kind != 1 && kind != 4) && !number(maxValue))) return true;
    const long start = std::ftell(file);
    const long size = fileSize(file);
    if (start < 0 || size < start) return true;
    // In double: the product of the sides could overflow 64 bits.
    const double samples = w * h * (kind == 3 || kind == 6 ? 3 : 1);
    double least = 0;
    if (kind == 4)
        least = std::ceil(w / 8) * h;
    else if (kind >= 5)
        least = samples * (maxValue > 255 ? 2 : 1);
    else
        least = 2 * samples;
    return least <= static_cast<double>(size - start);
}

// Why FreeImage must not see the file, or "" when it may.
std::string damageFreeImageMisses(std::FILE* file, FREE_IMAGE_FORMAT format) {
    if (format == FIF_EXR && !exrHeadersFitInFile(file))
        return "a header attribute runs past the end of the file";
    if (format == FIF_TARGA && !tgaHeaderIsValid(file))
        return "its header's image type, pixel depth or colour map is not one TGA defines";
    if (format == FIF_TARGA && !tgaIsSafeToDecode(file))
        return "its pixel data or thumbnail is cut short";
    if (format == FIF_ICO && !icoFitsInFile(file))
        return "its icon directory, or an icon's pixels, run past the end of the file";
    if (format == FIF_BMP && !bmpPixelsFitInFile(file))
        return "its pixel data ends before the rows its header declares";
    const bool pnm = format == FIF_PBM || format == FIF_PBMRAW || format == FIF_PGM ||
                     format == FIF_PGMRAW || format == FIF_PPM || format == FIF_PPMRAW;
    if (pnm && !pnmPixelsFitInFile(file))
        return "its pixel data ends before the rows its header declares";
    return "";
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

// Texel x of a scanline of a float image, greyscale replicated and alpha dropped. NaN and
// infinities are no colour, and would spread through every filter: they read as 0.
Color floatTexel(FREE_IMAGE_TYPE type, const BYTE* scanline, int x) {
    const auto finite = [](float v) { return std::isfinite(v) ? v : 0.0f; };
    switch (type) {
        case FIT_FLOAT:
            return Color(finite(reinterpret_cast<const float*>(scanline)[x]));
        case FIT_RGBAF: {
            const FIRGBAF& p = reinterpret_cast<const FIRGBAF*>(scanline)[x];
            return {finite(p.red), finite(p.green), finite(p.blue)};
        }
        default: {
            const FIRGBF& p = reinterpret_cast<const FIRGBF*>(scanline)[x];
            return {finite(p.red), finite(p.green), finite(p.blue)};
        }
    }
}

// Why an image of this size is not read, or "" when it is.
std::string sizeBeyondLimits(unsigned width, unsigned height) {
    if (width <= ImageReader::kMaxSide && height <= ImageReader::kMaxSide &&
        static_cast<unsigned long long>(width) * height <= ImageReader::kMaxPixels)
        return "";
    return "it is " + std::to_string(width) + " x " + std::to_string(height) + " pixels; at most " +
           std::to_string(ImageReader::kMaxSide) + " a side and " +
           std::to_string(ImageReader::kMaxPixels) + " in all are read";
}

bool isFloat(FREE_IMAGE_TYPE type) {
    return type == FIT_FLOAT || type == FIT_RGBF || type == FIT_RGBAF;
}

}  // namespace

Image ImageReader::read(const std::filesystem::path& path, Content content) {
    const std::string name = path.string();
    std::error_code ignored;
    if (std::filesystem::is_directory(path, ignored))
        throw InputError(name, "cannot open the image (a folder, not a file)");
    const File file(std::fopen(name.c_str(), "rb"));
    if (!file)
        throw InputError(name,
                         "cannot open the image (" + std::generic_category().message(errno) + ")");

    const FREE_IMAGE_FORMAT format = formatOf(file.get(), name);
    if (format == FIF_UNKNOWN || !FreeImage_FIFSupportsReading(format))
        throw InputError(name, "cannot read the image (unknown or corrupt format)");

    const auto corrupt = [&](const std::string& detail) {
        return InputError(name, std::string("cannot read the image (corrupt or truncated ") +
                                    FreeImage_GetFormatFromFIF(format) + " file" +
                                    (detail.empty() ? "" : ": " + detail) + ")");
    };
    if (const std::string damage = damageFreeImageMisses(file.get(), format); !damage.empty())
        throw corrupt(damage);
    std::rewind(file.get());

    startCapturingFreeImageMessages();
    shareExrWorkAmongThreads(format);
    const auto checkSize = [&](FIBITMAP* image) {
        const std::string beyond =
            sizeBeyondLimits(FreeImage_GetWidth(image), FreeImage_GetHeight(image));
        if (!beyond.empty()) throw InputError(name, "cannot read the image (" + beyond + ")");
    };
    if (FreeImage_FIFSupportsNoPixels(format)) {
        // The header alone first: its size decides whether the pixels are decoded at all.
        FreeImageBitmap header;
        try {
            header.reset(FreeImage_LoadFromHandle(format, ioFor(format), file.get(),
                                                  loadFlags(format) | FIF_LOAD_NOPIXELS));
        } catch (const std::exception& e) {
            throw corrupt(e.what());
        }
        if (!header) throw corrupt(lastFreeImageMessage());
        checkSize(header.get());
        if (format == FIF_PFM && !pfmPixelsFitInFile(file.get(), header.get()))
            throw corrupt("its pixel data ends before the rows its header declares");
        std::rewind(file.get());
    }
    FreeImageBitmap bitmap;
    try {
        bitmap.reset(
            FreeImage_LoadFromHandle(format, ioFor(format), file.get(), loadFlags(format)));
    } catch (const std::exception& e) {
        // From a C++ decoder inside FreeImage (OpenEXR): std::bad_alloc for a size that a damaged
        // file claims, for example.
        throw corrupt(e.what());
    }
    if (!bitmap || FreeImage_GetWidth(bitmap.get()) == 0 || FreeImage_GetHeight(bitmap.get()) == 0)
        throw corrupt(lastFreeImageMessage());
    checkSize(bitmap.get());  // for the formats without a header-only read

    // Float images are read as they are. Integer ones become float RGB scaled to [0, 1], still
    // sRGB-encoded; bitmaps other than 24-bit pass through 24 bits first (expanding palettes and
    // greyscale, dropping alpha), as FreeImage's float conversion misreads 16-bit (RGB 555, 565)
    // ones.
    if (content == Content::Alpha && FreeImage_IsTransparent(bitmap.get())) {
        // The alpha channel alone, as a greyscale image (from 32 bits for palettes).
        if (FreeImage_GetImageType(bitmap.get()) == FIT_BITMAP &&
            FreeImage_GetBPP(bitmap.get()) != 32)
            bitmap.reset(FreeImage_ConvertTo32Bits(bitmap.get()));
        if (bitmap) bitmap.reset(FreeImage_GetChannel(bitmap.get(), FICC_ALPHA));
        if (!bitmap) throw InputError(name, "cannot read the image's alpha channel");
    }
    const bool linear = isFloat(FreeImage_GetImageType(bitmap.get()));
    if (FreeImage_GetImageType(bitmap.get()) == FIT_BITMAP && FreeImage_GetBPP(bitmap.get()) != 24)
        bitmap.reset(FreeImage_ConvertTo24Bits(bitmap.get()));
    if (bitmap && !linear) bitmap.reset(FreeImage_ConvertToRGBF(bitmap.get()));
    if (!bitmap) throw InputError(name, "cannot read the image (its pixels are not colour data)");
    const FREE_IMAGE_TYPE type = FreeImage_GetImageType(bitmap.get());

    const int width = static_cast<int>(FreeImage_GetWidth(bitmap.get()));
    const int height = static_cast<int>(FreeImage_GetHeight(bitmap.get()));
    Image image(width, height);
    for (int y = 0; y < height; ++y) {
        const BYTE* scanline =
            FreeImage_GetScanLine(bitmap.get(), scanlineOfRow(format, y, height));
        for (int x = 0; x < width; ++x) {
            const Color c = floatTexel(type, scanline, x);
            image.at(x, y) = linear || content != Content::Color
                                 ? c
                                 : Color(srgbToLinear(c.r), srgbToLinear(c.g), srgbToLinear(c.b));
        }
    }
    return image;
}

void ImageReader::checkDeclaredSize(const unsigned char* bytes, std::size_t size,
                                    const std::string& name) {
    const auto close = [](FIMEMORY* memory) { FreeImage_CloseMemory(memory); };
    const std::unique_ptr<FIMEMORY, decltype(close)> memory(
        FreeImage_OpenMemory(const_cast<BYTE*>(bytes), static_cast<DWORD>(size)), close);
    if (!memory) return;
    const FREE_IMAGE_FORMAT format = FreeImage_GetFileTypeFromMemory(memory.get(), 0);
    if (format == FIF_UNKNOWN || !FreeImage_FIFSupportsNoPixels(format)) return;
    startCapturingFreeImageMessages();
    FreeImageBitmap header;
    try {
        header.reset(
            FreeImage_LoadFromMemory(format, memory.get(), loadFlags(format) | FIF_LOAD_NOPIXELS));
    } catch (const std::exception&) {
        return;  // damage the decoder will report
    }
    if (!header) return;
    if (const std::string beyond =
            sizeBeyondLimits(FreeImage_GetWidth(header.get()), FreeImage_GetHeight(header.get()));
        !beyond.empty())
        throw InputError(name, "cannot read the image (" + beyond + ")");
}

std::shared_ptr<const ImageTexture> ImageReader::readTexture(const std::filesystem::path& path,
                                                             Content content) {
    return std::make_shared<const ImageTexture>(
        std::make_shared<const MipMap>(read(path, content)));
}

}  // namespace lancer
