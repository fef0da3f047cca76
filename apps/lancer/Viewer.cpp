#include "Viewer.h"

#include <algorithm>
#include <cstdlib>
#include <optional>

#include "SdlLibrary.h"
#include "math/Srgb.h"

namespace lancer {

namespace {

PixelWindow unite(const PixelWindow& a, const PixelWindow& b) {
    if (a.width() <= 0 || a.height() <= 0) return b;
    return {std::min(a.x0, b.x0), std::min(a.y0, b.y0), std::max(a.x1, b.x1), std::max(a.y1, b.y1)};
}

std::string sdlError(const SdlLibrary& sdl, const std::string& what) {
    return what + " (" + sdl.SDL_GetError() + ")";
}

// Starts SDL's video on a display the user can see. Unless SDL_VIDEODRIVER chooses, the drivers
// that draw nowhere (offscreen, dummy) are passed over, and X11 and Wayland are tried only in
// their sessions (Wayland's library would complain on stderr). On failure, `error` says why the
// first display tried could not be used.
bool startVideo(const SdlLibrary& sdl, std::string& error) {
    if (std::getenv("SDL_VIDEODRIVER")) {
        if (sdl.SDL_Init(SDL_INIT_VIDEO) == 0) return true;
        error = sdlError(sdl, "no display available");
        return false;
    }
    error = "no display available (DISPLAY and WAYLAND_DISPLAY are not set)";
    bool tried = false;
    for (int i = 0; i < sdl.SDL_GetNumVideoDrivers(); ++i) {
        const std::string driver = sdl.SDL_GetVideoDriver(i);
        if (driver == "offscreen" || driver == "dummy" || driver == "evdev" ||
            (driver == "x11" && !std::getenv("DISPLAY")) ||
            (driver == "wayland" && !std::getenv("WAYLAND_DISPLAY")))
            continue;
        sdl.SDL_SetHint(SDL_HINT_VIDEODRIVER, driver.c_str());
        if (sdl.SDL_Init(SDL_INIT_VIDEO) == 0) return true;
        if ((driver == "x11" || driver == "wayland") && !tried) {
            error = "no display available (cannot connect to the " +
                    (driver == "x11"
                         ? "X display " + std::string(std::getenv("DISPLAY"))
                         : "Wayland display " + std::string(std::getenv("WAYLAND_DISPLAY"))) +
                    ")";
            tried = true;
        }
    }
    return false;
}

// Returns when SDL has events queued, or after `timeout`. Not SDL_WaitEventTimeout: to wake
// itself, that sends an X event to the window over a second connection, and when the X server
// handled it after the window was closed (a loaded machine), Xlib ended the program with
// "BadWindow" at SDL_Quit. Short sleeps between polls send nothing.
void waitForEvents(const SdlLibrary& sdl, std::chrono::milliseconds timeout) {
    constexpr std::chrono::milliseconds kPollStep{4};
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    for (;;) {
        sdl.SDL_PumpEvents();
        if (sdl.SDL_HasEvents(SDL_FIRSTEVENT, SDL_LASTEVENT)) return;
        const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
            deadline - std::chrono::steady_clock::now());
        if (left.count() <= 0) return;
        sdl.SDL_Delay(static_cast<Uint32>(std::min(left, kPollStep).count()));
    }
}

}  // namespace

Viewer::Viewer(const SdlLibrary& sdl, const std::string& name, int width, int height,
               const ToneMapper& toneMapper)
    : sdl_(sdl),
      name_(name),
      toneMapper_(toneMapper),
      image_(width, height),
      pixels8_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3, 0),
      changed_{0, 0, width, height} {}

std::string Viewer::libraryVersion() {
    const SdlLibrary& sdl = SdlLibrary::instance();
    if (!sdl.loaded()) return "SDL2 (" + sdl.error() + ")";
    SDL_version linked;
    sdl.SDL_GetVersion(&linked);
    return "SDL2 " + std::to_string(linked.major) + "." + std::to_string(linked.minor) + "." +
           std::to_string(linked.patch);
}

std::unique_ptr<Viewer> Viewer::open(const std::string& name, int width, int height,
                                     const ToneMapper& toneMapper, std::string& error) {
    const SdlLibrary& sdl = SdlLibrary::instance();
    if (!sdl.loaded()) {
        error = sdl.error();
        return nullptr;
    }
    // Ctrl-C stays the program's: SDL would turn it into a quit event.
    sdl.SDL_SetHint(SDL_HINT_NO_SIGNAL_HANDLERS, "1");
    if (!startVideo(sdl, error)) return nullptr;
    std::unique_ptr<Viewer> viewer(new Viewer(sdl, name, width, height, toneMapper));

    SDL_Rect screen{0, 0, width, height};
    sdl.SDL_GetDisplayUsableBounds(0, &screen);
    const double scale = std::min(
        {1.0, static_cast<double>(screen.w) / width, static_cast<double>(screen.h) / height});
    const int windowWidth = std::max(1, static_cast<int>(width * scale));
    const int windowHeight = std::max(1, static_cast<int>(height * scale));

    viewer->window_ =
        sdl.SDL_CreateWindow(name.c_str(), SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED,
                             windowWidth, windowHeight, SDL_WINDOW_HIDDEN);
    if (!viewer->window_) {
        error = sdlError(sdl, "cannot open a window");
        return nullptr;
    }
    // SDL's software renderer: one picture to copy per frame needs no GPU, the copy is exact,
    // and no OpenGL driver is loaded (slow to start, and it would replace the window).
    viewer->renderer_ = sdl.SDL_CreateRenderer(viewer->window_, -1, SDL_RENDERER_SOFTWARE);
    if (!viewer->renderer_) {
        error = sdlError(sdl, "cannot draw in a window");
        return nullptr;
    }
    viewer->texture_ = sdl.SDL_CreateTexture(viewer->renderer_, SDL_PIXELFORMAT_RGB24,
                                             SDL_TEXTUREACCESS_STREAMING, width, height);
    if (!viewer->texture_) {
        error = sdlError(sdl, "cannot make a texture for the image");
        return nullptr;
    }
    // Pixel for pixel at full size, so that the window shows exactly the 8-bit image; smoothed
    // when scaled down.
    sdl.SDL_SetTextureScaleMode(viewer->texture_,
                                scale < 1 ? SDL_ScaleModeLinear : SDL_ScaleModeNearest);
    // Shown only once it can be drawn.
    sdl.SDL_ShowWindow(viewer->window_);
    return viewer;
}

