#pragma once

namespace lancer {

// The frames of a scene's "animation" block, numbered from 1. Its keyframes are the loader's:
// each frame is loaded as a scene of its own.
struct AnimationSettings {
    static constexpr int kMaxFrames = 1'000'000;
    static constexpr float kMaxFramesPerSecond = 1000;

    int frames = 1;
    float framesPerSecond = 24;  // for players of the frames (the gallery's GIF)
};

}  // namespace lancer
