#pragma once

#include <SDL.h>

#include <string>

namespace lancer {

// The SDL2 functions the viewer calls.
#define LANCER_SDL_FUNCTIONS(X)   \
    X(SDL_CreateRenderer)         \
    X(SDL_CreateTexture)          \
    X(SDL_CreateWindow)           \
    X(SDL_Delay)                  \
    X(SDL_DestroyRenderer)        \
    X(SDL_DestroyTexture)         \
    X(SDL_DestroyWindow)          \
    X(SDL_GetDisplayUsableBounds) \
    X(SDL_GetError)               \
    X(SDL_GetNumVideoDrivers)     \
    X(SDL_GetVersion)             \
    X(SDL_GetVideoDriver)         \
    X(SDL_GetWindowSize)          \
    X(SDL_HasEvents)              \
    X(SDL_Init)                   \
    X(SDL_PollEvent)              \
    X(SDL_PumpEvents)             \
    X(SDL_Quit)                   \
    X(SDL_RenderClear)            \
    X(SDL_RenderCopy)             \
    X(SDL_RenderPresent)          \
    X(SDL_SetHint)                \
    X(SDL_SetTextureScaleMode)    \
    X(SDL_SetWindowTitle)         \
    X(SDL_ShowWindow)             \
    X(SDL_UpdateTexture)

// The SDL2 library, loaded when first asked for (a window, or lancer --version) rather than with
// the program: SDL2 brings some forty libraries of its own (X11, Wayland, audio), and loading them
// took 5 of the 11 ms that a run of lancer spent starting up, in runs that mostly open no window.
// (On Windows it is linked as usual, so that vcpkg puts SDL2.dll beside the program.) Its
// functions are members of the same names: sdl.SDL_Init(...).
class SdlLibrary {
public:
    // The library, loaded by the first call; see loaded().
    static const SdlLibrary& instance();

    // Whether every function was found; if not, error() says why.
    bool loaded() const { return error_.empty(); }
    const std::string& error() const { return error_; }

#define LANCER_SDL_MEMBER(name) decltype(&::name) name = nullptr;
    LANCER_SDL_FUNCTIONS(LANCER_SDL_MEMBER)
#undef LANCER_SDL_MEMBER

private:
    SdlLibrary();

    std::string error_;
};

}  // namespace lancer