Viewer::~Viewer() {
    if (texture_) sdl_.SDL_DestroyTexture(texture_);
    if (renderer_) sdl_.SDL_DestroyRenderer(renderer_);
    if (window_) sdl_.SDL_DestroyWindow(window_);
    sdl_.SDL_Quit();
}

void Viewer::showTile(const Image& film, const PixelWindow& tile) {
    std::lock_guard lock(mutex_);
    for (int y = tile.y0; y < tile.y1; ++y)
        for (int x = tile.x0; x < tile.x1; ++x) {
            image_.at(x, y) = film.at(x, y);
            const Color c = toneMapper_.display(film.at(x, y));
            unsigned char* p = &pixels8_[3 * (static_cast<std::size_t>(y) *
                                                  static_cast<std::size_t>(image_.width()) +
                                              static_cast<std::size_t>(x))];
            p[0] = linearToSrgb8(c.r);
            p[1] = linearToSrgb8(c.g);
            p[2] = linearToSrgb8(c.b);
        }
    changed_ = unite(changed_, tile);
}

void Viewer::showFilm(const Image& film) {
    showTile(film, {0, 0, film.width(), film.height()});
}

void Viewer::setStatus(const std::string& status) {
    std::lock_guard lock(mutex_);
    status_ = status;
    statusChanged_ = true;
}

Image Viewer::image() const {
    std::lock_guard lock(mutex_);
    return image_;
}

std::vector<ViewerEvent> Viewer::poll(std::chrono::milliseconds timeout) {
    waitForEvents(sdl_, timeout);
    std::vector<ViewerEvent> events;
    SDL_Event event;
    while (sdl_.SDL_PollEvent(&event)) {
        switch (event.type) {
            case SDL_QUIT:
                events.push_back({ViewerEvent::Kind::Close});
                break;
            case SDL_KEYDOWN:
                if (event.key.keysym.sym == SDLK_ESCAPE)
                    events.push_back({ViewerEvent::Kind::Close});
                if (event.key.keysym.sym == SDLK_s) events.push_back({ViewerEvent::Kind::Save});
                break;
            case SDL_MOUSEMOTION:
                if (event.motion.state & SDL_BUTTON_LMASK) {
                    int width = 0, height = 0;
                    sdl_.SDL_GetWindowSize(window_, &width, &height);
                    events.push_back(
                        {ViewerEvent::Kind::Drag,
                         static_cast<float>(event.motion.xrel) / static_cast<float>(width),
                         static_cast<float>(event.motion.yrel) / static_cast<float>(height)});
                }
                break;
            case SDL_MOUSEWHEEL: {
                const int steps = event.wheel.direction == SDL_MOUSEWHEEL_FLIPPED ? -event.wheel.y
                                                                                  : event.wheel.y;
                if (steps != 0) events.push_back({ViewerEvent::Kind::Zoom, 0, 0, steps});
                break;
            }
            case SDL_WINDOWEVENT:
                if (event.window.event == SDL_WINDOWEVENT_EXPOSED) exposed_ = true;
                break;
            default:
                break;
        }
    }

    std::optional<std::string> title;
    {
        std::lock_guard lock(mutex_);
        if (changed_.width() > 0 && changed_.height() > 0) {
            const SDL_Rect rect{changed_.x0, changed_.y0, changed_.width(), changed_.height()};
            const int pitch = 3 * image_.width();
            sdl_.SDL_UpdateTexture(
                texture_, &rect,
                &pixels8_[static_cast<std::size_t>(changed_.y0 * pitch + 3 * changed_.x0)], pitch);
            changed_ = {};
            exposed_ = true;
        }
        if (statusChanged_) title = name_ + "  " + status_;
        statusChanged_ = false;
    }
    // Drawing only when needed leaves the processor to the renderer.
    if (exposed_) {
        sdl_.SDL_RenderClear(renderer_);
        sdl_.SDL_RenderCopy(renderer_, texture_, nullptr, nullptr);
        sdl_.SDL_RenderPresent(renderer_);
        exposed_ = false;
    }
    // After the drawing: whoever sees the new title sees the picture that goes with it.
    if (title) sdl_.SDL_SetWindowTitle(window_, title->c_str());
    return events;
}

}  // namespace lancer
