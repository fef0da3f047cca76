#pragma once

#include <string>

namespace lancer {

// The scene file's "radiosity" block (docs/SCENE-FORMAT.md). Sizes of 0 mean "derived from the
// scene's size".
struct RadiositySettings {
    std::string method = "progressive";  // a name in RadiosityMethodRegistry
    float patchSize = 0;    // longest edge of a shooting patch; 0: the scene's diagonal / 8
    float elementSize = 0;  // longest edge of a receiving element; 0: patchSize / 2
    // Shooting stops once the unshot power left is below this fraction of the power emitted.
    float threshold = 0.01f;
    int maxShots = 100000;              // a bound on the shots, whatever the threshold
    int subdivisionLevels = 2;          // how many times an element may be split in four
    float subdivisionTolerance = 0.1f;  // relative jump in irradiance that makes an element split
    int visibilityRays = 4;             // rays per form factor, to points on the shooter
    // Hierarchical: rays per link refined from a link whose rays all got through (unless its
    // source is bright, a lamp).
    int refinedVisibilityRays = 1;
    // Hierarchical: a link whose reflected radiosity may be wrong by more than this fraction of
    // the mean radiosity put in is refined.
    float refinementTolerance = 0.02f;
    // Hierarchical: the patches grouped into clusters, the solve starting from the top cluster's
    // link to itself instead of linking every pair of patches.
    bool clusters = false;
    // Hierarchical: rays per leaf and per vertex estimating the light that reaches them through a
    // glossy reflection (in scenes with glossy surfaces; 0: none).
    int glossySamples = 64;
    // The render, not the solution: rays gathering the solution at each eye ray's diffuse hit
    // (0: the solution interpolated there).
    int finalGather = 0;
    // The render: emitter samples computing the direct light at each eye ray's diffuse hit with
    // shadow rays, the solution giving the rest (0: all of it from the solution).
    int directSamples = 0;
};

}  // namespace lancer
