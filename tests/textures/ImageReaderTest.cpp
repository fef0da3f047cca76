// Reading image files: formats, row order, sRGB decoding of integer images, float images kept as
// they are, and clear errors (never a crash) for missing and damaged files.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <ostream>
#include <string>

#include "TextureTestSupport.h"
#include "io/ImageReader.h"
#include "math/Srgb.h"
#include "scene/InputError.h"

namespace lancer {
namespace {

using test::Bitmap;
using test::fs::path;

// The linear value of an 8-bit sRGB code.
float decoded8(int code) {
    return srgbToLinear(static_cast<float>(code) / 255.0f);
}

void expectColor(const Color& actual, const Color& expected, float tolerance) {
    EXPECT_NEAR(actual.r, expected.r, tolerance);
    EXPECT_NEAR(actual.g, expected.g, tolerance);
    EXPECT_NEAR(actual.b, expected.b, tolerance);
}

// Expects read() to throw an InputError that names the file; returns its message.
std::string expectInputError(const path& file) {
    try {
        ImageReader::read(file);
    } catch (const InputError& error) {
        const std::string message = error.what();
        EXPECT_NE(message.find(file.string()), std::string::npos) << message;
        return message;
    }
    ADD_FAILURE() << "no InputError for " << file;
    return "";
}

class ImageReaderTest : public testing::Test {
protected:
    test::TempFolder folder;
};

// A smooth picture (JPEG keeps it to within a few codes): a gentle gradient per channel.
RGBQUAD gradientCode(int x, int y) {
    return test::rgb(40 + 3 * y, 200 - 3 * x, 60 + 2 * (x + y));
}

// A way of saving a test picture: FreeImage's format and flags, and a name for the test.
struct FileFormat {
    const char* name;
    const char* extension;
    FREE_IMAGE_FORMAT format;
    int saveFlags;
};

void PrintTo(const FileFormat& f, std::ostream* out) {
    *out << f.name;
}

std::string formatName(const testing::TestParamInfo<FileFormat>& info) {
    return info.param.name;
}

const FileFormat kPng{"png", ".png", FIF_PNG, PNG_DEFAULT};
const FileFormat kBmp{"bmp", ".bmp", FIF_BMP, BMP_DEFAULT};
const FileFormat kTga{"tga", ".tga", FIF_TARGA, TARGA_DEFAULT};
const FileFormat kTgaRle{"tga_rle", ".tga", FIF_TARGA, TARGA_SAVE_RLE};
const FileFormat kTiff{"tiff", ".tif", FIF_TIFF, TIFF_DEFAULT};
const FileFormat kJpeg{"jpeg", ".jpg", FIF_JPEG, JPEG_QUALITYSUPERB};
const FileFormat kProgressiveJpeg{"progressive_jpeg", ".jpg", FIF_JPEG,
                                  JPEG_QUALITYSUPERB | JPEG_PROGRESSIVE};
const FileFormat kExr{"exr", ".exr", FIF_EXR, EXR_FLOAT};  // 32-bit floats, not halves
const FileFormat kHdr{"hdr", ".hdr", FIF_HDR, HDR_DEFAULT};
const FileFormat kPfm{"pfm", ".pfm", FIF_PFM, PFM_DEFAULT};
const FileFormat kFloatTiff{"float_tiff", ".tif", FIF_TIFF, TIFF_DEFAULT};

bool isFloatFormat(const FileFormat& f) {
    return f.format == FIF_EXR || f.format == FIF_HDR || f.format == FIF_PFM;
}

// Linear values beyond 1, and (but in HDR, which has no sign) negative ones.
Image floatPicture(int width, int height, bool withNegatives) {
    return test::makeImage(width, height, [&](int x, int y) {
        const float v = 0.125f * static_cast<float>(1 + x + width * y);
        return Color(v, 8 * v, withNegatives && x == width - 1 ? -v : v / 4);
    });
}

class EightBitFormatTest : public ImageReaderTest,
                           public testing::WithParamInterface<FileFormat> {};

TEST_P(EightBitFormatTest, ReadsTheTexelsDecodedFromSrgb) {
    const FileFormat& f = GetParam();
    const path file = folder / (std::string("t") + f.extension);
    test::save(test::makeBitmap8(16, 16, gradientCode), file, f.format, f.saveFlags);
    if (f.format == FIF_JPEG && (f.saveFlags & JPEG_PROGRESSIVE)) {
        ASSERT_NE(test::readBytes(file).find("\xff\xc2"), std::string::npos)
            << "no progressive frame header (SOF2) in the file";
    }

    const Image image = ImageReader::read(file);
    ASSERT_EQ(image.width(), 16);
    ASSERT_EQ(image.height(), 16);
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) {
            const RGBQUAD code = gradientCode(x, y);
            const Color& texel = image.at(x, y);
            if (f.format != FIF_JPEG) {
                EXPECT_EQ(texel, Color(decoded8(code.rgbRed), decoded8(code.rgbGreen),
                                       decoded8(code.rgbBlue)))
                    << "at " << x << ", " << y;
            } else {
                // Compared in code units, since JPEG's error is about the same at every level.
                const float tolerance = 4 / 255.0f;
                EXPECT_NEAR(linearToSrgb(texel.r), code.rgbRed / 255.0f, tolerance);
                EXPECT_NEAR(linearToSrgb(texel.g), code.rgbGreen / 255.0f, tolerance);
                EXPECT_NEAR(linearToSrgb(texel.b), code.rgbBlue / 255.0f, tolerance);
            }
        }
}

INSTANTIATE_TEST_SUITE_P(Formats, EightBitFormatTest,
                         testing::Values(kPng, kBmp, kTga, kTgaRle, kTiff, kJpeg, kProgressiveJpeg),
                         formatName);

TEST_F(ImageReaderTest, DecodesEightBitGreyFromSrgb) {
    const path file = folder / "grey.png";
    test::save(test::makeBitmap8(2, 2, [](int, int) { return test::rgb(128, 128, 128); }), file,
               FIF_PNG);
    const Image image = ImageReader::read(file);
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 2; ++x)
            EXPECT_EQ(image.at(x, y), Color(srgbToLinear(128 / 255.0f)));
}

