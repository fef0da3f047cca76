#pragma once

#include <chrono>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "ViewerEvent.h"
#include "image/Image.h"
#include "render/Renderer.h"
#include "render/ToneMapper.h"

struct SDL_Renderer;
struct SDL_Texture;
struct SDL_Window;

namespace lancer {

class SdlLibrary;

// A window (SDL2) showing an image while something computes it. The image and the status in the
// title can be changed from any thread (a renderer's workers); the window itself belongs to the
// thread that opened it, which must call poll() often to keep it alive and up to date.
class Viewer {
public:
    // A window titled `name` for a width x height image, scaled down to fit the screen if larger,
    // showing it as 8-bit outputs store it (through `toneMapper`). Null, with the reason in
    // `error`, when there is no display to open it on or the SDL2 library cannot be loaded.
    static std::unique_ptr<Viewer> open(const std::string& name, int width, int height,
                                        const ToneMapper& toneMapper, std::string& error);
    // "SDL2 2.26.5": the version of the SDL library loaded, for lancer --version.
    static std::string libraryVersion();
    ~Viewer();
    Viewer(const Viewer&) = delete;
    Viewer& operator=(const Viewer&) = delete;

    // --- any thread ---

    // Shows `film`'s pixels in `tile` (a copy: film may change afterwards).
    void showTile(const Image& film, const PixelWindow& tile);
    void showFilm(const Image& film);
    // The title becomes "NAME  STATUS".
    void setStatus(const std::string& status);
    // What the window shows, in linear radiance (before the tone mapping).
    Image image() const;
    const ToneMapper& toneMapper() const { return toneMapper_; }

    // --- the thread that opened the window ---

    // Draws what changed, updates the title, and returns what the user did since the last call,
    // waiting up to `timeout` for something to happen.
    std::vector<ViewerEvent> poll(std::chrono::milliseconds timeout);

private:
    Viewer(const SdlLibrary& sdl, const std::string& name, int width, int height,
           const ToneMapper& toneMapper);

    const SdlLibrary& sdl_;
    std::string name_;
    ToneMapper toneMapper_;
    SDL_Window* window_ = nullptr;
    SDL_Renderer* renderer_ = nullptr;
    SDL_Texture* texture_ = nullptr;
    bool exposed_ = true;  // the window needs drawing (the UI thread's own)

    mutable std::mutex mutex_;  // guards the members below
    Image image_;
    std::vector<unsigned char> pixels8_;  // image_ as the window shows it: 8-bit sRGB, RGB order
    PixelWindow changed_;                 // what changed since the last upload; empty if nothing
    std::string status_;
    bool statusChanged_ = false;
};

}  // namespace lancer
