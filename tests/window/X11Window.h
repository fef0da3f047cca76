#pragma once

#include <chrono>
#include <string>

#include "LancerRun.h"

typedef struct _XDisplay Display;

namespace lancer::test {

// Another program's top-level window on an X display, driven as a user would: read its title,
// take a screenshot, press keys, drag and scroll the mouse (XTest), close it (WM_DELETE_WINDOW).
class X11Window {
public:
    // Waits up to `timeout` for a mapped top-level window whose title starts with `titlePrefix`
    // on `display`; throws std::runtime_error if none shows up.
    X11Window(const std::string& display, const std::string& titlePrefix,
              std::chrono::milliseconds timeout);
    ~X11Window();
    X11Window(const X11Window&) = delete;
    X11Window& operator=(const X11Window&) = delete;

    std::string title() const;
    // Waits up to `timeout` for the title to contain `text`; false if it did not.
    bool waitForTitle(const std::string& text, std::chrono::milliseconds timeout) const;

    int width() const;
    int height() const;
    // The window's content, 8 bits per channel.
    Image screenshot() const;

    // Presses and releases a key (an X keysym: XK_s, XK_Escape ...), the window focused.
    void pressKey(unsigned long keysym) const;
    // Drags with the left button from (x0, y0) to (x1, y1), window coordinates, in a few steps.
    void drag(int x0, int y0, int x1, int y1) const;
    // Turns the wheel by `steps` notches, positive away from the user, the pointer at (x, y).
    void scroll(int x, int y, int steps) const;
    // Asks the window to close, as a window manager's close button does.
    void close() const;

private:
    void movePointer(int x, int y) const;

    Display* display_ = nullptr;
    unsigned long window_ = 0;
};

}  // namespace lancer::test