TEST_F(ImageReaderTest, KeepsTheTopRowFirstAndTheChannelOrder) {
    const path file = folder / "corners.png";
    // Red, green on the top row; blue, white on the bottom one.
    test::save(
        test::makeBitmap8(2, 2,
                          [](int x, int y) {
                              if (y == 0)
                                  return x == 0 ? test::rgb(255, 0, 0) : test::rgb(0, 255, 0);
                              return x == 0 ? test::rgb(0, 0, 255) : test::rgb(255, 255, 255);
                          }),
        file, FIF_PNG);
    const Image image = ImageReader::read(file);
    EXPECT_EQ(image.at(0, 0), Color(1, 0, 0));
    EXPECT_EQ(image.at(1, 0), Color(0, 1, 0));
    EXPECT_EQ(image.at(0, 1), Color(0, 0, 1));
    EXPECT_EQ(image.at(1, 1), Color(1, 1, 1));
}

TEST_F(ImageReaderTest, ExpandsGreyscaleImages) {
    const path file = folder / "grey8.png";
    Bitmap bitmap(FreeImage_Allocate(3, 1, 8));  // FreeImage gives 8-bit images a grey ramp palette
    BYTE* row = FreeImage_GetScanLine(bitmap.get(), 0);
    row[0] = 0;
    row[1] = 100;
    row[2] = 255;
    test::save(bitmap, file, FIF_PNG);
    const Image image = ImageReader::read(file);
    EXPECT_EQ(image.at(0, 0), Color(0));
    EXPECT_EQ(image.at(1, 0), Color(decoded8(100)));
    EXPECT_EQ(image.at(2, 0), Color(1));
}

