// CSG end to end: a box with a hole through it in `whitted`, its face, the hole's wall and the
// floor lit through the hole shaded as the contract's closed form says; shadows through a glass
// lens and a glass union crossing exactly two surfaces; an emissive csg lighting a floor in
// `path` and in `radiosity` as the closed form of its visible faces says. (Its errors are in
// ErrorTest.)

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "ClosedForm.h"

namespace lancer::test {
namespace {

using nlohmann::json;

constexpr double kPi = 3.14159265358979323846;

// Where a ray is inside the box [-1, 1]^3 minus the cylinder of radius 0.5 about the z axis:
// the first crossing with t > 0 and the outward normal there.
struct Crossing {
    double t;
    Vec3d normal;
};
std::optional<Crossing> intersectBoxWithHole(const RayD& ray) {
    // The box's interval and its entry normal.
    double tEnter = -1e30, tExit = 1e30;
    Vec3d enterNormal, exitNormal;
    for (int axis = 0; axis < 3; ++axis) {
        const double d = ray.direction[axis], o = ray.origin[axis];
        if (d == 0) {
            if (std::abs(o) > 1) return std::nullopt;
            continue;
        }
        const double t0 = (-1 - o) / d, t1 = (1 - o) / d;
        if (std::min(t0, t1) > tEnter) {
            tEnter = std::min(t0, t1);
            enterNormal = Vec3d(0, 0, 0);
            enterNormal[axis] = d < 0 ? 1 : -1;
        }
        if (std::max(t0, t1) < tExit) {
            tExit = std::max(t0, t1);
            exitNormal = Vec3d(0, 0, 0);
            exitNormal[axis] = d < 0 ? -1 : 1;
        }
    }
    if (tEnter > tExit) return std::nullopt;
    // The cylinder's interval (all of the line when parallel to the axis and inside it).
    const double a = ray.direction.x * ray.direction.x + ray.direction.y * ray.direction.y;
    const double b = ray.origin.x * ray.direction.x + ray.origin.y * ray.direction.y;
    const double c = ray.origin.x * ray.origin.x + ray.origin.y * ray.origin.y - 0.25;
    double cEnter = 1e30, cExit = -1e30;
    if (a == 0) {
        if (c < 0) cEnter = -1e30, cExit = 1e30;
    } else if (b * b - a * c >= 0) {
        const double root = std::sqrt(b * b - a * c);
        cEnter = (-b - root) / a;
        cExit = (-b + root) / a;
    }
    const auto wallNormal = [&](double t) {
        const Vec3d p = ray.at(t);
        return normalize(Vec3d(-p.x, -p.y, 0));  // into the hole
    };
    // The box's interval less the cylinder's: [tEnter, cEnter) and (cExit, tExit].
    std::vector<Crossing> crossings;
    if (cEnter <= tEnter && cExit >= tExit) return std::nullopt;  // all inside the hole
    if (cEnter > tEnter && cEnter < tExit) {
        crossings.push_back({tEnter, enterNormal});
        crossings.push_back({cEnter, -wallNormal(cEnter)});
        if (cExit < tExit) {
            crossings.push_back({cExit, wallNormal(cExit)});
            crossings.push_back({tExit, exitNormal});
        }
    } else if (cExit > tEnter && cExit < tExit) {
        crossings.push_back({cExit, wallNormal(cExit)});
        crossings.push_back({tExit, exitNormal});
    } else {
        crossings.push_back({tEnter, enterNormal});
        crossings.push_back({tExit, exitNormal});
    }
    for (const Crossing& crossing : crossings)
        if (crossing.t > 0) return crossing;
    return std::nullopt;
}

TEST(CliCsg, ABoxWithAHoleShowsItsWallAndLetsTheLightThrough) {
    // The box [-1, 1]^3 minus a cylinder along z, a floor (a wall) behind it on z = -2, a
    // directional light nearly along the hole, the camera in front, a little above and aside.
    json scene = json::parse(R"({
      "background": 0.1, "ambient": 0,
      "materials": { "white": { "diffuse": 0.8 }, "green": { "diffuse": [0.2, 0.6, 0.2] },
                     "back": { "diffuse": 0.5 } },
      "objects": [
        { "type": "csg", "operation": "difference", "material": "white", "objects": [
          { "type": "box", "min": [-1, -1, -1], "max": [1, 1, 1] },
          { "type": "cylinder", "base": [0, 0, -1.5], "top": [0, 0, 1.5], "radius": 0.5,
            "material": "green" } ] },
        { "type": "plane", "point": [0, 0, -2], "normal": [0, 0, 1], "material": "back" }
      ],
      "lights": [ { "type": "directional", "direction": [-0.15, -0.1, -1], "irradiance": 3 } ]
    })");
    const CameraModel camera{.position = {0.9, 0.7, 6},
                             .lookAt = {0, 0, -0.5},
                             .vfovDegrees = 34,
                             .width = 64,
                             .height = 48};
    camera.placeIn(scene);
    scene["render"]["max_depth"] = 0;
    const Image image = renderScene(scene).image;

