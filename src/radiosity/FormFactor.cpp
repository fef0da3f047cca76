#include "radiosity/FormFactor.h"

#include <cmath>

#include "lights/Light.h"
#include "radiosity/SurfaceProbe.h"
#include "sampling/StratifiedPoint.h"
#include "scene/Scene.h"
#include "scene/ShadowRays.h"

namespace lancer {

FormFactor::FormFactor(const Scene& scene) : scene_(scene) {}

double FormFactor::pointToTriangle(const Vec3d& p, const Vec3d& n,
                                   const std::array<Vec3, 3>& triangle) {
    // The part of the triangle in front of p's tangent plane: the triangle, or a triangle or
    // quadrilateral cut from it (Sutherland-Hodgman against one plane, without allocating: this
    // runs for every element and shooter).
    std::array<Vec3d, 4> visible;
    std::size_t count = 0;
    std::array<double, 3> height;
    for (std::size_t k = 0; k < 3; ++k)
        height[k] = dot(n, Vec3d(triangle[k]) - p);
    if (height[0] <= 0 && height[1] <= 0 && height[2] <= 0) return 0;
    for (std::size_t k = 0; k < 3; ++k) {
        const std::size_t next = (k + 1) % 3;
        if (height[k] >= 0) visible[count++] = Vec3d(triangle[k]);
        if ((height[k] >= 0) != (height[next] >= 0))
            visible[count++] =
                Vec3d(triangle[k]) + (height[k] / (height[k] - height[next])) *
                                         (Vec3d(triangle[next]) - Vec3d(triangle[k]));
    }
    // F = 1 / (2 pi) sum_k angle(R_k, R_k+1) n . normalize(R_k x R_k+1), R_k = v_k - p.
    double sum = 0;
    for (std::size_t k = 0; k < count; ++k) {
        const Vec3d a = visible[k] - p, b = visible[(k + 1) % count] - p;
        const Vec3d c = cross(a, b);
        const double sine = length(c);
        if (!(sine > 0)) continue;  // an edge seen end-on subtends nothing
        sum += std::atan2(sine, dot(a, b)) * dot(n, c) / sine;
    }
    return std::abs(sum) / (2 * std::numbers::pi);
}

Color FormFactor::elementToTriangle(const Element& receiver, Side receiverSide,
                                    const std::array<Vec3, 3>& triangle, const Patch& shooter,
                                    Side shooterSide, int rays, std::uint64_t seed,
                                    std::uint64_t& rayCount) const {
    const Vec3d p(receiver.centroid);
    // The shooter's side must face the receiver.
    const double height = dot(Vec3d(shooter.normal), p - Vec3d(shooter.corners[0]));
    if (shooterSide == Side::Front ? !(height > 0) : !(height < 0)) return Color(0);
    const Vec3 n = receiverSide == Side::Front ? receiver.normal : -receiver.normal;
    const double unoccluded = pointToTriangle(p, Vec3d(n), triangle);
    if (!(unoccluded > 0)) return Color(0);

    Hit from;
    from.p = receiver.surfacePoint;
    from.pError = gamma(16) * abs(from.p);
    from.ng = receiver.surfaceNormal;
    Color visible;
    int counted = 0;
    for (int k = 0; k < rays; ++k) {
        // Uniform over the triangle (the square's cells keep their areas).
        const Vec2 uv = stratifiedPoint(k, rays, seed);
        const float su = std::sqrt(uv.x);
        Vec3 target =
            (1 - su) * triangle[0] + su * (1 - uv.y) * triangle[1] + su * uv.y * triangle[2];
        if (!(dot(n, target - receiver.centroid) > 0)) continue;  // behind the receiver
        if (shooter.curved) {
            // Onto the true surface, and a little off it towards the receiver: rounding must
            // not let a nearby receiver's ray meet the surface just before the target.
            const Vec3 towardsReceiver =
                shooterSide == Side::Front ? shooter.normal : -shooter.normal;
            target = SurfaceProbe::onSurface(shooter, target) +
                     (1e-4f * std::sqrt(shooter.area)) * towardsReceiver;
        }
        LightSample towards;
        towards.position = target;
        towards.wi = normalize(target - from.p);
        visible += ShadowRays::transmittance(scene_, from, towards, rayCount);
        ++counted;
    }
    if (counted == 0) return Color(0);
    return static_cast<float>(unoccluded) * visible / static_cast<float>(counted);
}

}  // namespace lancer
