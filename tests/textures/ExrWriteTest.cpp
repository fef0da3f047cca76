// EXR outputs are compressed on the threads the render may use (OpenEXR's pool, inside
// FreeImage, sized by lancer), into the same bytes as on one thread, and read back exactly.

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cstdint>

#include "TextureTestSupport.h"
#include "io/ImageReader.h"
#include "io/ImageWriter.h"

#if LANCER_WITH_OPENEXR
#include <ImfThreading.h>
#endif

namespace lancer {
namespace {

// Noise, which ZIP compression has to work at, in every channel and block of lines.
Image noisyImage() {
    return test::makeImage(320, 200, [](int x, int y) {
        std::uint32_t h =
            static_cast<std::uint32_t>(x) * 73856093u ^ static_cast<std::uint32_t>(y) * 19349663u;
        h ^= h >> 13;
        h *= 0x5bd1e995u;
        h ^= h >> 15;
        const auto channel = [&](int shift) {
            return static_cast<float>(h >> shift & 0xff) / 37.0f;
        };
        return Color(channel(0), channel(8), channel(16));
    });
}

TEST(ExrWrite, IsCompressedOnTheRendersThreadsIntoTheSameBytesAsOnOne) {
#if LANCER_WITH_OPENEXR
    const test::TempFolder folder;
    const Image image = noisyImage();
    ImageWriter::write(image, folder / "pool.exr");
    // The pool has as many threads as the render may use (none when that is one: the caller
    // compresses).
    const std::size_t threads =
        tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism);
    EXPECT_EQ(Imf::globalThreadCount(), threads > 1 ? static_cast<int>(threads) : 0);

    Imf::setGlobalThreadCount(0);
    ImageWriter::write(image, folder / "alone.exr");
    EXPECT_EQ(test::readBytes(folder / "pool.exr"), test::readBytes(folder / "alone.exr"));

    const Image read = ImageReader::read(folder / "pool.exr");
    ASSERT_EQ(read.width(), image.width());
    ASSERT_EQ(read.height(), image.height());
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            ASSERT_EQ(read.at(x, y), image.at(x, y)) << "at " << x << ", " << y;
#else
    GTEST_SKIP() << "built without OpenEXR's headers: EXR files are compressed on one thread";
#endif
}

}  // namespace
}  // namespace lancer
