#pragma once

#include <FreeImage.h>

#include <memory>
#include <string>

#if LANCER_WITH_OPENEXR
#include <ImfThreading.h>
#include <tbb/global_control.h>
#endif

namespace lancer {

// What the image reader and writer share about FreeImage: bitmaps that free themselves, and the
// messages FreeImage reports failures through (a global callback), caught per thread.

struct FreeImageBitmapDeleter {
    void operator()(FIBITMAP* bitmap) const { FreeImage_Unload(bitmap); }
};
using FreeImageBitmap = std::unique_ptr<FIBITMAP, FreeImageBitmapDeleter>;

// The last message FreeImage reported on this thread.
inline std::string& lastFreeImageMessage() {
    thread_local std::string message;
    return message;
}

inline void DLL_CALLCONV recordFreeImageMessage(FREE_IMAGE_FORMAT, const char* message) {
    lastFreeImageMessage() = message ? message : "";
}

// The scanline of a FreeImage bitmap that holds image row y (rows counted from the top). FreeImage
// stores rows bottom-up, scanline 0 at the bottom, except that its PFM plugin reads and writes the
// file's first row as the top one, while PFM stores the bottom row first (netpbm's and Debevec's
// definition, which Mitsuba and pbrt follow): bitmaps of PFM files are upside down.
inline unsigned scanlineOfRow(FREE_IMAGE_FORMAT format, int y, int height) {
    return static_cast<unsigned>(format == FIF_PFM ? y : height - 1 - y);
}

// Call before a FreeImage operation whose failure should be explained.
inline void startCapturingFreeImageMessages() {
    FreeImage_SetOutputMessage(recordFreeImageMessage);
    lastFreeImageMessage().clear();
}

// Call before FreeImage reads or writes a file of `format`. OpenEXR, which FreeImage reads and
// writes EXR files with, compresses and decompresses a file's blocks of lines on the threads of
// its global pool, which is empty unless the program sizes it: sized here, once, before the first
// EXR file is read or written (its threads start then), to the threads the render may use
// (--threads, set before any image is read). A 1920 x 1080 render's EXR takes 0.35 s to compress
// on one thread and 0.2 s on two, into the same bytes. (A build without OpenEXR's headers writes
// the same files on one thread.)
inline void shareExrWorkAmongThreads([[maybe_unused]] FREE_IMAGE_FORMAT format) {
#if LANCER_WITH_OPENEXR
    if (format != FIF_EXR) return;
    static const bool sized = [] {
        const std::size_t threads =
            tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism);
        Imf::setGlobalThreadCount(threads > 1 ? static_cast<int>(threads) : 0);
        return true;
    }();
    (void)sized;
#endif
}

}  // namespace lancer
