#pragma once

#include <FreeImage.h>

#include <memory>
#include <string>

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

}  // namespace lancer