    const Vec3d towardsLight = normalize(Vec3d(0.15, 0.1, 1));
    // What the eye ray sees: 0 the box's faces, 1 the hole's wall, 2 the back wall, 3 nothing;
    // the point, its normal, and whether it is lit.
    struct Seen {
        int surface;
        Vec3d p, normal;
        bool lit;
    };
    const auto see = [&](const RayD& ray) {
        Seen seen{3, {}, {}, false};
        const std::optional<Crossing> onSolid = intersectBoxWithHole(ray);
        const std::optional<double> onBack = intersectPlane(ray, Vec3d(0, 0, -2), Vec3d(0, 0, 1));
        if (onSolid && (!onBack || onSolid->t < *onBack)) {
            seen.p = ray.at(onSolid->t);
            seen.normal = onSolid->normal;
            const bool onWall = std::abs(seen.p.x) < 0.999 && std::abs(seen.p.y) < 0.999 &&
                                std::abs(seen.p.z) < 0.999;
            seen.surface = onWall ? 1 : 0;
        } else if (onBack) {
            seen.p = ray.at(*onBack);
            seen.normal = Vec3d(0, 0, 1);
            seen.surface = 2;
        } else {
            return seen;
        }
        seen.lit = dot(seen.normal, towardsLight) > 0 &&
                   !intersectBoxWithHole({seen.p + 1e-7 * seen.normal, towardsLight});
        return seen;
    };
    // A pixel's corners must see what its centre sees, or it lies on an edge and is skipped.
    const double pixelAngle = 2 * std::tan(camera.vfovDegrees * kPi / 360) / camera.height;
    int wallPixels = 0, throughHole = 0;
    const int checked = expectPixelsMatch(
        image, camera,
        [&](const RayD& ray) -> std::optional<Radiance> {
            const Seen centre = see(ray);
            Vec3d u, v;
            coordinateSystem(ray.direction, u, v);
            for (const auto& [du, dv] :
                 {std::pair{1.0, 1.0}, {1.0, -1.0}, {-1.0, 1.0}, {-1.0, -1.0}}) {
                const Seen corner = see(
                    {ray.origin, normalize(ray.direction + 0.75 * pixelAngle * (du * u + dv * v))});
                if (corner.surface != centre.surface || corner.lit != centre.lit)
                    return std::nullopt;
            }
            if (centre.surface == 3) return Radiance{0.1, 0.1, 0.1};
            const double irradiance = centre.lit ? 3 * dot(centre.normal, towardsLight) : 0;
            if (centre.surface == 1 && centre.lit) ++wallPixels;
            if (centre.surface == 2 && centre.lit) ++throughHole;
            const Radiance albedo = centre.surface == 0   ? Radiance{0.8, 0.8, 0.8}
                                    : centre.surface == 1 ? Radiance{0.2, 0.6, 0.2}
                                                          : Radiance{0.5, 0.5, 0.5};
            return irradiance * albedo;
        },
        1e-4, 1e-5);
    EXPECT_GT(checked, 2600);
    EXPECT_GT(wallPixels, 40) << "the lit part of the hole's wall is in view";
    EXPECT_GT(throughHole, 40) << "light through the hole reaches the wall behind";
}

// A floor under a glass lens (two spheres' intersection) and a glass union of two spheres, lit
// from straight above: in each shadow the light crosses two surfaces of transmission 0.5, so the
// floor receives a quarter (a sixteenth if the union kept its inner surfaces).
TEST(CliCsg, ShadowsThroughGlassCsgsCrossOnlyTheirOuterSurfaces) {
    json scene = json::parse(R"({
      "background": 0, "ambient": 0,
      "materials": { "floor": { "diffuse": 0.5 },
                     "glass": { "diffuse": 0, "transmission": 0.5, "ior": 1.5 } },
      "objects": [
        { "type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "floor" },
        { "type": "csg", "operation": "intersection", "material": "glass", "objects": [
          { "type": "sphere", "center": [0, 1, 0], "radius": 1 },
          { "type": "sphere", "center": [0, 2, 0], "radius": 1 } ] },
        { "type": "csg", "operation": "union", "material": "glass", "objects": [
          { "type": "sphere", "center": [1.6, 1.5, 0], "radius": 0.7 },
          { "type": "sphere", "center": [2.4, 1.5, 0], "radius": 0.7 } ] }
      ],
      "lights": [ { "type": "directional", "direction": [0, -1, 0], "irradiance": 2 } ]
    })");
    // Low, so that no eye ray reaches the glass (which is higher than the eye).
    const CameraModel camera{.position = {1.2, 0.7, 3},
                             .lookAt = {1.2, 0, 0},
                             .vfovDegrees = 16,
                             .width = 96,
                             .height = 24};
    camera.placeIn(scene);
    scene["render"]["max_depth"] = 1;
    const Image image = renderScene(scene).image;
    // Squared distances in the floor's plane from each shadow's circles (the lens's rim has
    // radius sqrt(3)/2), positive outside.
    const auto outsideBy = [](const Vec3d& p) {
        const double lens = std::hypot(p.x, p.z) - std::sqrt(0.75);
        const double left = std::hypot(p.x - 1.6, p.z) - 0.7;
        const double right = std::hypot(p.x - 2.4, p.z) - 0.7;
        return std::pair{lens, std::min(left, right)};
    };
    int shadowed = 0;
    const int checked = expectPixelsMatch(
        image, camera,
        [&](const RayD& ray) -> std::optional<Radiance> {
            const std::optional<double> t = intersectPlane(ray, Vec3d(0, 0, 0), Vec3d(0, 1, 0));
            if (!t) return std::nullopt;
            const auto [lens, spheres] = outsideBy(ray.at(*t));
            if (std::abs(lens) < 0.03 || std::abs(spheres) < 0.03) return std::nullopt;
            const bool inShadow = lens < 0 || spheres < 0;
            shadowed += inShadow;
            const double L = 0.5 * 2 * (inShadow ? 0.25 : 1);
            return Radiance{L, L, L};
        },
        1e-4, 1e-5);
    EXPECT_GT(checked, 1500);
    EXPECT_GT(shadowed, 300);
}

// The lamp: the box [-0.5, 0.5] x [1, 1.5] x [-0.5, 0.5] cut by the box x <= 0.1 of a bigger one,
// that is the box [-0.5, 0.1] x [1, 1.5] x [-0.5, 0.5], its faces coming from both children
// (most of each child's surface hidden). The floor beside it sees its bottom and its faces at
// x = 0.1 and z = 0.5.
const Vec3d kLampMin(-0.5, 1, -0.5), kLampMax(0.1, 1.5, 0.5);
const CameraModel kFloorCamera{.position = {0.9, 0.9, 0.8},
                               .lookAt = {0.9, 0, 0.8},
                               .up = {0, 0, -1},
                               .vfovDegrees = 2 * std::atan(0.4 / 0.9) * 180 / kPi,
                               .width = 9,
                               .height = 9};

json csgLampOverFloor(const std::string& integrator, int spp) {
    return emitterOverFloor(
        json::parse(
            R"({ "type": "disk", "center": [0.9, 0, 0.8], "normal": [0, 1, 0], "radius": 0.6 })"),
        json::parse(R"({ "type": "csg", "operation": "intersection", "objects": [
            { "type": "box", "min": [-0.5, 1, -0.5], "max": [0.5, 1.5, 0.5] },
            { "type": "box", "min": [-2, 0.5, -2], "max": [0.1, 2, 2] } ] })"),
        kFloorCamera, integrator, spp);
}

