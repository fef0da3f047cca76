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

// Call before a FreeImage operation whose failure should be explained.
inline void startCapturingFreeImageMessages() {
    FreeImage_SetOutputMessage(recordFreeImageMessage);
    lastFreeImageMessage().clear();
}

}  // namespace lancer
