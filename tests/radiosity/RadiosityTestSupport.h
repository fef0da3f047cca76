#pragma once

// What the radiosity tests share: scenes written in a few lines, and the form factor between two
// groups of patches computed the way the solver computes it (element to patch).

#include <string>
#include <vector>

#include "radiosity/RadiosityMesh.h"
#include "scene/Scene.h"

namespace lancer::test {

// A scene from its JSON text (a camera is added when it has none).
Scene loadScene(const std::string& objects, const std::string& extra = "");

// One unit square as two triangles, counter-clockwise about `normal`: corner + s u + t v for s, t
// in [0, 1], with u x v = normal.
std::string square(const Vec3& corner, const Vec3& u, const Vec3& v,
                   const std::string& material = "white");

// The same square cut into tiles x tiles squares.
std::string tiledSquare(const Vec3& corner, const Vec3& u, const Vec3& v, int tiles,
                        const std::string& material = "white");

// A closed box [0, 1]^3 of inward-facing squares (their front, the emitting side, inside), each
// wall cut into tiles x tiles squares.
std::string closedBox(const std::string& material, int tiles = 1);

// The patches whose normal is `normal` (the tests' surfaces face different ways).
std::vector<std::uint32_t> patchesFacing(const RadiosityMesh& mesh, const Vec3& normal);

// F from the area of `receivers` (its elements, front side) to the front of `shooters`:
// sum over elements e of A_e sum over patches p of F(e -> p), over the receivers' total area.
double areaFormFactor(const Scene& scene, const RadiosityMesh& mesh,
                      const std::vector<std::uint32_t>& receivers,
                      const std::vector<std::uint32_t>& shooters, int visibilityRays);

}  // namespace lancer::test
