#pragma once

#include <memory>
#include <string>
#include <vector>

#include "image/Image.h"
#include "lights/Light.h"
#include "math/Distribution2D.h"
#include "util/Parameters.h"

namespace lancer {

// Light from infinitely far away in every direction, from a latitude-longitude map: a ray
// leaving the scene with unit direction d (the map's rotation about +y undone) sees the map at
// u = 0.5 + atan2(d.x, -d.z) / (2 pi) across and v = acos(d.y) / pi down, bilinearly (the
// scene format's "environment"). Directions are sampled in proportion to the map's luminance
// times sin(theta), the Jacobian of the mapping: a texel's cell through a Distribution2D (by the
// cell's average luminance), then a point in the cell in proportion to the bilinear luminance.
class EnvironmentLight final : public Light {
public:
    // The scene file's "environment": its keys besides "file" (read by the loader, which gives
    // the image) and "samples" (the Whitted shadow samples, as for area lights).
    static std::vector<std::string> keys() { return {"file", "intensity", "rotate", "samples"}; }
    static std::unique_ptr<EnvironmentLight> create(const Parameters& parameters, Image map);
    // `map` holds linear radiance; it is scaled by `intensity` and turned by `rotateDegrees`
    // about +y (counter-clockwise seen from above).
    EnvironmentLight(Image map, float intensity, float rotateDegrees);

    // The radiance arriving from direction d (towards the environment; any length).
    Color radiance(const Vec3& d) const;

    LightSample sample(const Vec3& p, const Vec2& u) const override;
    bool isDelta() const override { return false; }
    float pdf(const Vec3& p, const Vec3& wi, const Hit& onLight) const override;
    // The flux through a disc as wide as the scene from every direction: pi R^2 times the
    // integral of the radiance over the sphere.
    Color power(float sceneRadius) const override;

    // The map's point (u, v) in [0, 1)^2 of a unit direction in the map's own frame, and back.
    static Vec2 mapPoint(const Vec3& d);
    static Vec3 mapDirection(const Vec2& uv);

private:
    // The bilinear lookup at (u, v): u wraps around, v is clamped at the poles.
    Color lookUp(const Vec2& uv) const;
    // A point of texel (x, y)'s cell in proportion to the bilinear luminance there, from u.
    Vec2 sampleInCell(int x, int y, Vec2 u) const;
    // The density over the map's (u, v) with which sample() picks a point.
    float mapDensity(const Vec2& uv) const;
    Vec3 toMap(const Vec3& world) const;
    Vec3 toWorld(const Vec3& map) const;

    Image map_;
    float cosRotate_, sinRotate_;
    std::vector<float> cellAverage_;  // each texel's cell's average luminance
    Distribution2D distribution_;     // of the cells, by average luminance times sin(theta)
    Color radianceIntegral_;          // the integral of the radiance over the sphere of directions
};

}  // namespace lancer