TEST_F(ImageReaderTest, LooksUpPalettizedImages) {
    const path file = folder / "palette.png";
    Bitmap bitmap(FreeImage_Allocate(2, 1, 8));
    RGBQUAD* palette = FreeImage_GetPalette(bitmap.get());
    palette[7] = test::rgb(250, 20, 90);
    palette[9] = test::rgb(5, 180, 60);
    BYTE* row = FreeImage_GetScanLine(bitmap.get(), 0);
    row[0] = 9;
    row[1] = 7;
    test::save(bitmap, file, FIF_PNG);
    const Image image = ImageReader::read(file);
    EXPECT_EQ(image.at(0, 0), Color(decoded8(5), decoded8(180), decoded8(60)));
    EXPECT_EQ(image.at(1, 0), Color(decoded8(250), decoded8(20), decoded8(90)));
}

// Colour ignores alpha; a cut-out mask is the alpha channel where there is one (linear, grey),
// else the values as data.
TEST_F(ImageReaderTest, ReadsAlphaOnlyAsAMask) {
    const path file = folder / "rgba.png";
    Bitmap bitmap(FreeImage_Allocate(2, 1, 32));
    BYTE* row = FreeImage_GetScanLine(bitmap.get(), 0);
    for (int x = 0; x < 2; ++x, row += 4) {
        row[FI_RGBA_RED] = 200;
        row[FI_RGBA_GREEN] = 100;
        row[FI_RGBA_BLUE] = 50;
        row[FI_RGBA_ALPHA] = x == 0 ? 0 : 128;  // transparent, half transparent
    }
    test::save(bitmap, file, FIF_PNG);
    const Image image = ImageReader::read(file);
    for (int x = 0; x < 2; ++x)
        EXPECT_EQ(image.at(x, 0), Color(decoded8(200), decoded8(100), decoded8(50)));
    const Image mask = ImageReader::read(file, ImageReader::Content::Alpha);
    EXPECT_EQ(mask.at(0, 0), Color(0));
    EXPECT_EQ(mask.at(1, 0), Color(128 / 255.0f));

    const path greyFile = folder / "grey8.png";
    Bitmap grey(FreeImage_Allocate(1, 1, 8));  // with a grey ramp palette, no transparency
    *FreeImage_GetScanLine(grey.get(), 0) = 128;
    test::save(grey, greyFile, FIF_PNG);
    EXPECT_EQ(ImageReader::read(greyFile, ImageReader::Content::Alpha).at(0, 0),
              Color(128 / 255.0f));
}

TEST_F(ImageReaderTest, DecodesSixteenBitImagesFromSrgb) {
    const path colourFile = folder / "rgb16.png";
    Bitmap colour(FreeImage_AllocateT(FIT_RGB16, 1, 1));
    *reinterpret_cast<FIRGB16*>(FreeImage_GetScanLine(colour.get(), 0)) = {1000, 32768, 65535};
    test::save(colour, colourFile, FIF_PNG);
    EXPECT_EQ(ImageReader::read(colourFile).at(0, 0),
              Color(srgbToLinear(1000 / 65535.0f), srgbToLinear(32768 / 65535.0f), 1));

    const path greyFile = folder / "grey16.png";
    Bitmap grey(FreeImage_AllocateT(FIT_UINT16, 1, 1));
    *reinterpret_cast<WORD*>(FreeImage_GetScanLine(grey.get(), 0)) = 20000;
    test::save(grey, greyFile, FIF_PNG);
    EXPECT_EQ(ImageReader::read(greyFile).at(0, 0), Color(srgbToLinear(20000 / 65535.0f)));
}

