// lancer's BVH against Intel Embree 3 on the same meshes and the same rays: build time, bytes per
// triangle, and single-ray throughput (Mrays/s) for primary, diffuse-bounce and shadow rays at 1
// and 2 threads. lancer is measured through lancer::Mesh, the renderer's own path (closest hits
// include filling the hit record); Embree through rtcIntersect1 / rtcOccluded1. Embree is linked
// by this benchmark only.
//
//   embree_comparison [--assets DIR] [--only NAME] [--min-time SECONDS] [--embree-config STRING]
//
// Prints Markdown tables on stdout and progress on stderr.

#include <embree3/rtcore.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "accel/Mesh.h"
#include "io/ObjLoader.h"

namespace lancer {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

constexpr int kThreadCounts[] = {1, 2};
constexpr int kImageSize = 1024;  // primary rays: kImageSize^2
constexpr int kTileSize = 16;     // primary rays are ordered by tiles, as the renderer traces them
constexpr std::size_t kChunkSize = 4096;  // rays a thread takes at a time
constexpr int kBuildRepetitions = 3;      // builds are timed this many times, the best kept
constexpr int kTraceRounds = 3;  // the structures take turns this many times, the best kept

struct Options {
    fs::path assets = LANCER_SHARED_ASSETS;
    std::string only;      // run only the meshes whose name contains this
    double minTime = 1.0;  // seconds of tracing per structure, ray type and thread count
    std::string embreeConfig;
};

struct BenchMesh {
    std::string name;
    TriangleMesh triangles;
    Vec3 cameraDirection;  // from the mesh's centre towards the camera
    bool lightInside;      // the point light hangs inside the box instead of outside the mesh
};

double secondsSince(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

TriangleMesh loadObj(const fs::path& path) {
    std::vector<std::string> warnings;
    // Textures do not matter here: every map_Kd falls back to its Kd colour.
    const auto noTexture = [](const fs::path&,
                              ImageReader::Content) -> std::shared_ptr<const Texture> {
        return nullptr;
    };
    return *ObjLoader::load(path, noTexture, warnings);
}

// A cube whose six faces are cells x cells grids of two triangles each (12 cells^2 triangles),
// projected onto the unit sphere and displaced radially by several octaves of waves: a closed,
// bumpy mesh whose dents and ridges shadow and catch bounce rays at every scale.
TriangleMesh displacedSphere(int cells) {
    const auto radius = [](const Vec3& d) {
        float r = 1, amplitude = 0.15f, frequency = 4;
        for (int octave = 0; octave < 6; ++octave) {
            const float o = static_cast<float>(octave);
            r += amplitude * std::sin(frequency * d.x + 1.3f * o) *
                 std::sin(frequency * d.y + 2.1f + o) * std::sin(frequency * d.z + 0.7f * o);
            amplitude *= 0.5f;
            frequency *= 2.1f;
        }
        return r;
    };
    TriangleMesh mesh;
    const auto n = static_cast<std::uint32_t>(cells);
    for (int face = 0; face < 6; ++face) {
        const int axis = face / 2;
        const float side = face % 2 == 0 ? 1.0f : -1.0f;
        const auto base = static_cast<std::uint32_t>(mesh.positions.size());
        for (std::uint32_t i = 0; i <= n; ++i) {
            for (std::uint32_t j = 0; j <= n; ++j) {
                const float u = -1 + 2 * static_cast<float>(i) / static_cast<float>(n);
                const float v = -1 + 2 * static_cast<float>(j) / static_cast<float>(n);
                Vec3 p;
                p[axis] = side;
                // Swapping u and v on the negative faces keeps every face counter-clockwise
                // seen from outside.
                p[(axis + 1) % 3] = side > 0 ? u : v;
                p[(axis + 2) % 3] = side > 0 ? v : u;
                const Vec3 d = normalize(p);
                mesh.positions.push_back(radius(d) * d);
            }
        }
        const auto vertex = [&](std::uint32_t i, std::uint32_t j) {
            return base + i * (n + 1) + j;
        };
        for (std::uint32_t i = 0; i < n; ++i) {
            for (std::uint32_t j = 0; j < n; ++j) {
                mesh.indices.insert(mesh.indices.end(),
                                    {vertex(i, j), vertex(i + 1, j), vertex(i + 1, j + 1),
                                     vertex(i, j), vertex(i + 1, j + 1), vertex(i, j + 1)});
            }
        }
    }
    mesh.faceMaterials.assign(mesh.triangleCount(), 0);
    return mesh;
}

std::vector<BenchMesh> loadMeshes(const Options& options) {
    struct Source {
        const char* name;
        std::function<TriangleMesh()> make;
        Vec3 cameraDirection;
        bool lightInside;
    };
    const Vec3 oblique(0.35f, 0.45f, 1);
    const fs::path a = options.assets;
    const Source sources[] = {
        {"cornell_box_sphere", [&] { return loadObj(a / "cornell_box/CornellBox-Sphere.obj"); },
         Vec3(0, 0, 1), true},
        {"bunny_lowres", [&] { return loadObj(a / "stanford_bunny_lowres/bunny.obj"); }, oblique,
         false},
        {"utah_teapot", [&] { return loadObj(a / "utah_teapot/teapot.obj"); }, oblique, false},
        {"spot", [&] { return loadObj(a / "spot/spot_textured.obj"); }, oblique, false},
        {"stanford_bunny", [&] { return loadObj(a / "stanford_bunny/stanford-bunny.obj"); },
         oblique, false},
        {"sphere_1M", [] { return displacedSphere(289); }, oblique, false},
        {"sphere_5M", [] { return displacedSphere(646); }, oblique, false},
    };
    std::vector<BenchMesh> meshes;
    for (const Source& source : sources) {
        if (std::string(source.name).find(options.only) == std::string::npos) continue;
        std::fprintf(stderr, "loading %s\n", source.name);
        meshes.push_back(
            {source.name, source.make(), normalize(source.cameraDirection), source.lightInside});
    }
    return meshes;
}

// The same rays for both tracers. tMax is infinite for closest hits and 1 for shadow rays, which
// run from a surface point to the light.
struct Rays {
    std::vector<Ray> rays;
    float tMax = kInfinity;

    std::size_t size() const { return rays.size(); }
};

struct RaySets {
    Rays primary, bounce, shadow;
};

// Primary rays of a pinhole camera framing the mesh's bounding sphere; bounce and shadow rays
// start at the primary hits (found by lancer), offset off the surface as the renderer does.
RaySets makeRays(const BenchMesh& bench, const Mesh& mesh) {
    const Bounds3 box = mesh.bounds();
    const Vec3 centre = 0.5f * (box.min + box.max);
    const float radius = 0.5f * length(box.diagonal());
    const Vec3 eye = centre + 2.2f * radius * bench.cameraDirection;
    const Vec3 forward = normalize(centre - eye);
    const Vec3 right = normalize(cross(forward, Vec3(0, 1, 0)));
    const Vec3 up = cross(right, forward);
    const float halfHeight = std::tan(radians(45.0f) / 2);
    const Vec3 light = bench.lightInside ? centre + Vec3(0, 0.45f * box.diagonal().y, 0)
                                         : centre + radius * Vec3(0.6f, 1.2f, 0.9f);

    RaySets sets;
    sets.primary.rays.reserve(std::size_t{kImageSize} * kImageSize);
    for (int tileY = 0; tileY < kImageSize; tileY += kTileSize)
        for (int tileX = 0; tileX < kImageSize; tileX += kTileSize)
            for (int y = tileY; y < tileY + kTileSize; ++y)
                for (int x = tileX; x < tileX + kTileSize; ++x) {
                    const float sx = (2 * (static_cast<float>(x) + 0.5f) / kImageSize - 1);
                    const float sy = (1 - 2 * (static_cast<float>(y) + 0.5f) / kImageSize);
                    const Vec3 d = forward + halfHeight * (sx * right + sy * up);
                    sets.primary.rays.push_back({eye, normalize(d)});
                }

    std::mt19937 rng(7);
    std::uniform_real_distribution<float> uniform(0, 1);
    sets.shadow.tMax = 1;
    for (const Ray& ray : sets.primary.rays) {
        const std::optional<Hit> found = mesh.intersect(ray, kInfinity);
        if (!found) continue;
        const Hit& hit = *found;
        // Cosine-distributed around the normal on the side the camera sees.
        const Vec3 n = dot(hit.ng, ray.direction) < 0 ? hit.ng : -hit.ng;
        Vec3 s, t;
        coordinateSystem(n, s, t);
        const float r = std::sqrt(uniform(rng)), phi = 2 * kPi * uniform(rng);
        const float z = std::sqrt(std::max(0.0f, 1 - r * r));
        const Vec3 w = normalize(r * std::cos(phi) * s + r * std::sin(phi) * t + z * n);
        sets.bounce.rays.push_back({offsetRayOrigin(hit.p, hit.pError, hit.ng, w), w});
        const Vec3 origin = offsetRayOrigin(hit.p, hit.pError, hit.ng, light - hit.p);
        sets.shadow.rays.push_back({origin, light - origin});
    }
    return sets;
}

// Net bytes Embree holds, as reported by its memory monitor.
std::atomic<std::int64_t> embreeBytes{0};

bool monitorEmbreeMemory(void*, ssize_t bytes, bool) {
    embreeBytes += bytes;
    return true;
}

class EmbreeDevice {
public:
    explicit EmbreeDevice(const std::string& config)
        : device_(rtcNewDevice(config.empty() ? nullptr : config.c_str())) {
        if (!device_) throw std::runtime_error("cannot create the Embree device");
        rtcSetDeviceMemoryMonitorFunction(device_, monitorEmbreeMemory, nullptr);
    }
    ~EmbreeDevice() { rtcReleaseDevice(device_); }
    EmbreeDevice(const EmbreeDevice&) = delete;
    EmbreeDevice& operator=(const EmbreeDevice&) = delete;

    RTCDevice get() const { return device_; }

private:
    RTCDevice device_;
};

// One Embree scene over one triangle mesh. Vertices and indices are shared with Embree (not
// copied), so that the memory monitor sees the acceleration structure alone.
class EmbreeMesh {
public:
    EmbreeMesh(const EmbreeDevice& device, const TriangleMesh& mesh, RTCBuildQuality quality)
        // Embree reads vertices with 16-byte loads: one float of padding after the last.
        : vertices_(3 * mesh.positions.size() + 1), indices_(mesh.indices) {
        for (std::size_t i = 0; i < mesh.positions.size(); ++i)
            for (int k = 0; k < 3; ++k)
                vertices_[3 * i + static_cast<std::size_t>(k)] = mesh.positions[i][k];
        const std::int64_t before = embreeBytes;
        const Clock::time_point start = Clock::now();
        scene_ = rtcNewScene(device.get());
        rtcSetSceneBuildQuality(scene_, quality);
        RTCGeometry geometry = rtcNewGeometry(device.get(), RTC_GEOMETRY_TYPE_TRIANGLE);
        rtcSetGeometryBuildQuality(geometry, quality);
        rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                   vertices_.data(), 0, 3 * sizeof(float), mesh.positions.size());
        rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                   indices_.data(), 0, 3 * sizeof(std::uint32_t),
                                   mesh.triangleCount());
        rtcCommitGeometry(geometry);
        rtcAttachGeometry(scene_, geometry);
        rtcReleaseGeometry(geometry);
        rtcCommitScene(scene_);
        buildSeconds_ = secondsSince(start);
        accelerationBytes_ = static_cast<std::size_t>(embreeBytes - before);
        if (rtcGetDeviceError(device.get()) != RTC_ERROR_NONE)
            throw std::runtime_error("Embree failed to build the scene");
    }
    ~EmbreeMesh() { rtcReleaseScene(scene_); }
    EmbreeMesh(const EmbreeMesh&) = delete;
    EmbreeMesh& operator=(const EmbreeMesh&) = delete;

