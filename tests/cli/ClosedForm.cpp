#include "ClosedForm.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace lancer::test {

Radiance Radiance::fromJson(const nlohmann::json& value) {
    if (value.is_number()) {
        const double grey = value.get<double>();
        return {grey, grey, grey};
    }
    return {value.at(0).get<double>(), value.at(1).get<double>(), value.at(2).get<double>()};
}

Vec3d vec3FromJson(const nlohmann::json& xyz) {
    return {xyz.at(0).get<double>(), xyz.at(1).get<double>(), xyz.at(2).get<double>()};
}

Incident incidentLight(const nlohmann::json& light, const Vec3d& p) {
    if (light.at("type") == "directional")
        return {Radiance::fromJson(light.at("irradiance")),
                -normalize(vec3FromJson(light.at("direction")))};
    const Vec3d toLight = vec3FromJson(light.at("position")) - p;
    const Radiance intensity = Radiance::fromJson(light.at("intensity"));
    const bool falloff = light.value("falloff", "inverse_square") != "none";
    return {falloff ? (1 / lengthSquared(toLight)) * intensity : intensity, normalize(toLight)};
}

double polygonIrradiance(const Vec3d& p, const Vec3d& n, const std::vector<Vec3d>& vertices) {
    Vec3d sum;
    for (std::size_t i = 0; i < vertices.size(); ++i) {
        const Vec3d a = normalize(vertices[i] - p);
        const Vec3d b = normalize(vertices[(i + 1) % vertices.size()] - p);
        const double theta = std::acos(std::clamp(dot(a, b), -1.0, 1.0));
        sum += theta * normalize(cross(a, b));
    }
    return std::abs(dot(n, sum)) / 2;
}

RayD CameraModel::rayThroughPixelCentre(int i, int j) const {
    const Vec3d w = normalize(position - lookAt);
    const Vec3d u = normalize(cross(up, w));
    const Vec3d v = cross(w, u);
    const double tanH = std::tan(vfovDegrees * std::numbers::pi / 360);
    const double tanW = tanH * width / height;
    const double px = i + 0.5, py = j + 0.5;
    const Vec3d direction =
        normalize((2 * px / width - 1) * tanW * u + (1 - 2 * py / height) * tanH * v - w);
    return {position, direction};
}

void CameraModel::placeIn(nlohmann::json& scene) const {
    const auto array = [](const Vec3d& p) { return nlohmann::json::array({p.x, p.y, p.z}); };
    scene["camera"] = {{"position", array(position)},
                       {"look_at", array(lookAt)},
                       {"up", array(up)},
                       {"vfov", vfovDegrees}};
    scene["render"]["width"] = width;
    scene["render"]["height"] = height;
    scene["render"]["spp"] = 1;
}

std::optional<double> intersectPlane(const RayD& ray, const Vec3d& point, const Vec3d& normal) {
    const double denominator = dot(normal, ray.direction);
    if (denominator == 0) return std::nullopt;
    const double t = dot(normal, point - ray.origin) / denominator;
    if (t <= 0) return std::nullopt;
    return t;
}

std::optional<double> intersectSphere(const RayD& ray, const Vec3d& center, double radius) {
    const Vec3d o = ray.origin - center;
    const double halfB = dot(o, ray.direction);
    const double c = dot(o, o) - radius * radius;
    const double discriminant = halfB * halfB - c;
    if (discriminant < 0) return std::nullopt;
    const double root = std::sqrt(discriminant);
    if (-halfB - root > 0) return -halfB - root;
    if (-halfB + root > 0) return -halfB + root;
    return std::nullopt;
}

double distanceToSegment(const Vec3d& point, const Vec3d& a, const Vec3d& b) {
    const Vec3d ab = b - a;
    const double t = std::clamp(dot(point - a, ab) / dot(ab, ab), 0.0, 1.0);
    return length(point - (a + t * ab));
}

double distanceToLine(const Vec3d& point, const RayD& ray) {
    const Vec3d toPoint = point - ray.origin;
    return length(toPoint - dot(toPoint, ray.direction) * ray.direction);
}

double boxIrradiance(const Vec3d& p, const Vec3d& n, const Vec3d& lo, const Vec3d& hi) {
    double E = 0;
    for (int axis = 0; axis < 3; ++axis)
        for (const bool atMax : {false, true}) {
            const double plane = atMax ? hi[axis] : lo[axis];
            if (atMax ? p[axis] <= plane : p[axis] >= plane) continue;  // behind the face
            const int a = (axis + 1) % 3, b = (axis + 2) % 3;
            std::vector<Vec3d> corners;
            for (const auto& [ua, ub] : {std::pair{0, 0}, {1, 0}, {1, 1}, {0, 1}}) {
                Vec3d c;
                c[axis] = plane;
                c[a] = ua ? hi[a] : lo[a];
                c[b] = ub ? hi[b] : lo[b];
                corners.push_back(c);
            }
            E += polygonIrradiance(p, n, corners);
        }
    return E;
}

nlohmann::json emitterOverFloor(const nlohmann::json& floor, const nlohmann::json& lamp,
                                const CameraModel& camera, const std::string& integrator, int spp) {
    nlohmann::json scene = nlohmann::json::parse(R"({
      "background": 0, "ambient": 0,
      "materials": { "floor": { "diffuse": 0.5 }, "lamp": { "diffuse": 0, "emission": 2 } }
    })");
    scene["objects"] = {floor, lamp};
    scene["objects"][0]["material"] = "floor";
    scene["objects"][1]["material"] = "lamp";
    camera.placeIn(scene);
    scene["render"]["integrator"] = integrator;
    scene["render"]["spp"] = spp;
    scene["render"]["max_depth"] = 1;
    return scene;
}

PixelOracle lambertianFloor(double kd, std::function<double(const Vec3d& p)> irradiance) {
    return [kd, irradiance = std::move(irradiance)](const RayD& ray) -> std::optional<Radiance> {
        const Vec3d p = ray.at(intersectPlane(ray, Vec3d(0, 0, 0), Vec3d(0, 1, 0)).value());
        const double L = kd * irradiance(p) / 3.14159265358979323846;
        return Radiance{L, L, L};
    };
}

int expectPixelsMatch(const Image& image, const CameraModel& camera, const PixelOracle& expected,
                      double relative, double absolute) {
    EXPECT_EQ(image.encoding, Image::Encoding::LinearFloat);
    EXPECT_EQ(image.width, camera.width);
    EXPECT_EQ(image.height, camera.height);
    if (image.width != camera.width || image.height != camera.height) return 0;

    constexpr int kMismatchesReported = 5;
    int checked = 0, mismatches = 0;
    for (int j = 0; j < image.height; ++j)
        for (int i = 0; i < image.width; ++i) {
            const std::optional<Radiance> want = expected(camera.rayThroughPixelCentre(i, j));
            if (!want) continue;
            ++checked;
            const Image::Rgb& got = image.at(i, j);
            const double wanted[3] = {want->r, want->g, want->b};
            bool close = true;
            for (std::size_t c = 0; c < 3; ++c)
                close = close &&
                        std::abs(got[c] - wanted[c]) <= absolute + relative * std::abs(wanted[c]);
            if (!close && ++mismatches <= kMismatchesReported)
                ADD_FAILURE() << "pixel (" << i << ", " << j << "): rendered (" << got[0] << ", "
                              << got[1] << ", " << got[2] << "), expected (" << wanted[0] << ", "
                              << wanted[1] << ", " << wanted[2] << ")";
        }
    EXPECT_EQ(mismatches, 0) << "of " << checked << " pixels checked";
    return checked;
}

}  // namespace lancer::test
