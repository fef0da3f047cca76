// Reuse in scene files (docs/SCENE-FORMAT.md, "Includes and groups"): a scene made of included
// files renders as the same scene written in one file, and a group placed several times as its
// objects written out at each place.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "LancerRun.h"

namespace lancer::test {
namespace {

using json = nlohmann::json;

const std::vector<std::string> kSmall{"--width", "48", "--height", "36", "--spp", "4"};

json parse(const std::string& text) {
    return json::parse(text);
}

// The scene in `files` (name and text; the first is the scene file) rendered where they are.
Image renderFiles(const std::vector<std::pair<std::string, json>>& files,
                  const std::vector<std::string>& options = kSmall) {
    const TempFolder folder;
    for (const auto& [name, text] : files)
        folder.write(name, text.dump(2));
    return renderSceneFile(folder / files.front().first, options).image;
}

// A room of boxes lit by a quad light, with what `scene` adds.
json room(json scene) {
    scene["camera"] = {{"position", {0, 1, 5}}, {"look_at", {0, 0.8, 0}}};
    scene["objects"].push_back(
        parse(R"({ "type": "box", "min": [-3, -1, -3], "max": [3, 0, 3] })"));
    scene["objects"].push_back(
        parse(R"({ "type": "box", "min": [-3, 0, -3], "max": [3, 4, -2.5] })"));
    scene["lights"].push_back(parse(
        R"({ "type": "quad", "corner": [-1, 3, -1], "edge1": [2, 0, 0], "edge2": [0, 0, 2], "radiance": 4 })"));
    return scene;
}

TEST(CliInclude, IncludedMaterialsObjectsAndLightsRenderTheSameBytesAsOneFile) {
    // scene.json includes lib/things.json, which includes materials.json beside it.
    const json materials = parse(R"({ "materials": {
      "red": { "diffuse": [0.8, 0.1, 0.1], "specular": 0.3, "shininess": 40 },
      "lamp": { "diffuse": 0, "emission": 6 } } })");
    const json things = parse(R"({ "include": ["materials.json"],
      "objects": [ { "type": "sphere", "center": [-0.8, 0.5, 0], "radius": 0.5, "material": "red" },
                   { "type": "sphere", "center": [1, 1.8, -1], "radius": 0.2, "material": "lamp" } ],
      "lights": [ { "type": "point", "position": [2, 4, 3], "intensity": 20 } ] })");
    json included = room(parse(R"({ "include": ["lib/things.json"],
      "materials": { "blue": { "diffuse": [0.1, 0.2, 0.8] } },
      "objects": [ { "type": "box", "min": [0.3, 0, -0.4], "max": [1.1, 0.8, 0.4],
                     "material": "blue" } ] })"));
    // The same in one file: the included files' contents first, the deepest first.
    json whole = included;
    whole.erase("include");
    whole["materials"].update(materials["materials"]);
    whole["objects"] = things["objects"];
    for (const json& object : included["objects"])
        whole["objects"].push_back(object);
    whole["lights"] = things["lights"];
    for (const json& light : included["lights"])
        whole["lights"].push_back(light);

    for (const char* integrator : {"whitted", "path"}) {
        SCOPED_TRACE(integrator);
        std::vector<std::string> options = kSmall;
        options.insert(options.end(), {"--integrator", integrator});
        const Image one = renderScene(whole, options).image;
        const Image parts = renderFiles({{"scene.json", included},
                                         {"lib/things.json", things},
                                         {"lib/materials.json", materials}},
                                        options);
        EXPECT_EQ(parts.pixels, one.pixels);
    }
}

// What the group tests compare: lancer's linear renders, within rounding of the transforms
// (an instance of an instance against one instance by the product: 4e-7 when written).
constexpr double kRounding = 1e-5;

const std::string kModel = LANCER_SOURCE_DIR "/scenes/models/stanford_bunny_lowres/bunny.obj";

// Objects of every kind, about the origin: a sphere, an emissive box (a light in "path"), a csg
// and a mesh.
json groupObjects() {
    json objects = parse(R"([
      { "type": "sphere", "center": [-0.4, 0.3, 0], "radius": 0.3, "material": "red" },
      { "type": "box", "min": [0.1, 0.9, -0.1], "max": [0.3, 1.1, 0.1], "material": "lamp" },
      { "type": "csg", "operation": "difference", "objects": [
          { "type": "box", "min": [0, 0, -0.3], "max": [0.6, 0.6, 0.3] },
          { "type": "sphere", "center": [0.3, 0.6, 0], "radius": 0.3 } ] },
      { "type": "mesh", "file": "", "material": "red",
        "transform": { "scale": 0.5, "translate": [0, 0.3, 0.6] } }
    ])");
    objects[3]["file"] = kModel;
    return objects;
}