    double buildSeconds() const { return buildSeconds_; }
    std::size_t accelerationBytes() const { return accelerationBytes_; }
    // The acceleration structure plus the vertex and index buffers it traces.
    std::size_t memoryBytes() const {
        return accelerationBytes_ + (vertices_.size() - 1) * sizeof(float) +
               indices_.size() * sizeof(std::uint32_t);
    }

    // The closest hit's t, or -1.
    float intersect(const Ray& ray, float tMax) const {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        RTCRayHit rayHit;
        setRay(rayHit.ray, ray, tMax);
        rayHit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rayHit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
        rtcIntersect1(scene_, &context, &rayHit);
        return rayHit.hit.geomID == RTC_INVALID_GEOMETRY_ID ? -1.0f : rayHit.ray.tfar;
    }

    bool occluded(const Ray& ray, float tMax) const {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        RTCRay r;
        setRay(r, ray, tMax);
        rtcOccluded1(scene_, &context, &r);
        return r.tfar < 0;  // -inf when blocked
    }

private:
    static void setRay(RTCRay& r, const Ray& ray, float tMax) {
        r.org_x = ray.origin.x;
        r.org_y = ray.origin.y;
        r.org_z = ray.origin.z;
        r.dir_x = ray.direction.x;
        r.dir_y = ray.direction.y;
        r.dir_z = ray.direction.z;
        r.tnear = 0;
        r.tfar = tMax;
        r.time = 0;
        r.mask = ~0u;
        r.id = 0;
        r.flags = 0;
    }

