#pragma once

// Test scenes for the BVH, their brute-force answers, and a walk over the flattened tree that
// checks its invariants.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <optional>
#include <random>
#include <span>
#include <string>
#include <vector>

#include "accel/Bvh.h"
#include "geometry/Triangle.h"
#include "math/Bounds3.h"
#include "math/Ray.h"
#include "math/Vec3.h"

namespace lancer::test {

// Triangles as three vertices each, tested with the renderer's watertight intersection.
struct TriangleSoup {
    std::vector<Vec3> vertices;  // 3 per triangle

    std::uint32_t size() const { return static_cast<std::uint32_t>(vertices.size() / 3); }
    void add(const Vec3& a, const Vec3& b, const Vec3& c) {
        vertices.insert(vertices.end(), {a, b, c});
    }
    Bounds3 triangleBounds(std::uint32_t i) const {
        return merge(Bounds3(vertices[3 * i], vertices[3 * i + 1]), vertices[3 * i + 2]);
    }
    std::vector<Bounds3> bounds() const {
        std::vector<Bounds3> b(size());
        for (std::uint32_t i = 0; i < size(); ++i)
            b[i] = triangleBounds(i);
        return b;
    }
    std::optional<float> intersect(std::uint32_t i, const Ray& ray, float tMax) const {
        const auto at = Triangle::intersect(vertices[3 * i], vertices[3 * i + 1],
                                            vertices[3 * i + 2], ray, tMax);
        if (!at) return std::nullopt;
        return at->t;
    }
    // The soup with its triangles in the BVH's leaf order.
    TriangleSoup reordered(std::span<const std::uint32_t> order) const {
        TriangleSoup r;
        r.vertices.reserve(vertices.size());
        for (const std::uint32_t i : order)
            r.add(vertices[3 * i], vertices[3 * i + 1], vertices[3 * i + 2]);
        return r;
    }
};

struct ClosestHit {
    float t = kInfinity;
    std::int64_t primitive = -1;  // original index; -1 for a miss
};

// The exact closest hit found by testing every primitive that could be hit, with ties on t going to
// the lowest index. To keep 100k rays on 100k triangles within seconds, primitives are put in
// groups of 16 spatially close ones (Morton order), and groups in clusters of 16; a group or a
// cluster whose bounding sphere the ray cannot reach before the best hit so far is skipped. That
// test is in double precision with a generous margin, and shares no code with the BVH.
class BruteForce {
public:
    explicit BruteForce(std::span<const Bounds3> primitiveBounds);

    // intersectFn(i, ray, tMax) -> std::optional<float>: the t of a hit on primitive i in (0,
    // tMax).
    template <typename IntersectFn>
    ClosestHit closest(const Ray& ray, IntersectFn&& intersectFn) const {
        ClosestHit best;
        const Line line{Vec3d(ray.origin), Vec3d(ray.direction)};
        for (const Sphere& cluster : clusters_) {
            if (!line.mayHit(cluster, best.t)) continue;
            for (std::uint32_t c = cluster.begin; c < cluster.end; ++c) {
                const Sphere& group = groups_[c];
                if (!line.mayHit(group, best.t)) continue;
                for (std::uint32_t g = group.begin; g < group.end; ++g) {
                    const std::uint32_t i = members_[g];
                    // Just above best.t, so that exact ties are seen and resolved by index.
                    const std::optional<float> t = intersectFn(i, ray, nextFloatUp(best.t));
                    if (t && (*t < best.t || (*t == best.t && i < best.primitive))) {
                        best.t = *t;
                        best.primitive = i;
                    }
                }
            }
        }
        return best;
    }

private:
    // Bounds a range of groups_ (a cluster) or of members_ (a group).
    struct Sphere {
        std::uint32_t begin, end;
        Vec3d center;
        double radius;
    };
    struct Line {
        Line(const Vec3d& o, const Vec3d& d)
            : origin(o), direction(d), dd(dot(d, d)), length(std::sqrt(dd)) {}

        bool mayHit(const Sphere& sphere, float tBest) const {
            const Vec3d v = sphere.center - origin;
            // Margin for the float rounding of the primitive tests: far above it, far below any
            // size.
            const double r =
                sphere.radius * (1 + 1e-4) + 1e-5 * (lancer::length(v) + sphere.radius);
            const double along = dot(v, direction);
            if (along < -r * length) return false;  // wholly behind the origin
            if (along - r * length > tBest * dd * (1 + 1e-6))
                return false;  // wholly beyond the best hit
            return lengthSquared(cross(v, direction)) <= r * r * dd;
        }

