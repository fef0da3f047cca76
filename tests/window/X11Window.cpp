#include "X11Window.h"

#include <X11/Xatom.h>
#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <X11/extensions/XTest.h>

#include <memory>
#include <stdexcept>
#include <thread>

namespace lancer::test {

namespace {

using namespace std::chrono_literals;

// The window's _NET_WM_NAME (UTF-8, what SDL sets), or its WM_NAME.
std::string titleOf(Display* display, Window window) {
    Atom type = None;
    int format = 0;
    unsigned long count = 0, remaining = 0;
    unsigned char* data = nullptr;
    std::string title;
    if (XGetWindowProperty(display, window, XInternAtom(display, "_NET_WM_NAME", False), 0, 1024,
                           False, XInternAtom(display, "UTF8_STRING", False), &type, &format,
                           &count, &remaining, &data) == Success &&
        data) {
        title.assign(reinterpret_cast<const char*>(data), count);
        XFree(data);
        return title;
    }
    char* name = nullptr;
    if (XFetchName(display, window, &name) && name) {
        title = name;
        XFree(name);
    }
    return title;
}

Window findWindow(Display* display, const std::string& titlePrefix) {
    Window root = 0, parent = 0, *children = nullptr;
    unsigned int count = 0;
    if (!XQueryTree(display, DefaultRootWindow(display), &root, &parent, &children, &count))
        return 0;
    const std::unique_ptr<Window, int (*)(void*)> owned(children, XFree);
    for (unsigned int i = 0; i < count; ++i) {
        XWindowAttributes attributes;
        if (XGetWindowAttributes(display, children[i], &attributes) &&
            attributes.map_state == IsViewable &&
            titleOf(display, children[i]).rfind(titlePrefix, 0) == 0)
            return children[i];
    }
    return 0;
}

// Xlib's default handler ends the process on any error, and the window of another program may
// vanish at any moment (it exits): a request about it then just fails.
int ignoreError(Display*, XErrorEvent*) {
    return 0;
}

}  // namespace

X11Window::X11Window(const std::string& display, const std::string& titlePrefix,
                     std::chrono::milliseconds timeout) {
    XSetErrorHandler(ignoreError);
    display_ = XOpenDisplay(display.c_str());
    if (!display_) throw std::runtime_error("cannot connect to the X display " + display);
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    while (!(window_ = findWindow(display_, titlePrefix))) {
        if (std::chrono::steady_clock::now() > deadline) {
            XCloseDisplay(display_);
            throw std::runtime_error("no window titled \"" + titlePrefix + "...\" on " + display);
        }
        std::this_thread::sleep_for(20ms);
    }
}

X11Window::~X11Window() {
    XCloseDisplay(display_);
}

std::string X11Window::title() const {
    return titleOf(display_, window_);
}

bool X11Window::waitForTitle(const std::string& text, std::chrono::milliseconds timeout) const {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    while (title().find(text) == std::string::npos) {
        if (std::chrono::steady_clock::now() > deadline) return false;
        std::this_thread::sleep_for(20ms);
    }
    return true;
}

int X11Window::width() const {
    XWindowAttributes attributes{};
    XGetWindowAttributes(display_, window_, &attributes);
    return attributes.width;
}

int X11Window::height() const {
    XWindowAttributes attributes{};
    XGetWindowAttributes(display_, window_, &attributes);
    return attributes.height;
}

Image X11Window::screenshot() const {
    const int w = width(), h = height();
    // XDestroyImage is a macro.
    const auto destroy = [](XImage* image) { XDestroyImage(image); };
    const std::unique_ptr<XImage, decltype(destroy)> shot(
        XGetImage(display_, window_, 0, 0, static_cast<unsigned>(w), static_cast<unsigned>(h),
                  AllPlanes, ZPixmap),
        destroy);
    if (!shot) throw std::runtime_error("XGetImage failed");
    // A channel's value from the pixel and the channel's mask: 8 bits on a 24-bit screen.
    const auto channel = [](unsigned long pixel, unsigned long mask) {
        int shift = 0;
        while (mask && !(mask & 1)) {
            mask >>= 1;
            ++shift;
        }
        return static_cast<float>((pixel >> shift) & mask);
    };
    Image image;
    image.width = w;
    image.height = h;
    image.encoding = Image::Encoding::EightBit;
    image.pixels.reserve(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const unsigned long pixel = XGetPixel(shot.get(), x, y);
            image.pixels.push_back({channel(pixel, shot->red_mask),
                                    channel(pixel, shot->green_mask),
                                    channel(pixel, shot->blue_mask)});
        }
    return image;
}

void X11Window::pressKey(unsigned long keysym) const {
    XSetInputFocus(display_, window_, RevertToParent, CurrentTime);
    XSync(display_, False);
    const KeyCode code = XKeysymToKeycode(display_, keysym);
    XTestFakeKeyEvent(display_, code, True, CurrentTime);
    XTestFakeKeyEvent(display_, code, False, CurrentTime);
    XSync(display_, False);
}

void X11Window::movePointer(int x, int y) const {
    int rootX = 0, rootY = 0;
    Window child = 0;
    XTranslateCoordinates(display_, window_, DefaultRootWindow(display_), x, y, &rootX, &rootY,
                          &child);
    XTestFakeMotionEvent(display_, -1, rootX, rootY, CurrentTime);
    XSync(display_, False);
}

void X11Window::drag(int x0, int y0, int x1, int y1) const {
    constexpr int kSteps = 8;
    movePointer(x0, y0);
    XTestFakeButtonEvent(display_, Button1, True, CurrentTime);
    for (int i = 1; i <= kSteps; ++i) {
        // Paced like a hand, so that the program sees a drag rather than one jump.
        std::this_thread::sleep_for(10ms);
        movePointer(x0 + (x1 - x0) * i / kSteps, y0 + (y1 - y0) * i / kSteps);
    }
    XTestFakeButtonEvent(display_, Button1, False, CurrentTime);
    XSync(display_, False);
}

void X11Window::scroll(int x, int y, int steps) const {
    movePointer(x, y);
    // X reports the wheel as buttons 4 (away from the user) and 5 (towards).
    const unsigned int button = steps > 0 ? Button4 : Button5;
    for (int i = 0; i < std::abs(steps); ++i) {
        XTestFakeButtonEvent(display_, button, True, CurrentTime);
        XTestFakeButtonEvent(display_, button, False, CurrentTime);
    }
    XSync(display_, False);
}

void X11Window::close() const {
    XEvent event{};
    event.xclient.type = ClientMessage;
    event.xclient.window = window_;
    event.xclient.message_type = XInternAtom(display_, "WM_PROTOCOLS", False);
    event.xclient.format = 32;
    event.xclient.data.l[0] = static_cast<long>(XInternAtom(display_, "WM_DELETE_WINDOW", False));
    event.xclient.data.l[1] = CurrentTime;
    XSendEvent(display_, window_, False, NoEventMask, &event);
    XSync(display_, False);
}

}  // namespace lancer::test
