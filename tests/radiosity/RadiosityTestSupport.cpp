#include "RadiosityTestSupport.h"

#include <array>
#include <sstream>

#include "io/SceneLoader.h"
#include "radiosity/FormFactor.h"
#include "sampling/Sampling.h"

namespace lancer::test {

Scene loadScene(const std::string& objects, const std::string& extra) {
    const std::string text = R"({
      "camera": {"position": [0.5, 0.5, 0.5], "look_at": [0.5, 0.5, -1]},
      "materials": {"white": {"diffuse": 0.5}, "black": {"diffuse": 0},
                    "glow": {"diffuse": 0.6, "emission": 0.25},
                    "lamp": {"diffuse": 0, "emission": 0.25},
                    "blinding": {"diffuse": 0.6, "emission": 3e38}},
      "objects": [)" + objects +
                             "]" + extra + "}";
    std::vector<std::string> warnings;
    return SceneLoader::loadString(text, "test.json", warnings);
}

std::string square(const Vec3& corner, const Vec3& u, const Vec3& v, const std::string& material) {
    const auto point = [](const Vec3& p) {
        std::ostringstream out;
        out << "[" << p.x << ", " << p.y << ", " << p.z << "]";
        return out.str();
    };
    const auto triangle = [&](const Vec3& a, const Vec3& b, const Vec3& c) {
        return R"({"type": "triangle", "material": ")" + material + R"(", "vertices": [)" +
               point(a) + ", " + point(b) + ", " + point(c) + "]}";
    };
    return triangle(corner, corner + u, corner + u + v) + ", " +
           triangle(corner, corner + u + v, corner + v);
}

std::string tiledSquare(const Vec3& corner, const Vec3& u, const Vec3& v, int tiles,
                        const std::string& material) {
    const float step = 1.0f / static_cast<float>(tiles);
    std::string text;
    for (int i = 0; i < tiles; ++i)
        for (int j = 0; j < tiles; ++j)
            text +=
                (text.empty() ? "" : ", ") + square(corner + (step * static_cast<float>(i)) * u +
                                                        (step * static_cast<float>(j)) * v,
                                                    step * u, step * v, material);
    return text;
}

std::string closedBox(const std::string& material, int tiles) {
    // floor, ceiling, back, front, left, right: corner, u, v
    const std::array<std::array<Vec3, 3>, 6> walls{{
        {Vec3(0, 0, 0), Vec3(0, 0, 1), Vec3(1, 0, 0)},
        {Vec3(0, 1, 0), Vec3(1, 0, 0), Vec3(0, 0, 1)},
        {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)},
        {Vec3(0, 0, 1), Vec3(0, 1, 0), Vec3(1, 0, 0)},
        {Vec3(0, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)},
        {Vec3(1, 0, 0), Vec3(0, 0, 1), Vec3(0, 1, 0)},
    }};
    std::string box;
    for (const auto& [corner, u, v] : walls)
        box += (box.empty() ? "" : ", ") + tiledSquare(corner, u, v, tiles, material);
    return box;
}

std::vector<std::uint32_t> patchesFacing(const RadiosityMesh& mesh, const Vec3& normal) {
    std::vector<std::uint32_t> result;
    for (std::uint32_t i = 0; i < mesh.patches.size(); ++i)
        if (dot(mesh.patches[i].normal, normal) > 0.999f) result.push_back(i);
    return result;
}

double areaFormFactor(const Scene& scene, const RadiosityMesh& mesh,
                      const std::vector<std::uint32_t>& receivers,
                      const std::vector<std::uint32_t>& shooters, int visibilityRays) {
    const FormFactor formFactor(scene);
    double weighted = 0, area = 0;
    std::uint64_t rays = 0;
    for (std::uint32_t r : receivers) {
        const Patch& patch = mesh.patches[r];
        for (std::uint32_t e = patch.firstElement; e < patch.firstElement + patch.elementCount;
             ++e) {
            const Element& element = mesh.elements[e];
            double F = 0;
            for (std::uint32_t s : shooters)
                F += formFactor
                         .elementToTriangle(element, Side::Front, mesh.patches[s].corners,
                                            mesh.patches[s], Side::Front, visibilityRays,
                                            hashValues(e, s), rays)
                         .average();
            weighted += element.area * F;
            area += element.area;
        }
    }
    return weighted / area;
}

}  // namespace lancer::test
