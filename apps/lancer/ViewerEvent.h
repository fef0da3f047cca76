#pragma once

namespace lancer {

// What the user did in the window.
struct ViewerEvent {
    enum class Kind {
        Close,  // Esc, or the window closed
        Save,   // S
        Drag,   // the mouse moved with its left button down: dx, dy
        Zoom,   // the wheel turned: steps, positive away from the user (zoom in)
    };
    Kind kind;
    // For Drag: the move as fractions of the window's width and height, x right, y down.
    float dx = 0, dy = 0;
    int steps = 0;
};

}  // namespace lancer
