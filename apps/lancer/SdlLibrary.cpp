#include "SdlLibrary.h"

#if !defined(_WIN32)
#include <dlfcn.h>
#endif

namespace lancer {

namespace {

#if defined(__APPLE__)
constexpr const char* kLibraryName = "libSDL2-2.0.0.dylib";
#else
constexpr const char* kLibraryName = "libSDL2-2.0.so.0";
#endif

}  // namespace

const SdlLibrary& SdlLibrary::instance() {
    static const SdlLibrary library;
    return library;
}

SdlLibrary::SdlLibrary() {
#if defined(_WIN32)
#define LANCER_SDL_LINK(name) name = &::name;
#else
    // Never closed: SDL stays until the program ends.
    void* library = dlopen(kLibraryName, RTLD_NOW | RTLD_LOCAL);
    if (!library) {
        const char* reason = dlerror();
        error_ = "cannot load SDL2: " + std::string(reason ? reason : kLibraryName);
        return;
    }
#define LANCER_SDL_LINK(name)                                                         \
    name = reinterpret_cast<decltype(&::name)>(dlsym(library, #name));                \
    if (!name) {                                                                      \
        error_ = "cannot load SDL2: " + std::string(kLibraryName) + " has no " #name; \
        return;                                                                       \
    }
#endif
    LANCER_SDL_FUNCTIONS(LANCER_SDL_LINK)
#undef LANCER_SDL_LINK
}

}  // namespace lancer