// Normal and bump maps are data: integer texels are scaled to [0, 1] and never sRGB-decoded,
// 8 bits and 16 alike; float images are the same read either way.
TEST_F(ImageReaderTest, ReadsIntegerMapsAsLinearData) {
    const path colourFile = folder / "rgb16.png";
    Bitmap colour(FreeImage_AllocateT(FIT_RGB16, 1, 1));
    *reinterpret_cast<FIRGB16*>(FreeImage_GetScanLine(colour.get(), 0)) = {1000, 32768, 65535};
    test::save(colour, colourFile, FIF_PNG);
    EXPECT_EQ(ImageReader::read(colourFile, ImageReader::Content::Data).at(0, 0),
              Color(1000 / 65535.0f, 32768 / 65535.0f, 1));

    const path greyFile = folder / "grey8.png";
    Bitmap grey(FreeImage_Allocate(1, 1, 8));  // with a grey ramp palette
    *FreeImage_GetScanLine(grey.get(), 0) = 128;
    test::save(grey, greyFile, FIF_PNG);
    EXPECT_EQ(ImageReader::read(greyFile, ImageReader::Content::Data).at(0, 0),
              Color(128 / 255.0f));
    EXPECT_EQ(ImageReader::read(greyFile).at(0, 0), Color(srgbToLinear(128 / 255.0f)));
}

// FreeImage's own conversion to float misreads these (as if they had 3 bytes a texel).
TEST_F(ImageReaderTest, ReadsSixteenBitRgbBitmaps) {
    const Bitmap truecolour = test::makeBitmap8(
        2, 1, [](int x, int) { return x == 0 ? test::rgb(255, 0, 0) : test::rgb(0, 0, 255); });
    const path bmp = folder / "rgb565.bmp";
    test::save(Bitmap(FreeImage_ConvertTo16Bits565(truecolour.get())), bmp, FIF_BMP);
    const path tga = folder / "rgb555.tga";
    test::save(Bitmap(FreeImage_ConvertTo16Bits555(truecolour.get())), tga, FIF_TARGA);
    for (const path& file : {bmp, tga}) {
        const Image image = ImageReader::read(file);
        EXPECT_EQ(image.at(0, 0), Color(1, 0, 0)) << file;
        EXPECT_EQ(image.at(1, 0), Color(0, 0, 1)) << file;
    }
}

class FloatFormatTest : public ImageReaderTest, public testing::WithParamInterface<FileFormat> {};

TEST_P(FloatFormatTest, KeepsTheLinearValues) {
    const FileFormat& f = GetParam();
    const Image written = floatPicture(4, 3, f.format != FIF_HDR);
    const path file = folder / (std::string("t") + f.extension);
    if (f.format == FIF_PFM)
        test::writePfm(written, file);
    else
        test::save(test::makeBitmapFloat(written), file, f.format, f.saveFlags);

    const Image image = ImageReader::read(file);
    ASSERT_EQ(image.width(), 4);
    ASSERT_EQ(image.height(), 3);
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 4; ++x) {
            const Color& expected = written.at(x, y);
            if (f.format != FIF_HDR) {
                EXPECT_EQ(image.at(x, y), expected) << "at " << x << ", " << y;
            } else {
                // RGBE: 8-bit mantissas under one shared exponent, so an error relative to the
                // largest channel.
                expectColor(image.at(x, y), expected, 0.01f * expected.maxComponent());
            }
        }
}

INSTANTIATE_TEST_SUITE_P(Formats, FloatFormatTest, testing::Values(kExr, kPfm, kFloatTiff, kHdr),
                         formatName);

TEST_F(ImageReaderTest, ExpandsFloatGreyscaleImages) {
    const path file = folder / "grey.exr";
    Bitmap bitmap(FreeImage_AllocateT(FIT_FLOAT, 1, 1));
    *reinterpret_cast<float*>(FreeImage_GetScanLine(bitmap.get(), 0)) = 2.75f;
    test::save(bitmap, file, FIF_EXR, EXR_FLOAT);
    EXPECT_EQ(ImageReader::read(file).at(0, 0), Color(2.75f));
}

TEST_F(ImageReaderTest, ReadsNonFiniteFloatsAsZero) {
    const path file = folder / "nan.exr";
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float infinity = std::numeric_limits<float>::infinity();
    test::save(test::makeBitmapFloat(
                   test::makeImage(1, 1, [&](int, int) { return Color(nan, infinity, 0.5f); })),
               file, FIF_EXR, EXR_FLOAT);
    EXPECT_EQ(ImageReader::read(file).at(0, 0), Color(0, 0, 0.5f));
}