PixelOracle floorBesideTheCsgLamp() {
    return lambertianFloor(0.5, [](const Vec3d& p) {
        return 2 * boxIrradiance(p, Vec3d(0, 1, 0), kLampMin, kLampMax);
    });
}

// Most samples of the children's faces fall on hidden parts and give nothing: 32768 samples keep
// the noise near 0.7%.
TEST(CliCsg, AnEmissiveCsgLightsTheFloorAsItsVisibleFacesClosedFormsSayInPath) {
    const Image image = renderScene(csgLampOverFloor("path", 32768)).image;
    EXPECT_EQ(expectPixelsMatch(image, kFloorCamera, floorBesideTheCsgLamp(), 0.03, 0), 81);
}

TEST(CliCsg, AnEmissiveCsgLightsTheFloorAsItsVisibleFacesClosedFormsSayInRadiosity) {
    json scene = csgLampOverFloor("radiosity", 1);
    scene["radiosity"] = {{"patch_size", 0.25}};
    const Image image = renderScene(scene).image;
    EXPECT_EQ(expectPixelsMatch(image, kFloorCamera, floorBesideTheCsgLamp(), 0.03, 0), 81);
}

// A cube model, closed or with its top left open, as a csg's first child: the closed one
// renders (the carved box beside the camera's line of sight), the open one is refused with one
// line naming the object.
TEST(CliCsg, MeshesAreChildrenWhenClosedAndRefusedWhenOpen) {
    const TempFolder folder;
    std::string vertices;
    for (const char* v :
         {"-1 -1 -1", "1 -1 -1", "1 1 -1", "-1 1 -1", "-1 -1 1", "1 -1 1", "1 1 1", "-1 1 1"})
        vertices += std::string("v ") + v + "\n";
    // Counter-clockwise seen from outside: the faces point out.
    const std::string sides = "f 1 4 3 2\nf 5 6 7 8\nf 1 5 8 4\nf 2 3 7 6\nf 1 2 6 5\n";
    folder.write("closed.obj", vertices + sides + "f 4 8 7 3\n");
    folder.write("open.obj", vertices + sides);
    const auto sceneWith = [](const std::string& file) {
        return R"({
  "render": { "width": 8, "height": 6, "spp": 1 },
  "camera": { "position": [0, 1, 5], "look_at": [0, 0, 0] },
  "lights": [ { "type": "point", "position": [2, 5, 3], "intensity": 40 } ],
  "objects": [
    { "type": "csg", "operation": "difference", "objects": [
      { "type": "mesh", "file": ")" +
               file + R"(" },
      { "type": "sphere", "center": [1, 1, 1], "radius": 0.8 } ] }
  ]
}
)";
    };
    folder.write("closed.json", sceneWith("closed.obj"));
    folder.write("open.json", sceneWith("open.obj"));
    const RunResult closed =
        runLancer({"closed.json", "-o", "closed.png", "--quiet"}, folder.path());
    EXPECT_EQ(closed.exitStatus, 0) << closed;
    const RunResult open = runLancer({"open.json", "-o", "open.png", "--quiet"}, folder.path());
    EXPECT_EQ(open.exitStatus, 2) << open;
    ASSERT_EQ(open.errorLines().size(), 1u) << open;
    EXPECT_EQ(open.errorLines()[0].rfind("open.json:7:7: error: a mesh here is not a solid", 0), 0u)
        << open;
    EXPECT_FALSE(fs::exists(folder / "open.png"));
}

}  // namespace
}  // namespace lancer::test