    std::vector<float> vertices_;
    std::vector<std::uint32_t> indices_;
    RTCScene scene_ = nullptr;
    double buildSeconds_ = 0;
    std::size_t accelerationBytes_ = 0;
};

// The CPU time of the calling thread.
double threadCpuSeconds() {
    timespec now{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
    return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

struct PassTime {
    double wallSeconds;
    // The CPU time of the tracing threads divided by their number: the wall-clock time of the
    // pass had they had their cores to themselves. Rates are measured against it, so that other
    // work on the (shared) machine that takes turns on the cores does not count.
    double cpuSecondsPerThread;
};

// Runs traceOne(i) for every ray index on `threads` threads, which take chunks of rays as they
// go.
PassTime traceAll(std::size_t count, int threads,
                  const std::function<void(std::size_t)>& traceOne) {
    std::atomic<std::size_t> next{0};
    std::vector<double> cpuSeconds(static_cast<std::size_t>(threads));
    const auto work = [&](std::size_t thread) {
        const double start = threadCpuSeconds();
        for (;;) {
            const std::size_t begin = next.fetch_add(kChunkSize);
            if (begin >= count) break;
            const std::size_t end = std::min(begin + kChunkSize, count);
            for (std::size_t i = begin; i < end; ++i)
                traceOne(i);
        }
        cpuSeconds[thread] = threadCpuSeconds() - start;
    };
    const Clock::time_point start = Clock::now();
    std::vector<std::thread> helpers;
    for (std::size_t t = 1; t < cpuSeconds.size(); ++t)
        helpers.emplace_back(work, t);
    work(0);
    for (std::thread& helper : helpers)
        helper.join();
    double cpu = 0;
    for (const double c : cpuSeconds)
        cpu += c;
    return {secondsSince(start), cpu / threads};
}

enum class Tracer { kLancer, kEmbreeHigh, kEmbreeMedium };
constexpr int kTracerCount = 3;
constexpr const char* kTracerNames[kTracerCount] = {"lancer", "Embree high", "Embree medium"};

struct Structures {
    const Mesh& lancer;
    const EmbreeMesh& high;
    const EmbreeMesh& medium;

    const EmbreeMesh& embree(Tracer tracer) const {
        return tracer == Tracer::kEmbreeHigh ? high : medium;
    }
};

enum class RayKind { kPrimary, kBounce, kShadow };
constexpr const char* kRayKindNames[] = {"primary", "diffuse bounce", "shadow"};

// Traces the rays once with one tracer; result[i] is the hit's t (-1 on a miss) or, for shadow
// rays, 1 when blocked and 0 when not.
PassTime traceOnce(const Structures& s, Tracer tracer, RayKind kind, const Rays& rays, int threads,
                   std::vector<float>& result) {
    result.assign(rays.size(), 0);
    const float tMax = rays.tMax;
    if (tracer == Tracer::kLancer) {
        if (kind == RayKind::kShadow)
            return traceAll(rays.size(), threads, [&](std::size_t i) {
                result[i] = s.lancer.occluded(rays.rays[i], tMax) ? 1.0f : 0.0f;
            });
        return traceAll(rays.size(), threads, [&](std::size_t i) {
            const std::optional<Hit> hit = s.lancer.intersect(rays.rays[i], tMax);
            result[i] = hit ? hit->t : -1.0f;
        });
    }
    const EmbreeMesh& embree = s.embree(tracer);
    if (kind == RayKind::kShadow)
        return traceAll(rays.size(), threads, [&](std::size_t i) {
            result[i] = embree.occluded(rays.rays[i], tMax) ? 1.0f : 0.0f;
        });
    return traceAll(rays.size(), threads,
                    [&](std::size_t i) { result[i] = embree.intersect(rays.rays[i], tMax); });
}

// How far lancer's answers are from Embree's: rays on which they disagree about hitting, and
// for closest hits the rays both hit at t more than kTTolerance apart (relatively): a ray that
// slips through an edge in one of them and hits a surface behind.
struct Agreement {
    std::size_t hitDisagreements = 0;
    std::size_t tDisagreements = 0;
};
constexpr float kTTolerance = 1e-4f;

Agreement compare(const std::vector<float>& ours, const std::vector<float>& theirs) {
    Agreement a;
    for (std::size_t i = 0; i < ours.size(); ++i) {
        const bool ourHit = ours[i] > 0, theirHit = theirs[i] > 0;
        if (ourHit != theirHit) {
            ++a.hitDisagreements;
        } else if (ourHit) {
            const float difference = std::abs(ours[i] - theirs[i]) / std::max(ours[i], theirs[i]);
            a.tDisagreements += difference > kTTolerance;
        }
    }
    return a;
}

struct Throughput {
    RayKind kind;
    int threads;
    std::size_t rays;
    double hitFraction;  // lancer's
    double mraysPerSecond[kTracerCount];
    Agreement agreement;  // lancer against Embree high
};

// Each tracer traces the rays kTraceRounds times in turn (so that a burst of load elsewhere on
// the machine hits all of them alike), each time repeating for minTime / kTraceRounds; the best
// rate is kept.
Throughput measureThroughput(const Structures& s, RayKind kind, const Rays& rays, int threads,
                             double minTime) {
    Throughput out{kind, threads, rays.size(), 0, {0, 0, 0}, {}};
    std::vector<float> results[kTracerCount];
    for (int round = 0; round < kTraceRounds; ++round) {
        for (int t = 0; t < kTracerCount; ++t) {
            double elapsed = 0;
            do {
                const PassTime pass =
                    traceOnce(s, static_cast<Tracer>(t), kind, rays, threads, results[t]);
                elapsed += pass.wallSeconds;
                const double rate =
                    static_cast<double>(rays.size()) / pass.cpuSecondsPerThread * 1e-6;
                out.mraysPerSecond[t] = std::max(out.mraysPerSecond[t], rate);
            } while (elapsed < minTime / kTraceRounds);
        }
    }
    std::size_t hits = 0;
    for (const float r : results[0])
        hits += r > 0;
    out.hitFraction =
        static_cast<double>(hits) / static_cast<double>(std::max<std::size_t>(1, rays.size()));
    out.agreement = compare(results[0], results[static_cast<int>(Tracer::kEmbreeHigh)]);
    return out;
}

struct BuildFigures {
    double seconds[kTracerCount][2] = {};  // per tracer, at 1 and 2 threads (best of several)
    double bytesPerTriangle[kTracerCount] = {};
    double lancerTraversalBytesPerTriangle = 0;         // without normals, uvs and face materials
    double embreeAccelerationBytesPerTriangle[2] = {};  // high, medium: the BVH and leaves only
};

struct MeshReport {
    std::string name;
    std::size_t triangles;
    BuildFigures build;
    std::vector<Throughput> throughput;
};

MeshReport benchmarkMesh(const BenchMesh& bench, const EmbreeDevice& device,
                         const Options& options) {
    MeshReport report{bench.name, bench.triangles.triangleCount(), {}, {}};
    const auto triangles = static_cast<double>(report.triangles);
    std::fprintf(stderr, "%s: %zu triangles, building\n", bench.name.c_str(), report.triangles);
    std::unique_ptr<Mesh> lancer;
    std::unique_ptr<EmbreeMesh> high, medium;
    for (int threadIndex = 0; threadIndex < 2; ++threadIndex) {
        const tbb::global_control parallelism(tbb::global_control::max_allowed_parallelism,
                                              static_cast<std::size_t>(kThreadCounts[threadIndex]));
        auto& seconds = report.build.seconds;
        for (int repetition = 0; repetition < kBuildRepetitions; ++repetition) {
            const auto keepBest = [&](Tracer tracer, double s) {
                double& best = seconds[static_cast<int>(tracer)][threadIndex];
                best = repetition == 0 ? s : std::min(best, s);
            };
            lancer.reset();
            TriangleMesh copy = bench.triangles;  // Mesh takes its triangles: copied untimed
            const Clock::time_point start = Clock::now();
            lancer = std::make_unique<Mesh>(std::move(copy));
            keepBest(Tracer::kLancer, secondsSince(start));
            high.reset();
            high = std::make_unique<EmbreeMesh>(device, bench.triangles, RTC_BUILD_QUALITY_HIGH);
            keepBest(Tracer::kEmbreeHigh, high->buildSeconds());
            medium.reset();
            medium =
                std::make_unique<EmbreeMesh>(device, bench.triangles, RTC_BUILD_QUALITY_MEDIUM);
            keepBest(Tracer::kEmbreeMedium, medium->buildSeconds());
        }
    }
    const TriangleMesh& m = lancer->triangles();
    const std::size_t shadingBytes = m.normals.size() * sizeof(Vec3) + m.uvs.size() * sizeof(Vec2) +
                                     m.faceMaterials.size() * sizeof(std::uint32_t);
    report.build.bytesPerTriangle[0] = static_cast<double>(lancer->memoryBytes()) / triangles;
    report.build.lancerTraversalBytesPerTriangle =
        static_cast<double>(lancer->memoryBytes() - shadingBytes) / triangles;
    report.build.bytesPerTriangle[1] = static_cast<double>(high->memoryBytes()) / triangles;
    report.build.bytesPerTriangle[2] = static_cast<double>(medium->memoryBytes()) / triangles;
    report.build.embreeAccelerationBytesPerTriangle[0] =
        static_cast<double>(high->accelerationBytes()) / triangles;
    report.build.embreeAccelerationBytesPerTriangle[1] =
        static_cast<double>(medium->accelerationBytes()) / triangles;

    const RaySets rays = makeRays(bench, *lancer);
    const Structures structures{*lancer, *high, *medium};
    const Rays* sets[] = {&rays.primary, &rays.bounce, &rays.shadow};
    for (int kind = 0; kind < 3; ++kind) {
        for (const int threads : kThreadCounts) {
            std::fprintf(stderr, "%s: %s rays, %d thread(s)\n", bench.name.c_str(),
                         kRayKindNames[kind], threads);
            report.throughput.push_back(measureThroughput(structures, static_cast<RayKind>(kind),
                                                          *sets[kind], threads, options.minTime));
        }
    }
    return report;
}

void printReports(const std::vector<MeshReport>& reports) {
    std::printf("\n### Build time (best of %d) and memory\n\n", kBuildRepetitions);
    std::printf(
        "| mesh | triangles | lancer ms 1T / 2T | Embree high ms 1T / 2T | Embree medium ms 1T / "
        "2T | lancer / high (2T) | lancer / medium (2T) | lancer B/tri (Mesh; traversal) | "
        "Embree high B/tri (total; BVH) | Embree medium B/tri (total; BVH) |\n");
    std::printf("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    for (const MeshReport& r : reports) {
        const BuildFigures& b = r.build;
        std::printf(
            "| %s | %zu | %.1f / %.1f | %.1f / %.1f | %.1f / %.1f | %.2f | %.2f | %.1f; %.1f | "
            "%.1f; %.1f | %.1f; %.1f |\n",
            r.name.c_str(), r.triangles, 1e3 * b.seconds[0][0], 1e3 * b.seconds[0][1],
            1e3 * b.seconds[1][0], 1e3 * b.seconds[1][1], 1e3 * b.seconds[2][0],
            1e3 * b.seconds[2][1], b.seconds[0][1] / b.seconds[1][1],
            b.seconds[0][1] / b.seconds[2][1], b.bytesPerTriangle[0],
            b.lancerTraversalBytesPerTriangle, b.bytesPerTriangle[1],
            b.embreeAccelerationBytesPerTriangle[0], b.bytesPerTriangle[2],
            b.embreeAccelerationBytesPerTriangle[1]);
    }
    std::printf(
        "\n### Single-ray throughput, Mrays/s per thread count (rays / (CPU time / threads), best "
        "of the passes)\n\n");
    std::printf(
        "| mesh | rays | threads | count | hit %% | lancer | Embree high | Embree medium | "
        "lancer / high | lancer / medium | hit/miss differ | t differs |\n");
    std::printf("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
    for (const MeshReport& r : reports) {
        for (const Throughput& t : r.throughput) {
            std::printf(
                "| %s | %s | %d | %zu | %.1f | %.2f | %.2f | %.2f | %.2f | %.2f | %zu | %zu |\n",
                r.name.c_str(), kRayKindNames[static_cast<int>(t.kind)], t.threads, t.rays,
                100 * t.hitFraction, t.mraysPerSecond[0], t.mraysPerSecond[1], t.mraysPerSecond[2],
                t.mraysPerSecond[0] / t.mraysPerSecond[1],
                t.mraysPerSecond[0] / t.mraysPerSecond[2], t.agreement.hitDisagreements,
                t.agreement.tDisagreements);
        }
    }
    // Geometric means of the ratios over all meshes, per ray kind and thread count.
    std::printf("\n### Geometric mean of lancer / Embree over the meshes\n\n");
    std::printf("| rays | threads | lancer / high | lancer / medium |\n|---|---:|---:|---:|\n");
    for (int kind = 0; kind < 3; ++kind) {
        for (const int threads : kThreadCounts) {
            double logHigh = 0, logMedium = 0;
            int n = 0;
            for (const MeshReport& r : reports)
                for (const Throughput& t : r.throughput)
                    if (static_cast<int>(t.kind) == kind && t.threads == threads) {
                        logHigh += std::log(t.mraysPerSecond[0] / t.mraysPerSecond[1]);
                        logMedium += std::log(t.mraysPerSecond[0] / t.mraysPerSecond[2]);
                        ++n;
                    }
            if (n == 0) continue;
            std::printf("| %s | %d | %.2f | %.2f |\n", kRayKindNames[kind], threads,
                        std::exp(logHigh / n), std::exp(logMedium / n));
        }
    }
    double logBuild = 0;
    for (const MeshReport& r : reports)
        logBuild += std::log(r.build.seconds[0][1] / r.build.seconds[1][1]);
    if (!reports.empty())
        std::printf("\nBuild time lancer / Embree high (2 threads), geometric mean: %.2f\n",
                    std::exp(logBuild / static_cast<double>(reports.size())));
}

std::optional<Options> parseOptions(int argc, char** argv) {
    Options options;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        if (i + 1 >= argc) return std::nullopt;
        const std::string value = argv[++i];
        if (arg == "--assets")
            options.assets = value;
        else if (arg == "--only")
            options.only = value;
        else if (arg == "--min-time")
            options.minTime = std::stod(value);
        else if (arg == "--embree-config")
            options.embreeConfig = value;
        else
            return std::nullopt;
    }
    return options;
}

int run(int argc, char** argv) {
    const std::optional<Options> options = parseOptions(argc, argv);
    if (!options) {
        std::fprintf(stderr,
                     "usage: embree_comparison [--assets DIR] [--only NAME] [--min-time SECONDS] "
                     "[--embree-config STRING]\n");
        return 2;
    }
    const EmbreeDevice device(options->embreeConfig);
    std::vector<MeshReport> reports;
    for (const BenchMesh& mesh : loadMeshes(*options))
        reports.push_back(benchmarkMesh(mesh, device, *options));
    printReports(reports);
    return 0;
}

}  // namespace
}  // namespace lancer

int main(int argc, char** argv) {
    try {
        return lancer::run(argc, argv);
    } catch (const std::exception& error) {
        std::fprintf(stderr, "embree_comparison: %s\n", error.what());
    }
    return 1;
}