TEST(ImageReaderRealFileTest, ReadsAProgressiveJpeg) {
    const Image image = ImageReader::read(test::dataFolder() / "engineflare1.jpg");
    EXPECT_EQ(image.width(), 128);
    EXPECT_EQ(image.height(), 128);
    // A flare: bright in the middle, dark in the corners.
    EXPECT_GT(image.at(64, 64).average(), 0.5f);
    EXPECT_LT(image.at(0, 0).average(), 0.05f);
}

TEST(ImageReaderRealFileTest, ReadsABaselineJpegOfOddWidth) {
    const Image image = ImageReader::read(test::dataFolder() / "SpiderTex.jpg");
    EXPECT_EQ(image.width(), 249);
    EXPECT_EQ(image.height(), 250);
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x) {
            const Color& c = image.at(x, y);
            ASSERT_TRUE(c.r >= 0 && c.r <= 1 && c.g >= 0 && c.g <= 1 && c.b >= 0 && c.b <= 1)
                << "at " << x << ", " << y;
        }
}

// ---- Errors: a clear InputError naming the file, never a crash.

TEST_F(ImageReaderTest, MissingFileIsAnError) {
    const std::string message = expectInputError(folder / "absent.png");
    EXPECT_NE(message.find("cannot open the image"), std::string::npos) << message;
    EXPECT_NE(message.find("No such file"), std::string::npos) << message;
}

TEST_F(ImageReaderTest, FolderIsAnError) {
    const path subfolder = folder / "textures.png";
    test::fs::create_directory(subfolder);
    const std::string message = expectInputError(subfolder);
    EXPECT_NE(message.find("folder"), std::string::npos) << message;
}

TEST_F(ImageReaderTest, TextFileNamedPngIsAnError) {
    const path file = folder / "notes.png";
    test::writeBytes(file, "this is not a picture\n");
    const std::string message = expectInputError(file);
    EXPECT_NE(message.find("cannot read the image"), std::string::npos) << message;
}

TEST_F(ImageReaderTest, EmptyFileIsAnError) {
    const path file = folder / "empty.jpg";
    test::writeBytes(file, "");
    expectInputError(file);
}

TEST_F(ImageReaderTest, FileWithUnknownFormatIsAnError) {
    const path file = folder / "texture.xyz";
    test::writeBytes(file, std::string(64, '\x01'));
    const std::string message = expectInputError(file);
    EXPECT_NE(message.find("unknown or corrupt format"), std::string::npos) << message;
}

TEST_F(ImageReaderTest, TruncatedPngIsAnError) {
    const path whole = folder / "whole.png";
    test::save(test::makeBitmap8(32, 32, gradientCode), whole, FIF_PNG);
    const std::string bytes = test::readBytes(whole);
    const path truncated = folder / "truncated.png";
    test::writeBytes(truncated, bytes.substr(0, bytes.size() / 2));
    const std::string message = expectInputError(truncated);
    EXPECT_NE(message.find("corrupt or truncated PNG"), std::string::npos) << message;
}

TEST_F(ImageReaderTest, TruncatedBmpIsAnError) {
    // FreeImage reads the missing rows as black and succeeds.
    const path whole = folder / "whole.bmp";
    test::save(test::makeBitmap8(32, 32, gradientCode), whole, FIF_BMP);
    const std::string bytes = test::readBytes(whole);
    const path truncated = folder / "truncated.bmp";
    test::writeBytes(truncated, bytes.substr(0, bytes.size() - 1));
    const std::string message = expectInputError(truncated);
    EXPECT_NE(message.find("corrupt or truncated BMP file: its pixel data ends before the rows"),
              std::string::npos)
        << message;
}