        Vec3d origin, direction;
        double dd, length;
    };

    std::vector<std::uint32_t> members_;
    std::vector<Sphere> groups_;
    std::vector<Sphere> clusters_;
};

// The BVH's answer with the same per-primitive test, on primitives stored in leaf order.
template <typename IntersectFn>
ClosestHit bvhClosest(const Bvh& bvh, const Ray& ray, IntersectFn&& intersectInLeafOrder) {
    ClosestHit best;
    bvh.intersect(ray, best.t, [&](std::uint32_t k, const Ray& r, float& tMax) {
        const std::optional<float> t = intersectInLeafOrder(k, r, tMax);
        if (!t) return false;
        tMax = *t;
        best.primitive = bvh.primitiveOrder()[k];
        return true;
    });
    return best;
}

template <typename IntersectFn>
bool bvhOccluded(const Bvh& bvh, const Ray& ray, float tMax, IntersectFn&& intersectInLeafOrder) {
    return bvh.occluded(ray, tMax, [&](std::uint32_t k, const Ray& r, float t) {
        return intersectInLeafOrder(k, r, t).has_value();
    });
}

// The ray as text that reproduces it exactly (9 significant digits round-trip a float).
std::string describe(const Ray& ray);
// "t = <t in hexadecimal> on primitive <index>", or "none".
std::string describe(const ClosestHit& hit);

// Random directions, uniform on the sphere.
inline Vec3 randomDirection(std::mt19937& rng) {
    std::normal_distribution<float> normal;
    for (;;) {
        const Vec3 d(normal(rng), normal(rng), normal(rng));
        if (lengthSquared(d) > 1e-6f) return normalize(d);
    }
}

inline Vec3 randomPointIn(const Bounds3& box, std::mt19937& rng) {
    std::uniform_real_distribution<float> u(0, 1);
    const Vec3 d = box.diagonal();
    return box.min + Vec3(u(rng) * d.x, u(rng) * d.y, u(rng) * d.z);
}

inline Bounds3 enlarged(const Bounds3& box, float fraction) {
    const Vec3 margin = fraction * box.diagonal();
    return {box.min - margin, box.max + margin};
}

// Incoherent rays: half start anywhere around the scene in random directions, half start outside
// and aim at a random point of the scene, so that a good share of them hits something.
inline std::vector<Ray> randomRays(const Bounds3& scene, int count, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::vector<Ray> rays;
    rays.reserve(static_cast<std::size_t>(count));
    const Bounds3 around = enlarged(scene, 0.2f);
    const float radius = length(scene.diagonal());
    for (int i = 0; i < count; ++i) {
        if (i % 2 == 0) {
            rays.push_back({randomPointIn(around, rng), randomDirection(rng)});
        } else {
            const Vec3 origin = scene.centroid() + radius * randomDirection(rng);
            rays.push_back({origin, randomPointIn(scene, rng) - origin});
        }
    }
    return rays;
}

// n random triangles of roughly `size` inside the unit cube.
inline TriangleSoup randomSoup(std::uint32_t n, float size, std::uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> u(0, 1);
    TriangleSoup soup;
    for (std::uint32_t i = 0; i < n; ++i) {
        const Vec3 c(u(rng), u(rng), u(rng));
        soup.add(c + size * randomDirection(rng), c + size * randomDirection(rng),
                 c + size * randomDirection(rng));
    }
    return soup;
}

// A closed, bumpy, star-shaped mesh: an icosahedron subdivided `levels` times (20 * 4^levels
// triangles), its vertices pushed to a radius between 0.8 and 1.2 around the origin. Shared
// vertices are computed once, so neighbouring triangles share exact edges.
TriangleSoup bumpySphere(int levels);

// n triangles whose boxes are all centred on the origin (so their centroids coincide), of random
// sizes and shapes.
TriangleSoup sameCentroidSoup(std::uint32_t n, std::uint32_t seed);

struct TreeStats {
    int maxDepth = 0;  // of the deepest leaf, the root being at depth 0
    std::uint32_t leafCount = 0;
    std::uint32_t maxLeafSize = 0;
};

// Walks the flattened tree and checks what every BVH must satisfy: children inside their parent,
// first child right after its parent, leaves covering [0, primitiveCount) once each in order, every
// primitive inside its leaf, and every node reached.
TreeStats checkTree(const Bvh& bvh, std::span<const Bounds3> primitiveBounds);

}  // namespace lancer::test