json groupScene() {
    return room(parse(R"({ "render": { "integrator": "path" },
      "materials": { "red": { "diffuse": [0.8, 0.1, 0.1] },
                     "lamp": { "diffuse": 0, "emission": 8 } },
      "objects": [], "lights": [] })"));
}

// `object` placed by `transform` (composed after a transform of its own).
json placedAt(json object, const json& transform) {
    if (!object.contains("transform")) {
        object["transform"] = transform;
        return object;
    }
    // Only translations and scales are composed here: the object's scale, then its translation
    // and the placement's.
    const json& own = object["transform"];
    json composed = own;
    std::vector<double> translate{0, 0, 0};
    for (std::size_t i = 0; i < 3; ++i)
        translate[i] = own["translate"][i].get<double>() + transform["translate"][i].get<double>();
    composed["translate"] = translate;
    object["transform"] = composed;
    return object;
}

TEST(CliGroup, PlacedTwiceRendersAsItsObjectsWrittenOutAtEachPlace) {
    const json left = {{"translate", {-1.2, 0, 0}}};
    const json right = {{"translate", {0.9, 0, -0.5}}};
    json grouped = groupScene();
    grouped["groups"]["things"] = groupObjects();
    grouped["objects"].push_back({{"type", "group"}, {"group", "things"}, {"transform", left}});
    grouped["objects"].push_back({{"type", "group"}, {"group", "things"}, {"transform", right}});
    json written = groupScene();
    for (const json& transform : {left, right})
        for (const json& object : groupObjects())
            written["objects"].push_back(placedAt(object, transform));

    const Image expected = renderScene(written, kSmall).image;
    const Image image = renderScene(grouped, kSmall).image;
    EXPECT_LE(maxAbsoluteDifference(image, expected), kRounding);
    // The group shows: the room alone is another picture.
    EXPECT_GT(maxAbsoluteDifference(renderScene(groupScene(), kSmall).image, expected), 0.1);
}

TEST(CliGroup, PlacesGroupsThatPlaceGroups) {
    // A pair of things, placed twice: four of each object.
    json nested = groupScene();
    nested["groups"]["things"] = groupObjects();
    nested["groups"]["pair"] = parse(R"([
      { "type": "group", "group": "things", "transform": { "translate": [-0.7, 0, 0] } },
      { "type": "group", "group": "things", "transform": { "translate": [0.7, 0, 0] } } ])");
    nested["objects"].push_back(parse(
        R"({ "type": "group", "group": "pair", "transform": { "translate": [0, 0, 0.5] } })"));
    nested["objects"].push_back(parse(
        R"({ "type": "group", "group": "pair", "transform": { "translate": [0, 0, -1.5] } })"));
    json written = groupScene();
    for (const double z : {0.5, -1.5})
        for (const double x : {-0.7, 0.7})
            for (const json& object : groupObjects())
                written["objects"].push_back(placedAt(object, {{"translate", {x, 0, z}}}));

    EXPECT_LE(maxAbsoluteDifference(renderScene(nested, kSmall).image,
                                    renderScene(written, kSmall).image),
              kRounding);
}

TEST(CliGroup, ObjectsWithoutAMaterialKeepTheDefaultInACsg) {
    // A csg's material is that of its children without one, but not of a group's objects: they
    // are the same wherever the group is placed.
    json grouped = groupScene();
    grouped["groups"]["ball"] =
        parse(R"([ { "type": "sphere", "center": [0.6, 0.6, 0], "radius": 0.5 } ])");
    grouped["objects"].push_back(parse(R"({ "type": "csg", "operation": "union", "material": "red",
      "objects": [ { "type": "box", "min": [-0.6, 0, -0.4], "max": [0.4, 0.8, 0.4] },
                   { "type": "group", "group": "ball" } ] })"));
    // Written out, the sphere names a material of the default's values.
    json written = groupScene();
    written["materials"]["plain"] = json::object();
    written["objects"].push_back(parse(R"({ "type": "csg", "operation": "union", "material": "red",
      "objects": [ { "type": "box", "min": [-0.6, 0, -0.4], "max": [0.4, 0.8, 0.4] },
                   { "type": "sphere", "center": [0.6, 0.6, 0], "radius": 0.5,
                     "material": "plain", "transform": { "translate": [0, 0, 0] } } ] })"));
    EXPECT_LE(maxAbsoluteDifference(renderScene(grouped, kSmall).image,
                                    renderScene(written, kSmall).image),
              kRounding);
}

}  // namespace
}  // namespace lancer::test