// FreeImage's PNM decoders read on past the end of a file: a PBM, PGM or PPM, text or binary,
// must hold the samples its header declares (found by fuzz_image: 43 bytes declaring 9000 x 10000
// grey pixels took 10 s under the sanitizers). Each kind read whole with exactly the bytes its
// samples need, and refused one byte short of them.
TEST_F(ImageReaderTest, PnmShortOfItsPixelsIsAnError) {
    struct Case {
        const char* name;
        std::string header;
        std::size_t bodyBytes;  // the least the declared samples need
        char filler;            // what the body is made of
    };
    const Case cases[] = {
        {"p1.pbm", "P1\n13 3\n", 2 * 13 * 3, '1'},
        {"p2.pgm", "P2\n# a comment\n13 3\n255\n", 2 * 13 * 3, '7'},
        {"p3.ppm", "P3\n13 3\n255\n", 2 * 13 * 3 * 3, '7'},
        {"p4.pbm", "P4\n13 3\n", 2 * 3, '\x55'},  // rows of 13 bits in 2 bytes
        {"p5.pgm", "P5\n13 3\n255\n", 13 * 3, '\x40'},
        {"p5-16.pgm", "P5\n13 3\n65535\n", 2 * 13 * 3, '\x40'},
        {"p6.ppm", "P6\n13 3\n255\n", 3 * 13 * 3, '\x40'},
    };
    for (const Case& c : cases) {
        std::string body(c.bodyBytes, c.filler);
        if (c.name[1] <= '3')  // text: "7 7 7 ... 7 "
            for (std::size_t i = 1; i < body.size(); i += 2)
                body[i] = ' ';
        const path whole = folder / (std::string("whole-") + c.name);
        test::writeBytes(whole, c.header + body);
        const Image image = ImageReader::read(whole);
        EXPECT_EQ(image.width(), 13) << c.name;
        EXPECT_EQ(image.height(), 3) << c.name;
        const path cut = folder / (std::string("cut-") + c.name);
        test::writeBytes(cut, c.header + body.substr(0, body.size() - 1));
        const std::string message = expectInputError(cut);
        EXPECT_NE(message.find("its pixel data ends before the rows its header declares"),
                  std::string::npos)
            << c.name << ": " << message;
    }
}

// A run-length TGA header (true colour, 24 bits, bottom-up) declaring `width` x `height` pixels,
// followed by `dataBytes` bytes of runs (at least the 4 bytes a row that tgaIsSafeToDecode asks).
std::string tgaHeader(unsigned width, unsigned height, std::size_t dataBytes) {
    std::string bytes(18, '\0');
    bytes[2] = 10;  // run-length true colour
    bytes[12] = static_cast<char>(width & 0xff);
    bytes[13] = static_cast<char>(width >> 8);
    bytes[14] = static_cast<char>(height & 0xff);
    bytes[15] = static_cast<char>(height >> 8);
    bytes[16] = 24;
    return bytes + std::string(dataBytes, '\x40');
}

// The sizes headers declare are checked before any pixel is decoded: these files are small, and
// their pixels would take gigabytes (or, for the first, be read as zeros and rendered).
TEST_F(ImageReaderTest, ImageWiderThanTheLimitIsRefusedBeforeDecoding) {
    const path file = folder / "wide.tga";
    test::writeBytes(file, tgaHeader(ImageReader::kMaxSide + 1, 1, 300));
    const std::string message = expectInputError(file);
    EXPECT_NE(message.find("it is 32769 x 1 pixels; at most 32768 a side"), std::string::npos)
        << message;
}

TEST_F(ImageReaderTest, PfmTallerThanTheLimitIsRefusedBeforeDecoding) {
    const path file = folder / "tall.pfm";
    test::writeBytes(file, "PF\n1 40000\n-1\n" + std::string(120, '\0'));
    const std::string message = expectInputError(file);
    EXPECT_NE(message.find("it is 1 x 40000 pixels"), std::string::npos) << message;
}

TEST_F(ImageReaderTest, ImageOfMorePixelsThanTheLimitIsRefusedBeforeDecoding) {
    // 20000 x 20000: each side within the limit, 4e8 pixels in all (4.8 GB as float RGB).
    const path file = folder / "large.tga";
    test::writeBytes(file, tgaHeader(20000, 20000, 4 * 20000));
    const std::string message = expectInputError(file);
    EXPECT_NE(message.find("it is 20000 x 20000 pixels"), std::string::npos) << message;
    EXPECT_NE(message.find("268435456 in all"), std::string::npos) << message;
}

