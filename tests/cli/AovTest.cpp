// Auxiliary outputs (--aov albedo,normal,depth; docs/SCENE-FORMAT.md, "Exposure, tone mapping and
// extra outputs"): their values on scenes whose first hits have closed forms, with one sample per
// pixel through the pixel centre (the camera's own ray, made here by the library's Camera), and
// what must not change them (threads, the integrator) or be changed by them (the image).

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <optional>

#include "LancerRun.h"
#include "PfmFile.h"
#include "math/Vec3.h"
#include "scene/PerspectiveCamera.h"

namespace lancer::test {
namespace {

// The image and the auxiliary outputs of one run, by name ("image", "albedo", ...), and the
// raw bytes of each file.
struct AovRun {
    std::map<std::string, Image> images;
    std::map<std::string, std::string> bytes;
};

AovRun renderWithAovs(const nlohmann::json& scene, const std::vector<std::string>& options,
                      const std::string& aovs = "albedo,normal,depth") {
    const TempFolder folder;
    folder.write("scene.json", scene.dump(2));
    std::vector<std::string> arguments = {"scene.json", "-o", "out.pfm", "--quiet", "--aov", aovs};
    arguments.insert(arguments.end(), options.begin(), options.end());
    const RunResult run = runLancer(arguments, folder.path());
    if (run.exitStatus != 0) throw std::runtime_error("lancer failed: " + run.standardError);
    AovRun result;
    const auto read = [&](const std::string& name, const fs::path& file) {
        result.images[name] = loadImage(folder / file);
        result.bytes[name] = readFile(folder / file);
    };
    read("image", "out.pfm");
    for (const std::string name : {"albedo", "normal", "depth"})
        if (aovs.find(name) != std::string::npos) read(name, "out." + name + ".exr");
    return result;
}

// The camera of the scenes below, as lancer makes it.
struct TestCamera {
    Vec3d position, lookAt;
    int width, height;