TEST_F(ImageReaderTest, TinyBmpDeclaringMillionsOfPixelsIsRefusedBeforeDecoding) {
    // The 233 bytes declaring 67 million x 6 pixels: FreeImage allocated 9.45 GB.
    const auto le32 = [](std::uint32_t v) {
        std::string b(4, '\0');
        for (int i = 0; i < 4; ++i)
            b[static_cast<std::size_t>(i)] = static_cast<char>(v >> (8 * i) & 0xff);
        return b;
    };
    std::string bytes = "BM" + le32(233) + le32(0) + le32(54) + le32(40) + le32(67'108'864) +
                        le32(6) + std::string("\x01\x00\x18\x00", 4) + le32(0) + le32(0) + le32(0) +
                        le32(0) + le32(0) + le32(0);
    bytes += std::string(233 - bytes.size(), '\x40');
    const path file = folder / "tiny.bmp";
    test::writeBytes(file, bytes);
    expectInputError(file);
}

// Damage that FreeImage's decoders do not survive, caught before they see it.

TEST_F(ImageReaderTest, ExrHeaderCutShortIsAnError) {
    // OpenEXR, reading through FreeImage, never learns that the file has ended: it used to loop
    // forever.
    const path whole = folder / "whole.exr";
    test::save(test::makeBitmapFloat(floatPicture(4, 4, false)), whole, FIF_EXR, EXR_FLOAT);
    const path cut = folder / "cut.exr";
    test::writeBytes(cut, test::readBytes(whole).substr(0, 40));
    expectInputError(cut);
}

TEST_F(ImageReaderTest, ExrAttributeLargerThanTheFileIsAnError) {
    // OpenEXR would allocate the gigabytes that the damaged size claims.
    const path whole = folder / "whole.exr";
    test::save(test::makeBitmapFloat(floatPicture(4, 4, false)), whole, FIF_EXR, EXR_FLOAT);
    std::string bytes = test::readBytes(whole);
    const std::size_t size = bytes.find("chlist") + 7;  // the first attribute's size
    bytes[size + 3] = '\x7f';
    const path damaged = folder / "damaged.exr";
    test::writeBytes(damaged, bytes);
    const std::string message = expectInputError(damaged);
    EXPECT_NE(message.find("past the end of the file"), std::string::npos) << message;
}

TEST_F(ImageReaderTest, TgaRunLengthDataCutShortIsAnError) {
    // An ID field of 255 bytes leaves too little data for the rows: FreeImage returned a bitmap
    // that it had freed.
    const path whole = folder / "whole.tga";
    test::save(test::makeBitmap8(8, 8, gradientCode), whole, FIF_TARGA, TARGA_SAVE_RLE);
    std::string bytes = test::readBytes(whole);
    bytes[0] = '\xff';
    const path damaged = folder / "damaged.tga";
    test::writeBytes(damaged, bytes);
    expectInputError(damaged);
}

TEST_F(ImageReaderTest, UncompressedTgaCutShortIsAnError) {
    // FreeImage read the missing pixels as black and succeeded.
    const path whole = folder / "whole.tga";
    test::save(test::makeBitmap8(8, 8, gradientCode), whole, FIF_TARGA, TARGA_DEFAULT);
    const std::string bytes = test::readBytes(whole);
    const path cut = folder / "cut.tga";
    test::writeBytes(cut, bytes.substr(0, 18 + 8 * 8 * 3 - 1));
    const std::string message = expectInputError(cut);
    EXPECT_NE(message.find("corrupt or truncated TARGA file"), std::string::npos) << message;
}

TEST_F(ImageReaderTest, TgaPostageStampLargerThanItsSpaceIsAnError) {
    // A TGA 2.0 thumbnail claiming 255 x 255 pixels in a few bytes: FreeImage copied them from
    // beyond its buffer.
    Bitmap bitmap = test::makeBitmap8(8, 8, gradientCode);
    const Bitmap thumbnail = test::makeBitmap8(2, 2, gradientCode);
    FreeImage_SetThumbnail(bitmap.get(), thumbnail.get());
    const path whole = folder / "whole.tga";
    test::save(bitmap, whole, FIF_TARGA, TARGA_SAVE_RLE);
    std::string bytes = test::readBytes(whole);
    const auto littleEndian32 = [&](std::size_t at) {
        std::uint32_t value = 0;
        for (std::size_t i = 4; i-- > 0;)
            value = value << 8 | static_cast<unsigned char>(bytes[at + i]);
        return value;
    };
    const std::size_t extensionArea = littleEndian32(bytes.size() - 26);
    const std::size_t stamp = littleEndian32(extensionArea + 486);
    ASSERT_EQ(bytes[stamp], 2) << "the thumbnail's width, where the format puts it";
    bytes[stamp] = bytes[stamp + 1] = '\xff';
    const path damaged = folder / "damaged.tga";
    test::writeBytes(damaged, bytes);
    expectInputError(damaged);
}

// Every prefix of a small file of each format, and the file with each byte changed in turn: each
// one either reads (some decoders fill in what is missing) or throws InputError.
class DamagedFileTest : public ImageReaderTest, public testing::WithParamInterface<FileFormat> {
protected:
    static void expectReadOrInputError(const path& file, const std::string& what) {
        try {
            const Image image = ImageReader::read(file);
            EXPECT_GE(image.width(), 1) << what;
        } catch (const InputError&) {
        } catch (const std::exception& e) {
            ADD_FAILURE() << what << ": not an InputError: " << e.what();
        }
    }
};

// The bytes of a file that hold its width and height, which the test leaves alone: a damaged size
// makes a valid, huge picture, which the decoders fill at a cost of time and gigabytes without
// testing anything more.
struct ByteRange {
    std::size_t begin = 0, end = 0;
    bool contains(std::size_t i) const { return i >= begin && i < end; }
};
ByteRange sizeBytes(const FileFormat& f, const std::string& bytes) {
    switch (f.format) {
        case FIF_BMP:
            return {18, 26};  // BITMAPINFOHEADER biWidth, biHeight
        case FIF_EXR: {
            // The value of the dataWindow attribute (name, type "box2i", length, 16 bytes).
            const std::size_t name = bytes.find("dataWindow");
            return {name + 21, name + 37};
        }
        default:
            return {};
    }
}

TEST_P(DamagedFileTest, ReadsOrThrowsInputError) {
    const FileFormat& f = GetParam();
    const path whole = folder / (std::string("whole") + f.extension);
    test::save(isFloatFormat(f) ? test::makeBitmapFloat(floatPicture(8, 8, false))
                                : test::makeBitmap8(8, 8, gradientCode),
               whole, f.format, f.saveFlags);
    const std::string bytes = test::readBytes(whole);
    const path damaged = folder / (std::string("damaged") + f.extension);
    for (std::size_t length = 0; length < bytes.size(); ++length) {
        test::writeBytes(damaged, bytes.substr(0, length));
        expectReadOrInputError(damaged, "the first " + std::to_string(length) + " bytes");
    }
    const ByteRange size = sizeBytes(f, bytes);
    for (std::size_t at = 0; at < bytes.size(); ++at) {
        if (size.contains(at)) continue;
        std::string changed = bytes;
        changed[at] = static_cast<char>(changed[at] ^ 0x5a);
        test::writeBytes(damaged, changed);
        expectReadOrInputError(damaged, "byte " + std::to_string(at) + " changed");
    }
}

INSTANTIATE_TEST_SUITE_P(Formats, DamagedFileTest,
                         testing::Values(kPng, kJpeg, kProgressiveJpeg, kBmp, kTgaRle, kTiff, kExr,
                                         kHdr, kPfm),
                         formatName);

}  // namespace
}  // namespace lancer