    nlohmann::json json() const {
        return {{"position", {position.x, position.y, position.z}},
                {"look_at", {lookAt.x, lookAt.y, lookAt.z}},
                {"vfov", 40}};
    }
    // The ray through the centre of pixel (x, y), in double from the float one.
    std::pair<Vec3d, Vec3d> ray(int x, int y) const {
        const PerspectiveCamera camera(CameraFrame(Vec3(position), Vec3(lookAt), Vec3(0, 1, 0)),
                                       40);
        const Ray r =
            *camera.generateRay(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f, width,
                                height, Vec2(0.5f, 0.5f));
        return {Vec3d(r.origin), Vec3d(r.direction)};
    }
};

nlohmann::json sceneWith(const TestCamera& camera, const nlohmann::json& materials,
                         const nlohmann::json& objects) {
    return {{"render", {{"width", camera.width}, {"height", camera.height}, {"spp", 1}}},
            {"camera", camera.json()},
            {"materials", materials},
            {"objects", objects},
            {"lights", {{{"type", "point"}, {"position", {0, 4, 4}}, {"intensity", 20}}}}};
}

// Float rounding of the hit point and of the pixel's ray (the test's ray is the same float ray,
// intersected in double): well under 1e-4 at these distances of a few units.
constexpr double kTolerance = 1e-4;

void expectRgb(const Image& image, int x, int y, const Vec3d& expected, const std::string& what) {
    for (int k = 0; k < 3; ++k)
        EXPECT_NEAR(image.at(x, y)[static_cast<std::size_t>(k)], expected[k], kTolerance)
            << what << " at (" << x << ", " << y << "), channel " << k;
}

// The nearest t > 0 at which the ray meets the sphere of radius r about the origin.
std::optional<double> hitSphere(const Vec3d& o, const Vec3d& d, double r) {
    const double b = dot(o, d), c = dot(o, o) - r * r;
    const double disc = b * b - c;
    if (disc < 0) return std::nullopt;
    const double t = -b - std::sqrt(disc);
    return t > 0 ? std::optional<double>(t) : std::nullopt;
}

TEST(CliAov, SphereNormalsAndDepthsAreTheAnalyticOnesAndZeroOnTheBackground) {
    const TestCamera camera{{0.3, 0.4, 5}, {0, 0, 0}, 24, 18};
    const nlohmann::json scene = sceneWith(
        camera, {{"red", {{"diffuse", {0.7, 0.2, 0.1}}}}},
        {{{"type", "sphere"}, {"center", {0, 0, 0}}, {"radius", 1}, {"material", "red"}}});
    const AovRun run = renderWithAovs(scene, {});
    int hits = 0, misses = 0;
    for (int y = 0; y < camera.height; ++y)
        for (int x = 0; x < camera.width; ++x) {
            const auto [o, d] = camera.ray(x, y);
            const std::optional<double> t = hitSphere(o, d, 1);
            if (t) {
                ++hits;
                expectRgb(run.images.at("normal"), x, y, normalize(o + *t * d), "normal");
                expectRgb(run.images.at("depth"), x, y, Vec3d(*t), "depth");
                expectRgb(run.images.at("albedo"), x, y, Vec3d(0.7, 0.2, 0.1), "albedo");
            } else if (!hitSphere(o, d, 1.02)) {  // clear of the silhouette's rounding
                ++misses;
                for (const std::string name : {"normal", "depth", "albedo"})
                    expectRgb(run.images.at(name), x, y, Vec3d(0), name + " of the background");
            }
        }
    EXPECT_GT(hits, 40);
    EXPECT_GT(misses, 150);
}

// The plane y = 0 seen from above and from below: the depth along the ray is -o.y / d.y, and the
// normal is turned towards the camera.
TEST(CliAov, PlaneDepthIsTheClosedFormAndItsNormalFacesTheCamera) {
    for (const double height : {1.5, -1.5}) {
        const TestCamera camera{{0.2, height, 3}, {0, 0, -2}, 20, 16};
        const nlohmann::json scene = sceneWith(camera, {{"grey", {{"diffuse", 0.5}}}},
                                               {{{"type", "plane"},
                                                 {"point", {0, 0, 0}},
                                                 {"normal", {0, 1, 0}},
                                                 {"material", "grey"}}});
        const AovRun run = renderWithAovs(scene, {}, "depth,normal");
        EXPECT_EQ(run.images.count("albedo"), 0u);
        int hits = 0;
        for (int y = 0; y < camera.height; ++y)
            for (int x = 0; x < camera.width; ++x) {
                const auto [o, d] = camera.ray(x, y);
                const double t = -o.y / d.y;
                if (t > 0) {
                    ++hits;
                    expectRgb(run.images.at("depth"), x, y, Vec3d(t), "depth");
                    expectRgb(run.images.at("normal"), x, y, Vec3d(0, height > 0 ? 1 : -1, 0),
                              "normal");
                } else {
                    expectRgb(run.images.at("depth"), x, y, Vec3d(0), "depth above the horizon");
                }
            }
        EXPECT_GT(hits, 100) << height;
    }
}

// The normal output is the shading normal, normal map included: a constant map (0.8, 0.5, 0.9) is
// n = 0.6 T + 0.8 N in the tangent frame, and on the plane y = 0 (uv = (x, z)) T is +x.
TEST(CliAov, NormalIsTheMappedShadingNormal) {
    const TempFolder maps;
    writePfm(lancer::Image(4, 4, Color(0.8f, 0.5f, 0.9f)), maps / "tilt.pfm");
    const TestCamera camera{{0.2, 2, 0.5}, {0, 0, 0}, 12, 9};
    const nlohmann::json scene = sceneWith(
        camera, {{"mapped", {{"diffuse", 0.5}, {"normal_map", (maps / "tilt.pfm").string()}}}},
        {{{"type", "plane"}, {"point", {0, 0, 0}}, {"normal", {0, 1, 0}}, {"material", "mapped"}}});
    const Image normal = renderWithAovs(scene, {}, "normal").images.at("normal");
    for (int y = 0; y < camera.height; ++y)
        for (int x = 0; x < camera.width; ++x)
            expectRgb(normal, x, y, Vec3d(0.6, 0.8, 0), "mapped normal");
}

// A mirror (the plane z = 0) that shows a checkered floor (y = 0, uv = (x, z)): the albedo is the
// floor's checker at the reflected ray's hit, the normal and depth are the mirror's.
TEST(CliAov, AlbedoIsTheCheckerSeenThroughAMirror) {
    const TestCamera camera{{0.1, 1, 3}, {0, 0.45, 0}, 24, 18};
    const Vec3d even(0.9, 0.5, 0.1), odd(0.1, 0.2, 0.7);
    const double scale = 0.5;
    const nlohmann::json scene = sceneWith(
        camera,
        {{"mirror", {{"diffuse", 0}, {"reflection", 1}}},
         {"floor",
          {{"diffuse",
            {{"checker",
              {{"even", {even.x, even.y, even.z}},
               {"odd", {odd.x, odd.y, odd.z}},
               {"scale", scale}}}}}}}},
        {{{"type", "plane"}, {"point", {0, 0, 0}}, {"normal", {0, 0, 1}}, {"material", "mirror"}},
         {{"type", "plane"}, {"point", {0, 0, 0}}, {"normal", {0, 1, 0}}, {"material", "floor"}}});
    const AovRun run = renderWithAovs(scene, {});
    int throughTheMirror = 0, onTheFloor = 0;
    for (int y = 0; y < camera.height; ++y)
        for (int x = 0; x < camera.width; ++x) {
            auto [o, d] = camera.ray(x, y);
            const double tMirror = -o.z / d.z, tFloor = d.y < 0 ? -o.y / d.y : INFINITY;
            const bool mirror = tMirror < tFloor;
            if (mirror) {
                expectRgb(run.images.at("normal"), x, y, Vec3d(0, 0, 1), "mirror normal");
                expectRgb(run.images.at("depth"), x, y, Vec3d(tMirror), "mirror depth");
                o = o + tMirror * d;
                d.z = -d.z;
            }
            if (d.y >= 0) {
                expectRgb(run.images.at("albedo"), x, y, Vec3d(0), "albedo of the sky");
                continue;
            }
            const Vec3d p = o + (-o.y / d.y) * d;
            const double u = p.x / scale, v = p.z / scale;
            // Clear of the squares' edges, where the float hit point may fall either side.
            if (std::abs(u - std::round(u)) < 1e-3 || std::abs(v - std::round(v)) < 1e-3) continue;
            const bool isEven =
                (static_cast<long long>(std::floor(u)) + static_cast<long long>(std::floor(v))) %
                    2 ==
                0;
            expectRgb(run.images.at("albedo"), x, y, isEven ? even : odd, "albedo");
            ++(mirror ? throughTheMirror : onTheFloor);
        }
    EXPECT_GT(throughTheMirror, 50);
    EXPECT_GT(onTheFloor, 50);
}

// With no bounce allowed, the mirror's pixels end on the mirror, which has no diffuse colour.
TEST(CliAov, AlbedoIsZeroWhereMaxDepthStopsTheRayAtAMirror) {
    const TestCamera camera{{0, 0, 3}, {0, 0, 0}, 8, 6};
    const nlohmann::json scene = sceneWith(
        camera, {{"mirror", {{"diffuse", 0}, {"reflection", 1}}}, {"wall", {{"diffuse", 0.6}}}},
        {{{"type", "plane"}, {"point", {0, 0, 0}}, {"normal", {0, 0, 1}}, {"material", "mirror"}},
         {{"type", "plane"}, {"point", {0, 0, 5}}, {"normal", {0, 0, 1}}, {"material", "wall"}}});
    const Image seen = renderWithAovs(scene, {}, "albedo").images.at("albedo");
    const Image stopped = renderWithAovs(scene, {"--max-depth", "0"}, "albedo").images.at("albedo");
    for (int y = 0; y < camera.height; ++y)
        for (int x = 0; x < camera.width; ++x) {
            expectRgb(seen, x, y, Vec3d(0.6), "the wall behind the camera, in the mirror");
            expectRgb(stopped, x, y, Vec3d(0), "the mirror at max_depth 0");
        }
}

// Glass splits a ray; the branch that carries the most light is followed: at normal incidence on
// a slab of index 1.5, the refracted one (96% of the light), to the wall behind.
TEST(CliAov, AlbedoIsTheWallSeenThroughGlass) {
    const TestCamera camera{{0, 0, 4}, {0, 0, 0}, 8, 6};
    const nlohmann::json scene = sceneWith(
        camera,
        {{"glass", {{"diffuse", 0}, {"transmission", 1}, {"ior", 1.5}}},
         {"wall", {{"diffuse", {0.2, 0.6, 0.3}}}}},
        {{{"type", "box"}, {"min", {-5, -5, -0.5}}, {"max", {5, 5, 0.5}}, {"material", "glass"}},
         {{"type", "plane"}, {"point", {0, 0, -3}}, {"normal", {0, 0, 1}}, {"material", "wall"}}});
    const AovRun run = renderWithAovs(scene, {});
    for (int y = 0; y < camera.height; ++y)
        for (int x = 0; x < camera.width; ++x) {
            const auto [o, d] = camera.ray(x, y);
            expectRgb(run.images.at("albedo"), x, y, Vec3d(0.2, 0.6, 0.3), "albedo");
            expectRgb(run.images.at("depth"), x, y, Vec3d((0.5 - o.z) / d.z), "depth of the glass");
        }
}

// A scene with a bit of everything the probe meets: glass, a mirror, a textured floor.
nlohmann::json busyScene() {
    nlohmann::json scene = loadWhittedScene();
    scene["render"]["width"] = 48;
    scene["render"]["height"] = 36;
    scene["render"]["spp"] = 4;
    scene["render"]["filter"] = "mitchell";
    return scene;
}

TEST(CliAov, FilesAreTheSameBytesWhateverTheThreads) {
    const nlohmann::json scene = busyScene();
    const AovRun one = renderWithAovs(scene, {"--threads", "1"});
    const AovRun three = renderWithAovs(scene, {"--threads", "3"});
    for (const std::string name : {"image", "albedo", "normal", "depth"})
        EXPECT_TRUE(one.bytes.at(name) == three.bytes.at(name)) << name;
}

TEST(CliAov, ChangeNothingInTheImage) {
    const nlohmann::json scene = busyScene();
    const std::string plain = renderScene(scene).bytes;
    EXPECT_TRUE(renderWithAovs(scene, {}).bytes.at("image") == plain);
}

// The outputs come from the camera rays alone: every integrator writes the same files (its own
// samples differ, the camera's do not).
TEST(CliAov, AreTheSameForEveryIntegrator) {
    nlohmann::json scene = busyScene();
    scene["render"]["spp"] = 2;
    // A rough solution: it lights the image, not the outputs, and the default one takes seconds.
    scene["radiosity"] = {{"max_shots", 20}, {"subdivision_levels", 0}};
    const AovRun whitted = renderWithAovs(scene, {"--integrator", "whitted"});
    for (const std::string integrator : {"path", "radiosity"}) {
        const AovRun other = renderWithAovs(scene, {"--integrator", integrator});
        for (const std::string name : {"albedo", "normal", "depth"})
            EXPECT_TRUE(other.bytes.at(name) == whitted.bytes.at(name))
                << integrator << " " << name;
    }
}

// A crop fills its window as the full render does and leaves the rest 0; adaptive sampling
// averages whatever samples a pixel took, with the same weights as the image.
TEST(CliAov, CropFillsItsWindowAsTheFullRender) {
    const nlohmann::json scene = busyScene();
    const AovRun full = renderWithAovs(scene, {});
    const AovRun crop = renderWithAovs(scene, {"--crop", "5,7,30,20"});
    for (const std::string name : {"albedo", "normal", "depth"}) {
        const Image& a = full.images.at(name);
        const Image& b = crop.images.at(name);
        for (int y = 0; y < a.height; ++y)
            for (int x = 0; x < a.width; ++x) {
                const bool inside = x >= 5 && x < 30 && y >= 7 && y < 20;
                for (std::size_t k = 0; k < 3; ++k)
                    ASSERT_EQ(b.at(x, y)[k], inside ? a.at(x, y)[k] : 0.0f)
                        << name << " at (" << x << ", " << y << ")";
            }
    }
}

TEST(CliAov, AdaptiveSamplingAveragesThePixelsSamples) {
    const TestCamera camera{{0.2, 1.5, 3}, {0, 0, -2}, 20, 16};
    nlohmann::json scene = sceneWith(
        camera, {{"grey", {{"diffuse", 0.5}}}},
        {{{"type", "plane"}, {"point", {0, 0, 0}}, {"normal", {0, 1, 0}}, {"material", "grey"}}});
    scene["render"].erase("spp");
    scene["render"]["adaptive"] = {{"min_spp", 4}, {"max_spp", 64}, {"threshold", 0.01}};
    scene["render"]["filter"] = "mitchell";
    const AovRun run = renderWithAovs(scene, {}, "normal,albedo");
    // Each pixel's samples hit the plane (the normal (0, 1, 0), the albedo 0.5) or the sky (0):
    // a weighted average of those, so exactly the plane's below the horizon's pixels.
    const Image& normal = run.images.at("normal");
    const Image& albedo = run.images.at("albedo");
    EXPECT_EQ(normal.at(10, 15)[1], 1.0f);
    EXPECT_EQ(albedo.at(10, 15)[0], 0.5f);
    for (int y = 0; y < camera.height; ++y)
        for (int x = 0; x < camera.width; ++x) {
            EXPECT_EQ(normal.at(x, y)[0], 0.0f);
            EXPECT_NEAR(albedo.at(x, y)[0], 0.5f * normal.at(x, y)[1], 1e-6);
        }
}

}  // namespace
}  // namespace lancer::test
