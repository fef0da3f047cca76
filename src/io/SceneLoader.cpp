#include "io/SceneLoader.h"

#include <chrono>
#include <cmath>
#include <fstream>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include "accel/Mesh.h"
#include "geometry/Box.h"
#include "geometry/Cone.h"
#include "geometry/Csg.h"
#include "geometry/Cylinder.h"
#include "geometry/Disk.h"
#include "geometry/Instance.h"
#include "geometry/Plane.h"
#include "geometry/Quad.h"
#include "geometry/SmoothingByAngle.h"
#include "geometry/Sphere.h"
#include "geometry/Torus.h"
#include "geometry/Triangle.h"
#include "integrators/IntegratorRegistry.h"
#include "io/GltfLoader.h"
#include "io/ImageReader.h"
#include "io/InputFile.h"
#include "io/JsonDocument.h"
#include "io/Keyframes.h"
#include "io/ModelCache.h"
#include "io/ObjLoader.h"
#include "io/PlyLoader.h"
#include "lights/AreaLight.h"
#include "lights/DirectionalLight.h"
#include "lights/EnvironmentLight.h"
#include "lights/PointLight.h"
#include "lights/SpotLight.h"
#include "materials/BlinnPhongMaterial.h"
#include "materials/BumpMap.h"
#include "materials/CheckerTexture.h"
#include "materials/ConstantTexture.h"
#include "materials/ImageTexture.h"
#include "materials/MaterialParameters.h"
#include "materials/NormalMap.h"
#include "math/Transform.h"
#include "radiosity/RadiosityMethodRegistry.h"
#include "render/Filter.h"
#include "render/ToneMapper.h"
#include "scene/FisheyeCamera.h"
#include "scene/LatLongCamera.h"
#include "scene/OrthographicCamera.h"
#include "scene/PerspectiveCamera.h"
#include "util/DidYouMean.h"
#include "util/Parameters.h"
#include "util/Registry.h"

namespace lancer {

namespace {

std::string inQuotes(const std::string& s) {
    return "\"" + s + "\"";
}

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// What a JSON value is, in words, for "expected ..., got ..." messages.
std::string describe(const nlohmann::json& v) {
    if (v.is_null()) return "null";
    if (v.is_boolean()) return v.get<bool>() ? "true" : "false";
    if (v.is_number()) return "a number";
    if (v.is_string()) return "the string " + inQuotes(v.get<std::string>());
    if (v.is_array()) return "an array of " + std::to_string(v.size());
    return "an object";
}

// The keys every object of a kind takes, then those of its type.
std::vector<std::string> withKeys(std::vector<std::string> common,
                                  const std::vector<std::string>& own) {
    common.insert(common.end(), own.begin(), own.end());
    return common;
}

// How many shadow rays the Whitted integrator traces towards an area light or the environment per
// shading point, unless the light's "samples" says.
constexpr int kDefaultShadowSamples = 16;

}  // namespace

class SceneLoader::Reader {
    using json = nlohmann::json;

    // A value of a document (the scene file or a file it includes), where it is (a JSON
    // pointer) and what to call it in messages.
    struct Node {
        const json& value;
        std::string pointer;
        std::string name;
        const JsonDocument* document;
        // Where members of an object put together by the loader (the camera of an animation's
        // frame) were written, by key, when not at `pointer`'s own members.
        const std::map<std::string, std::string>* memberPointers = nullptr;

        Node operator[](const std::string& key) const;  // an object's member
        Node at(std::size_t index) const;               // an array's element
        bool has(const std::string& key) const { return value.contains(key); }
    };

public:
    // `frame`: the frame of the scene's animation to load, from 1 (any frame, without one).
    Reader(const JsonDocument& doc, std::vector<std::string>& warnings, int frame,
           const ModelCache* modelCache);
    Scene load();

private:
    friend class SceneLoader;  // its vocabulary() lists the tables

    // The files `fragment` includes, each after those it includes itself, appended to
    // `fragments` (a file already read is not read again).
    void readIncludes(const Node& fragment, std::vector<Node>& fragments);
    // What a scene file or an included one defines by name: its materials and groups.
    void loadDefinitions(const Node& fragment);
    // What it places: its objects and lights.
    void loadContents(const Node& fragment);
    void loadRender(const Node& node);
    void loadFilter(const Node& node);
    void loadAdaptive(const Node& render, const Node& node);
    void loadRadiosity(const Node& node);
    // The "animation" block: its settings and keyframes (each keyframed transform is checked).
    void loadAnimation(const Node& node);
    // The camera at the frame loaded: `node` with its keyframed keys at that frame.
    void loadCamera(const Node& node);
    // The camera for `entry`'s keys.
    void loadCameraOfType(const Node& node);
    void loadMaterials(const Node& node);
    void loadGroups(const Node& node);
    // Names defined twice (in one file or two) are an error naming both places.
    void checkFirstDefinition(const std::map<std::string, std::string>& placesOfNames,
                              const std::string& name, const Node& definition,
                              const std::string& what) const;
    std::unique_ptr<Material> loadMaterial(const Node& node);
    // A warning for each reflectance written as 0-255 (a beginner's trap).
    void warnOfByteColours(const Node& material) const;
    // The normal or bump map of a material's object (normal_map, bump_map, bump_scale), or null.
    std::shared_ptr<const ShadingNormalMap> loadShadingNormalMap(const Node& material);
    // A colour, or a texture object; an image texture of `content` (Data: a map of numbers, read
    // linear, as roughness is).
    std::shared_ptr<const Texture> loadTexture(
        const Node& node, ImageReader::Content content = ImageReader::Content::Color);
    // The shapes an object makes: one, or none (left out with a warning), or a group's.
    using Shapes = std::vector<std::unique_ptr<Shape>>;
    // A type of the "objects" or "lights" array, and the member reading its keys.
    struct ObjectType {
        const char* name;
        const char* what;  // "a sphere": the object, in messages
        Shapes (Reader::*load)(const Node& node, const char* what,
                               const std::optional<Transform>& transform);
    };
    // An object's keys, read for the class it makes.
    class ObjectParameters;
    struct LightType {
        const char* name;
        const char* what;  // "a point light": the light, in messages
        void (Reader::*load)(const Node& node, const char* what);
    };
    // A material type, chosen by the material's "type" key (by default "blinn_phong").
    struct MaterialType {
        const char* name;
        std::vector<std::string> (*keys)();
        std::unique_ptr<Material> (*create)(const MaterialParameters& parameters);
    };
    // A camera type, chosen by the camera's "type" key (by default "perspective").
    struct CameraType {
        const char* name;
        std::vector<std::string> (*keys)();
        std::unique_ptr<Camera> (*create)(const Parameters& parameters, const CameraFrame& frame);
    };
    // A texture, named by the one key of its object ({"checker": {...}}).
    struct TextureType {
        const char* name;
        std::shared_ptr<const Texture> (Reader::*load)(const Node& value,
                                                       ImageReader::Content content);
    };
    static const Registry<ObjectType>& objectTypes();
    static const Registry<MaterialType>& materialTypes();
    static const Registry<TextureType>& textureTypes();
    static const Registry<LightType>& lightTypes();
    static const Registry<CameraType>& cameraTypes();

    void loadObject(const Node& node);
    // The shapes an element of "objects" (or of a csg's, or of a group's) makes, placed by its
    // transform.
    Shapes readObject(const Node& node);
    // A shape that reads its own keys: ShapeType::keys() and ShapeType::create(parameters,
    // material).
    template <typename ShapeType>
    Shapes loadShape(const Node& node, const char* what, const std::optional<Transform>& transform);
    Shapes loadTriangle(const Node& node, const char* what,
                        const std::optional<Transform>& transform);
    Shapes loadMeshObject(const Node& node, const char* what,
                          const std::optional<Transform>& transform);
    Shapes loadGltfObject(const Node& node, const char* what,
                          const std::optional<Transform>& transform);
    // An instance of the model that the object's "file" names, made by `make` (read, smoothed
    // by the angle it is given, and built; "model" names it in messages), with the object's
    // material if it has one, else the model's own.
    using MeshMaker = std::function<std::shared_ptr<const Mesh>(const std::filesystem::path&,
                                                                const std::optional<float>&)>;
    Shapes loadModelObject(const Node& node, const char* what,
                           const std::optional<Transform>& transform, const std::string& model,
                           const MeshMaker& make);
    // The mesh of a model's triangles, smoothed by `smooth` degrees if given.
    std::shared_ptr<const Mesh> builtMesh(std::shared_ptr<TriangleMesh> triangles,
                                          const std::optional<float>& smooth);
    Shapes loadCsg(const Node& node, const char* what, const std::optional<Transform>& transform);
    // An instance of each shape of the group the object names, placed by its transform.
    Shapes loadGroupObject(const Node& node, const char* what,
                           const std::optional<Transform>& transform);
    // A named group of objects, read once.
    struct Group {
        Node objects;
        std::optional<std::vector<std::shared_ptr<const Shape>>> shapes;  // once read
        std::size_t instancedTriangles = 0;  // what each placement draws
    };
    // The group the string at `name` names, read if not yet (a group placed by a group read
    // before it); a group placing itself, directly or through others, is an error.
    const Group& groupNamed(const Node& name);
    void readGroup(const std::string& name, Group& group);
    static std::unique_ptr<Shape> placed(std::unique_ptr<Shape> shape,
                                         const std::optional<Transform>& transform);
    static Shapes only(std::unique_ptr<Shape> shape);
    // `smooth`: the threshold angle of SmoothingByAngle, if the object asks for it.
    std::shared_ptr<const Mesh> loadMesh(const Node& file, const std::string& model,
                                         const MeshMaker& make, const std::optional<float>& smooth);
    // Image files are read once, however many materials (and models) use them.
    std::shared_ptr<const Texture> loadImageTexture(
        const std::filesystem::path& path,
        ImageReader::Content content = ImageReader::Content::Color);
    // The image file that the string at `file` names; `what` names it in messages ("texture").
    std::shared_ptr<const Texture> loadImageFile(const Node& file, const std::string& what,
                                                 ImageReader::Content content);
    std::shared_ptr<const Texture> loadImageTextureFile(const Node& file,
                                                        ImageReader::Content content);
    std::shared_ptr<const Texture> loadCheckerTexture(const Node& checker, ImageReader::Content);
    Transform readTransform(const Node& node) const;
    // An object's transform, if it has one: its own, or its keyframes' at the frame loaded when
    // its "name" is animated.
    std::optional<Transform> readPlacement(const Node& node);
    // Every object the animation names must exist.
    void checkAnimatedNames() const;
    void loadLight(const Node& node);
    // A light that reads its own keys: LightType::keys() and LightType::create(parameters).
    template <typename LightType>
    void loadLight(const Node& node, const char* what);
    // The top-level "environment" (the root is where a "background" beside it is reported).
    void loadEnvironment(const Node& root);
    // A light's "samples": the Whitted integrator's shadow rays towards it per shading point.
    int readShadowSamples(const Node& node) const;
    void loadQuadLight(const Node& node, const char* what);
    // A warning for each quad light with every other bounded surface behind it (a beginner's
    // trap: its edges in the wrong order), once every shape is in the scene. Conservative: a
    // shape counts as lit if its bounding box reaches in front, and infinite planes count as lit.
    void warnOfLightsFacingAway() const;
    void loadSphereLight(const Node& node, const char* what);
    // A material that emits `radiance` and reflects nothing: the visible surface of an area light.
    const Material* emitterOf(const Color& radiance);
    // Adds an area light and its visible surface, linked to each other.
    void addAreaLight(const Node& node, std::unique_ptr<Shape> surface,
                      std::unique_ptr<Light> light);
    const Material* materialOf(const Node& object);

    // The entry of `table` that the string at `name` names; an unknown name is an error that
    // lists the valid ones ("unknown light type \"area\"; expected ...").
    template <typename Entry>
    const Entry& lookUp(const Registry<Entry>& table, const Node& name,
                        const std::string& what) const;
    // The folder that relative paths in the node's file start from.
    static std::filesystem::path folderOf(const Node& node);
    // "file:line:col" of an object member's key.
    static std::string placeOfKey(const Node& node);
    [[noreturn]] void fail(const Node& node, const std::string& message) const;
    // The error of a name that `defined` (the scene's `section`) does not hold: the names it
    // holds, and the nearest.
    template <typename Definitions>
    [[noreturn]] void failUndefined(const Node& node, const std::string& what,
                                    const std::string& name, const Definitions& defined,
                                    const char* section) const {
        std::vector<std::string> names;
        for (const auto& entry : defined)
            names.push_back(entry.first);
        fail(node,
             what + " " + inQuotes(name) + " is not defined" + didYouMean(name, names) +
                 (names.empty() ? std::string("; the scene's \"") + section + "\" defines none"
                                : "; expected " + quotedNames(names)));
    }
    [[noreturn]] void failAtKey(const Node& node, const std::string& message) const;
    void warn(const Node& node, const std::string& message) const;
    void checkKeys(const Node& object, const std::string& what,
                   const std::vector<std::string>& allowed) const;
    void requireObject(const Node& node, const std::string& what) const;
    void requireArray(const Node& node, const std::string& what) const;
    Node require(const Node& object, const std::string& key, const std::string& what) const;

    bool readFlag(const Node& node) const;
    float readNumber(const Node& node) const;
    float readNumberAtLeast(const Node& node, float minimum, bool inclusive) const;
    int readInt(const Node& node, int minimum, int maximum = 1'000'000'000) const;
    std::string readString(const Node& node) const;
    Vec3 readVec3(const Node& node) const;
    Vec3 readDirection(const Node& node) const;
    Vec2 readVec2(const Node& node) const;
    Color readColor(const Node& node) const;

    const JsonDocument& doc_;  // the scene file
    // The files it includes, and those they include (Nodes point into them).
    std::vector<std::unique_ptr<const JsonDocument>> included_;
    // Each file read, by its canonical path; those on the way from the scene file to the one
    // being read are in includeChain_ (shown as named), where finding one again is a cycle.
    std::set<std::string> filesRead_;
    std::vector<std::pair<std::string, std::string>> includeChain_;
    std::vector<std::string>& warnings_;
    Scene scene_;
    std::map<std::string, const Material*> materials_;
    std::map<std::string, std::string> materialPlaces_;  // where each was defined
    std::map<std::string, Group> groups_;
    std::map<std::string, std::string> groupPlaces_;
    std::vector<std::string> groupsBeingRead_;  // the groups placing the one being read
    // The quad lights, for warnOfLightsFacingAway: the light, its surface, a point of its plane
    // and the normal of its lit side.
    struct OneSidedLight {
        Node node;
        const Shape* surface;
        Vec3 point;
        Vec3 normal;
    };
    std::vector<OneSidedLight> oneSidedLights_;
    const Material* defaultMaterial_ = nullptr;
    // Each model and texture file is loaded once, however many objects use it.
    std::map<std::string, std::shared_ptr<const Mesh>> meshes_;
    std::map<std::string, std::shared_ptr<const Texture>> textures_;
    // The animation: the frame loaded, the keyframes of the camera's keys and of the named
    // objects' transforms, and where each object name was given (file:line:column).
    int frame_;
    const ModelCache* modelCache_;
    Keyframes::Interpolation interpolation_ = Keyframes::Interpolation::Linear;
    std::map<std::string, Keyframes> cameraKeyframes_;
    std::map<std::string, Keyframes> objectKeyframes_;
    std::map<std::string, std::string> objectNames_;
    // The camera of the frame loaded, and where its keyframed keys were written.
    json animatedCamera_;
    std::map<std::string, std::string> animatedCameraPointers_;
};

class SceneLoader::Reader::ObjectParameters final : public MaterialParameters {
public:
    ObjectParameters(Reader& loader, const Node& node, const char* what)
        : loader_(loader), node_(node), what_(what) {}

    bool has(const std::string& key) const override { return node_.has(key); }
    float number(const std::string& key) const override {
        return loader_.readNumber(loader_.require(node_, key, what_));
    }
    float numberAbove(const std::string& key, float minimum, bool inclusive) const override {
        return loader_.readNumberAtLeast(loader_.require(node_, key, what_), minimum, inclusive);
    }
    Vec3 point(const std::string& key) const override {
        return loader_.readVec3(loader_.require(node_, key, what_));
    }
    Vec3 direction(const std::string& key) const override {
        return loader_.readDirection(loader_.require(node_, key, what_));
    }
    Color color(const std::string& key) const override {
        return loader_.readColor(loader_.require(node_, key, what_));
    }
    bool flag(const std::string& key) const override {
        return loader_.readFlag(loader_.require(node_, key, what_));
    }
    std::size_t choice(const std::string& key,
                       const std::vector<std::string>& options) const override {
        const Node value = loader_.require(node_, key, what_);
        const std::string text = loader_.readString(value);
        const auto it = std::find(options.begin(), options.end(), text);
        if (it == options.end()) {
            loader_.fail(value, unknownName(key, text, options));
        }
        return static_cast<std::size_t>(it - options.begin());
    }
    std::shared_ptr<const Texture> texture(const std::string& key) const override {
        return loader_.loadTexture(loader_.require(node_, key, what_));
    }
    std::shared_ptr<const Texture> dataTexture(const std::string& key) const override {
        return loader_.loadTexture(loader_.require(node_, key, what_), ImageReader::Content::Data);
    }
    bool isTexture(const std::string& key) const override {
        return loader_.require(node_, key, what_).value.is_object();
    }
    std::unique_ptr<Parameters> object(const std::string& key,
                                       const std::vector<std::string>& keys) const override {
        const Node value = loader_.require(node_, key, what_);
        loader_.requireObject(value, value.name);
        loader_.checkKeys(value, value.name, keys);
        return std::make_unique<ObjectParameters>(loader_, value, value.name.c_str());
    }
    [[noreturn]] void fail(const std::string& key, const std::string& message) const override {
        loader_.fail(node_.has(key) ? node_[key] : node_, message);
    }

private:
    Reader& loader_;
    const Node node_;
    std::string what_;
};

// The scene file's object and light types: one registration line each.
const Registry<SceneLoader::Reader::ObjectType>& SceneLoader::Reader::objectTypes() {
    static const Registry<ObjectType> types{
        {"sphere", "a sphere", &Reader::loadShape<Sphere>},
        {"plane", "a plane", &Reader::loadShape<Plane>},
        {"triangle", "a triangle", &Reader::loadTriangle},
        {"mesh", "a mesh", &Reader::loadMeshObject},
        {"gltf", "a glTF model", &Reader::loadGltfObject},
        {"disk", "a disk", &Reader::loadShape<Disk>},
        {"box", "a box", &Reader::loadShape<Box>},
        {"cylinder", "a cylinder", &Reader::loadShape<Cylinder>},
        {"cone", "a cone", &Reader::loadShape<Cone>},
        {"torus", "a torus", &Reader::loadShape<Torus>},
        {"csg", "a csg", &Reader::loadCsg},
        {"group", "a group", &Reader::loadGroupObject},
    };
    return types;
}

const Registry<SceneLoader::Reader::MaterialType>& SceneLoader::Reader::materialTypes() {
    static const Registry<MaterialType> types{
        {"blinn_phong", &BlinnPhongMaterial::keys, &BlinnPhongMaterial::create},
    };
    return types;
}

const Registry<SceneLoader::Reader::TextureType>& SceneLoader::Reader::textureTypes() {
    static const Registry<TextureType> types{
        {"texture", &Reader::loadImageTextureFile},
        {"checker", &Reader::loadCheckerTexture},
    };
    return types;
}

const Registry<SceneLoader::Reader::LightType>& SceneLoader::Reader::lightTypes() {
    static const Registry<LightType> types{
        {"point", "a point light", &Reader::loadLight<PointLight>},
        {"directional", "a directional light", &Reader::loadLight<DirectionalLight>},
        {"spot", "a spot light", &Reader::loadLight<SpotLight>},
        {"quad", "a quad light", &Reader::loadQuadLight},
        {"sphere", "a sphere light", &Reader::loadSphereLight},
    };
    return types;
}

const Registry<SceneLoader::Reader::CameraType>& SceneLoader::Reader::cameraTypes() {
    static const Registry<CameraType> types{
        {"perspective", &PerspectiveCamera::keys, &PerspectiveCamera::create},
        {"orthographic", &OrthographicCamera::keys, &OrthographicCamera::create},
        {"fisheye", &FisheyeCamera::keys, &FisheyeCamera::create},
        {"latlong", &LatLongCamera::keys, &LatLongCamera::create},
    };
    return types;
}

SceneLoader::Reader::Node SceneLoader::Reader::Node::operator[](const std::string& key) const {
    if (memberPointers)
        if (const auto written = memberPointers->find(key); written != memberPointers->end())
            return {value.at(key), written->second, inQuotes(key), document};
    return {value.at(key), JsonDocument::child(pointer, key), inQuotes(key), document};
}

SceneLoader::Reader::Node SceneLoader::Reader::Node::at(std::size_t index) const {
    return {value.at(index), JsonDocument::child(pointer, index),
            "element " + std::to_string(index) + " of " + name, document};
}

std::vector<SceneLoader::Vocabulary> SceneLoader::vocabulary() {
    return {{"objects", Reader::objectTypes().names()},
            {"lights", Reader::lightTypes().names()},
            {"materials", Reader::materialTypes().names()},
            {"textures", Reader::textureTypes().names()},
            {"cameras", Reader::cameraTypes().names()},
            {"filters", Filter::types().names()},
            {"tone operators", ToneMapper::operators().names()},
            {"integrators", IntegratorRegistry::table().names()}};
}

namespace {

// The text of a scene file (or of a file it includes); InputError naming the file if it cannot be
// read.
std::string readSceneText(const std::filesystem::path& path) {
    return InputFile::read(path, "a scene file", "scene files", InputFile::kMaxSceneBytes);
}

// What tells files apart however a path names them: the canonical path (or the path as given,
// when the file system cannot say).
std::string identityOf(const std::filesystem::path& path) {
    std::error_code error;
    const std::filesystem::path canonical = std::filesystem::weakly_canonical(path, error);
    return (error ? path : canonical).string();
}

// The top-level keys of an included file, and those only the scene file may give.
const std::vector<std::string> kFragmentKeys{"include", "materials", "groups", "objects", "lights"};
const std::vector<std::string> kSceneFileKeys{"render",  "camera",    "background", "environment",
                                              "ambient", "radiosity", "animation"};

}  // namespace

Scene SceneLoader::loadFile(const std::filesystem::path& path, std::vector<std::string>& warnings,
                            int frame, const ModelCache* modelCache) {
    Scene scene = loadString(readSceneText(path), path.string(), warnings, frame, modelCache);
    scene.addSourceFile(path);
    return scene;
}

Scene SceneLoader::loadString(const std::string& text, const std::string& fileName,
                              std::vector<std::string>& warnings, int frame,
                              const ModelCache* modelCache) {
    const JsonDocument doc = JsonDocument::parse(text, fileName);
    return Reader(doc, warnings, frame, modelCache).load();
}

SceneLoader::Reader::Reader(const JsonDocument& doc, std::vector<std::string>& warnings, int frame,
                            const ModelCache* modelCache)
    : doc_(doc), warnings_(warnings), frame_(frame), modelCache_(modelCache) {}

Scene SceneLoader::Reader::load() {
    const auto start = std::chrono::steady_clock::now();
    const Node root{doc_.root(), "", "the scene", &doc_};
    requireObject(root, "the scene");
    checkKeys(root, "the scene", withKeys(kSceneFileKeys, kFragmentKeys));

    defaultMaterial_ = scene_.addMaterial(std::make_unique<BlinnPhongMaterial>());
    if (root.has("render")) loadRender(root["render"]);
    if (root.has("radiosity")) loadRadiosity(root["radiosity"]);
    if (root.has("animation")) loadAnimation(root["animation"]);
    if (!root.has("camera")) fail(root, "the scene has no \"camera\"");
    loadCamera(root["camera"]);
    if (root.has("background")) scene_.setBackground(readColor(root["background"]));
    if (root.has("environment")) loadEnvironment(root);
    if (root.has("ambient")) scene_.setAmbient(readColor(root["ambient"]));
    // The included files' contents come before the scene file's own; every name is defined
    // before any object is read, so that an object may use what any file defines.
    std::vector<Node> fragments;
    const std::string sceneFile = identityOf(doc_.fileName());
    filesRead_.insert(sceneFile);
    includeChain_.emplace_back(sceneFile, doc_.fileName());
    readIncludes(root, fragments);
    fragments.push_back(root);
    for (const Node& fragment : fragments)
        loadDefinitions(fragment);
    // Every group is read before any object, outside any csg (whose material its objects would
    // otherwise take), and so is the same wherever it is placed; one never placed is read too,
    // so that its mistakes are found.
    for (auto& [name, group] : groups_)
        if (!group.shapes) readGroup(name, group);
    for (const Node& fragment : fragments)
        loadContents(fragment);
    checkAnimatedNames();
    warnOfLightsFacingAway();
    const auto buildStart = std::chrono::steady_clock::now();
    scene_.buildAccelerationStructure();
    scene_.statistics().buildSeconds += secondsSince(buildStart);
    scene_.statistics().loadSeconds = secondsSince(start);
    return std::move(scene_);
}

void SceneLoader::Reader::readIncludes(const Node& fragment, std::vector<Node>& fragments) {
    if (!fragment.has("include")) return;
    const Node list = fragment["include"];
    requireArray(list, "\"include\"");
    for (std::size_t i = 0; i < list.value.size(); ++i) {
        const Node entry = list.at(i);
        const std::filesystem::path path = (folderOf(entry) / readString(entry)).lexically_normal();
        const std::string identity = identityOf(path);
        const auto onChain = std::find_if(includeChain_.begin(), includeChain_.end(),
                                          [&](const auto& link) { return link.first == identity; });
        if (onChain != includeChain_.end()) {
            std::string cycle;
            for (auto link = onChain; link != includeChain_.end(); ++link)
                cycle += link->second + " includes ";
            fail(entry, "include cycle: " + cycle + path.string());
        }
        // A file included twice (a library of materials that several files use) is read once.
        if (!filesRead_.insert(identity).second) continue;
        std::string text;
        try {
            text = readSceneText(path);
        } catch (const InputError& e) {
            fail(entry, "include " + inQuotes(path.string()) + ": " + e.message());
        }
        scene_.addSourceFile(path);
        // Its own mistakes are told at their place in it.
        const JsonDocument& document = *included_.emplace_back(
            std::make_unique<const JsonDocument>(JsonDocument::parse(text, path.string())));
        const Node root{document.root(), "", "the included file", &document};
        requireObject(root, "an included file");
        for (const std::string& key : kSceneFileKeys)
            if (root.has(key))
                failAtKey(root[key], inQuotes(key) +
                                         " belongs to the scene file itself: an included file "
                                         "may give " +
                                         quotedNames(kFragmentKeys));
        checkKeys(root, "an included file", kFragmentKeys);
        includeChain_.emplace_back(identity, path.string());
        readIncludes(root, fragments);
        includeChain_.pop_back();
        fragments.push_back(root);
    }
}

void SceneLoader::Reader::loadDefinitions(const Node& fragment) {
    if (fragment.has("materials")) loadMaterials(fragment["materials"]);
    if (fragment.has("groups")) loadGroups(fragment["groups"]);
}

void SceneLoader::Reader::loadContents(const Node& fragment) {
    if (fragment.has("objects")) {
        const Node objects = fragment["objects"];
        requireArray(objects, "\"objects\"");
        for (std::size_t i = 0; i < objects.value.size(); ++i)
            loadObject(objects.at(i));
    }
    if (fragment.has("lights")) {
        const Node lights = fragment["lights"];
        requireArray(lights, "\"lights\"");
        for (std::size_t i = 0; i < lights.value.size(); ++i)
            loadLight(lights.at(i));
    }
}

void SceneLoader::Reader::loadRender(const Node& node) {
    requireObject(node, "\"render\"");
    checkKeys(node, "\"render\"",
              {"width", "height", "spp", "max_depth", "adc_bailout", "integrator", "filter",
               "adaptive", "light_edge_factor", "exposure", "tonemap", "clamp"});
    RenderSettings& settings = scene_.settings();
    if (node.has("width"))
        settings.width = readInt(node["width"], 1, RenderSettings::kMaxImageSide);
    if (node.has("height"))
        settings.height = readInt(node["height"], 1, RenderSettings::kMaxImageSide);
    if (node.has("spp"))
        settings.samplesPerPixel = readInt(node["spp"], 1, RenderSettings::kMaxSamplesPerPixel);
    if (node.has("max_depth"))
        settings.maxDepth = readInt(node["max_depth"], 0, RenderSettings::kMaxDepthLimit);
    if (node.has("adc_bailout")) {
        const Node bailout = node["adc_bailout"];
        settings.adcBailout = readNumber(bailout);
        if (!(settings.adcBailout >= 0 && settings.adcBailout <= 1))
            fail(bailout, "\"adc_bailout\" must be between 0 and 1");
    }
    if (node.has("integrator")) {
        settings.integrator =
            lookUp(IntegratorRegistry::table(), node["integrator"], "integrator").name;
    }
    if (node.has("filter")) loadFilter(node["filter"]);
    if (node.has("adaptive")) loadAdaptive(node, node["adaptive"]);
    if (node.has("light_edge_factor"))
        settings.lightEdgeFactor =
            readInt(node["light_edge_factor"], 1, RenderSettings::kMaxSamplesPerPixel);
    if (node.has("exposure")) {
        const Node exposure = node["exposure"];
        settings.exposure = readNumber(exposure);
        constexpr int limit = RenderSettings::kMaxExposure;
        if (std::abs(settings.exposure) > static_cast<float>(limit))
            fail(exposure, "\"exposure\" must be between -" + std::to_string(limit) + " and " +
                               std::to_string(limit) + " stops");
    }
    if (node.has("tonemap"))
        settings.tonemap = lookUp(ToneMapper::operators(), node["tonemap"], "tonemap").name;
    if (node.has("clamp")) settings.sampleClamp = readNumberAtLeast(node["clamp"], 0, false);
}

void SceneLoader::Reader::loadFilter(const Node& node) {
    FilterSettings& filter = scene_.settings().filter;
    if (node.value.is_object()) {
        checkKeys(node, "\"filter\"", {"type", "radius"});
        if (node.has("radius")) {
            const Node radius = node["radius"];
            filter.radius = readNumberAtLeast(radius, 0, false);
            // Far outside this range the filters' arithmetic under- or overflows.
            if (*filter.radius < 0.001f || *filter.radius > 32)
                fail(radius, "\"radius\" must be between 0.001 and 32 pixels");
        }
    } else if (!node.value.is_string()) {
        fail(node, "\"filter\" must be a filter name or {\"type\": NAME, \"radius\": R}, got " +
                       describe(node.value));
    }
    const Node type = node.value.is_object() ? require(node, "type", "\"filter\"") : node;
    filter.type = lookUp(Filter::types(), type, "filter").name;
}

void SceneLoader::Reader::loadAdaptive(const Node& render, const Node& node) {
    requireObject(node, "\"adaptive\"");
    checkKeys(node, "\"adaptive\"", {"min_spp", "max_spp", "threshold"});
    RenderSettings& settings = scene_.settings();
    AdaptiveSettings adaptive;
    if (node.has("max_spp")) {
        // Both would set RenderSettings::samplesPerPixel, the per-pixel budget.
        if (render.has("spp"))
            failAtKey(node["max_spp"],
                      "\"max_spp\" and the render's \"spp\" both set the most samples per "
                      "pixel; give one of them");
        settings.samplesPerPixel = readInt(node["max_spp"], 1, RenderSettings::kMaxSamplesPerPixel);
    }
    if (node.has("min_spp")) {
        const Node minSpp = node["min_spp"];
        adaptive.minSamples = readInt(minSpp, 1, RenderSettings::kMaxSamplesPerPixel);
        if (adaptive.minSamples > settings.samplesPerPixel)
            fail(minSpp, "\"min_spp\" (" + std::to_string(adaptive.minSamples) +
                             ") is more than \"max_spp\" (" +
                             std::to_string(settings.samplesPerPixel) +
                             (node.has("max_spp") ? "" : ", the render's \"spp\"") + ")");
    } else {
        adaptive.minSamples = std::min(adaptive.minSamples, settings.samplesPerPixel);
    }
    if (node.has("threshold")) adaptive.threshold = readNumberAtLeast(node["threshold"], 0, false);
    settings.adaptive = adaptive;
}

void SceneLoader::Reader::loadRadiosity(const Node& node) {
    requireObject(node, "\"radiosity\"");
    checkKeys(
        node, "\"radiosity\"",
        {"method", "patch_size", "element_size", "threshold", "max_shots", "subdivision_levels",
         "subdivision_tolerance", "visibility_rays", "refined_visibility_rays",
         "refinement_tolerance", "clusters", "glossy_samples", "final_gather", "direct_samples"});
    RadiositySettings& r = scene_.settings().radiosity;
    if (node.has("method"))
        r.method =
            lookUp(RadiosityMethodRegistry::table(), node["method"], "radiosity method").name;
    if (node.has("patch_size")) r.patchSize = readNumberAtLeast(node["patch_size"], 0, false);
    if (node.has("element_size")) r.elementSize = readNumberAtLeast(node["element_size"], 0, false);
    if (node.has("threshold")) {
        r.threshold = readNumberAtLeast(node["threshold"], 0, false);
        if (r.threshold >= 1) fail(node["threshold"], "\"threshold\" must be below 1");
    }
    if (node.has("max_shots")) r.maxShots = readInt(node["max_shots"], 1);
    if (node.has("subdivision_levels")) {
        r.subdivisionLevels = readInt(node["subdivision_levels"], 0);
        // Each level multiplies the elements by up to four.
        if (r.subdivisionLevels > 8)
            fail(node["subdivision_levels"], "\"subdivision_levels\" must be at most 8");
    }
    if (node.has("subdivision_tolerance"))
        r.subdivisionTolerance = readNumberAtLeast(node["subdivision_tolerance"], 0, false);
    if (node.has("refinement_tolerance"))
        r.refinementTolerance = readNumberAtLeast(node["refinement_tolerance"], 0, false);
    if (node.has("clusters")) r.clusters = readFlag(node["clusters"]);
    // A count of rays or samples between `least` and `most`.
    const auto readCount = [&](const char* key, int least, int most, int& into) {
        if (!node.has(key)) return;
        into = readInt(node[key], least);
        if (into > most)
            fail(node[key], "\"" + std::string(key) + "\" must be at most " + std::to_string(most));
    };
    readCount("visibility_rays", 1, 1024, r.visibilityRays);
    readCount("refined_visibility_rays", 1, 1024, r.refinedVisibilityRays);
    readCount("final_gather", 0, 4096, r.finalGather);
    readCount("glossy_samples", 0, 4096, r.glossySamples);
    readCount("direct_samples", 0, 4096, r.directSamples);
}

void SceneLoader::Reader::loadCamera(const Node& node) {
    requireObject(node, "\"camera\"");
    if (cameraKeyframes_.empty()) return loadCameraOfType(node);
    animatedCamera_ = node.value;
    for (const auto& [key, keyframes] : cameraKeyframes_) {
        Keyframes::Value value = keyframes.at(frame_, interpolation_);
        animatedCamera_[key] = std::move(value.value);
        animatedCameraPointers_[key] = JsonDocument::child(value.pointer, key);
    }
    loadCameraOfType(
        {animatedCamera_, node.pointer, node.name, node.document, &animatedCameraPointers_});
}

void SceneLoader::Reader::loadCameraOfType(const Node& node) {
    const CameraType& entry = node.has("type") ? lookUp(cameraTypes(), node["type"], "camera type")
                                               : *cameraTypes().find("perspective");
    checkKeys(node, "\"camera\"", withKeys({"type", "position", "look_at", "up"}, entry.keys()));
    const Vec3 position = readVec3(require(node, "position", "the camera"));
    const Vec3 lookAt = readVec3(require(node, "look_at", "the camera"));
    if (position == lookAt) fail(node["look_at"], "\"look_at\" is the camera's own \"position\"");
    const Vec3 up = node.has("up") ? readDirection(node["up"]) : Vec3(0, 1, 0);
    if (lengthSquared(cross(normalize(up), normalize(position - lookAt))) < 1e-12f)
        fail(node.has("up") ? node["up"] : node,
             "the camera's \"up\" is parallel to its viewing direction");
    scene_.setCamera(entry.create(ObjectParameters(*this, node, "the camera"),
                                  CameraFrame(position, lookAt, up)));
}

void SceneLoader::Reader::loadMaterials(const Node& node) {
    requireObject(node, "\"materials\"");
    for (const auto& [name, value] : node.value.items()) {
        checkFirstDefinition(materialPlaces_, name, node[name], "material");
        materialPlaces_[name] = placeOfKey(node[name]);
        materials_[name] = scene_.addMaterial(loadMaterial(node[name]));
    }
}

void SceneLoader::Reader::loadGroups(const Node& node) {
    requireObject(node, "\"groups\"");
    for (const auto& [name, value] : node.value.items()) {
        const Node objects = node[name];
        requireArray(objects, "group " + objects.name);
        checkFirstDefinition(groupPlaces_, name, objects, "group");
        groupPlaces_[name] = placeOfKey(objects);
        groups_.emplace(name, Group{objects, std::nullopt, 0});
    }
}

void SceneLoader::Reader::checkFirstDefinition(
    const std::map<std::string, std::string>& placesOfNames, const std::string& name,
    const Node& definition, const std::string& what) const {
    if (const auto it = placesOfNames.find(name); it != placesOfNames.end())
        failAtKey(definition,
                  what + " " + inQuotes(name) + " is defined twice: here and at " + it->second);
}

std::unique_ptr<Material> SceneLoader::Reader::loadMaterial(const Node& node) {
    requireObject(node, "material " + node.name);
    const MaterialType& entry = node.has("type")
                                    ? lookUp(materialTypes(), node["type"], "material type")
                                    : *materialTypes().find("blinn_phong");
    checkKeys(node, "a material",
              withKeys({"type", "normal_map", "bump_map", "bump_scale", "opacity"}, entry.keys()));
    std::unique_ptr<Material> material = entry.create(ObjectParameters(*this, node, "a material"));
    material->setShadingNormalMap(loadShadingNormalMap(node));
    if (node.has("opacity")) {
        // A mask, not a fraction: a surface is there or cut away, so a number would be all or none.
        if (!node["opacity"].value.is_object())
            fail(node["opacity"],
                 "\"opacity\" is a cut-out mask: a texture ({\"texture\": FILE} or a checker)");
        material->setOpacity(loadTexture(node["opacity"], ImageReader::Content::Alpha));
    }
    warnOfByteColours(node);
    return material;
}

void SceneLoader::Reader::warnOfByteColours(const Node& material) const {
    // Reflectances only: they lie in [0, 1], so whole numbers up to 255 above 1 are a picker's
    // bytes. Emission and light radiances are legitimately large and often whole.
    for (const char* key : {"diffuse", "ambient", "specular", "reflection", "transmission"}) {
        if (!material.has(key)) continue;
        const nlohmann::json& value = material[key].value;
        std::vector<double> channels;
        if (value.is_number()) channels.push_back(value.get<double>());
        if (value.is_array())
            for (const nlohmann::json& channel : value)
                if (channel.is_number()) channels.push_back(channel.get<double>());
        if (channels.empty()) continue;
        const bool bytes = std::all_of(channels.begin(), channels.end(), [](double c) {
            return c >= 0 && c <= 255 && c == std::floor(c);
        });
        if (bytes && *std::max_element(channels.begin(), channels.end()) > 1)
            warn(material[key], "\"" + std::string(key) + "\" " + value.dump() +
                                    " looks like 8-bit values (0 to 255): colours are linear, "
                                    "from 0 to 1 (divide by 255, then convert from sRGB)");
    }
}

std::shared_ptr<const ShadingNormalMap> SceneLoader::Reader::loadShadingNormalMap(
    const Node& material) {
    if (material.has("normal_map") && material.has("bump_map"))
        failAtKey(material["bump_map"],
                  "\"normal_map\" and \"bump_map\" both give the shading normal; give one of them");
    if (material.has("bump_scale") && !material.has("bump_map"))
        failAtKey(material["bump_scale"], "\"bump_scale\" scales a \"bump_map\", which is missing");
    if (material.has("normal_map"))
        return std::make_shared<NormalMap>(
            loadImageFile(material["normal_map"], "normal map", ImageReader::Content::Data));
    if (!material.has("bump_map")) return nullptr;
    const float scale = material.has("bump_scale") ? readNumber(material["bump_scale"]) : 1;
    return std::make_shared<BumpMap>(
        loadImageFile(material["bump_map"], "bump map", ImageReader::Content::Data), scale);
}

std::shared_ptr<const Texture> SceneLoader::Reader::loadTexture(const Node& node,
                                                                ImageReader::Content content) {
    if (!node.value.is_object()) return std::make_shared<ConstantTexture>(readColor(node));
    checkKeys(node, "a texture", textureTypes().names());
    if (node.value.size() != 1)
        fail(node, "a texture is one of " + textureTypes().quotedNames() + ": {NAME: ...}");
    const std::string name = node.value.begin().key();
    return (this->*textureTypes().find(name)->load)(node[name], content);
}

std::shared_ptr<const Texture> SceneLoader::Reader::loadImageTextureFile(
    const Node& file, ImageReader::Content content) {
    return loadImageFile(file, "texture", content);
}

std::shared_ptr<const Texture> SceneLoader::Reader::loadImageFile(const Node& file,
                                                                  const std::string& what,
                                                                  ImageReader::Content content) {
    const std::filesystem::path path = folderOf(file) / readString(file);
    try {
        return loadImageTexture(path, content);
    } catch (const InputError& e) {
        fail(file, what + " " + inQuotes(path.string()) + ": " + e.message());
    }
}

std::shared_ptr<const Texture> SceneLoader::Reader::loadCheckerTexture(const Node& checker,
                                                                       ImageReader::Content) {
    requireObject(checker, "\"checker\"");
    checkKeys(checker, "\"checker\"", CheckerTexture::keys());
    return CheckerTexture::create(ObjectParameters(*this, checker, "\"checker\""));
}

const Material* SceneLoader::Reader::materialOf(const Node& object) {
    if (!object.has("material")) return defaultMaterial_;
    const Node node = object["material"];
    const std::string name = readString(node);
    const auto it = materials_.find(name);
    if (it != materials_.end()) return it->second;
    failUndefined(node, "material", name, materials_, "materials");
}

void SceneLoader::Reader::loadObject(const Node& node) {
    for (std::unique_ptr<Shape>& shape : readObject(node))
        scene_.addShape(std::move(shape));
}

SceneLoader::Reader::Shapes SceneLoader::Reader::readObject(const Node& node) {
    requireObject(node, "an object");
    const ObjectType& entry =
        lookUp(objectTypes(), require(node, "type", "an object"), "object type");
    return (this->*entry.load)(node, entry.what, readPlacement(node));
}

template <typename ShapeType>
SceneLoader::Reader::Shapes SceneLoader::Reader::loadShape(
    const Node& node, const char* what, const std::optional<Transform>& transform) {
    checkKeys(node, what, withKeys({"type", "material", "transform", "name"}, ShapeType::keys()));
    return only(placed(ShapeType::create(ObjectParameters(*this, node, what), materialOf(node)),
                       transform));
}

template <typename LightType>
void SceneLoader::Reader::loadLight(const Node& node, const char* what) {
    checkKeys(node, what, withKeys({"type"}, LightType::keys()));
    scene_.addLight(LightType::create(ObjectParameters(*this, node, what)));
}

SceneLoader::Reader::Shapes SceneLoader::Reader::loadTriangle(
    const Node& node, const char* what, const std::optional<Transform>& transform) {
    checkKeys(node, what, {"type", "vertices", "normals", "uvs", "material", "transform", "name"});
    const auto readThree = [&](const std::string& key, auto read) {
        const Node list = require(node, key, what);
        if (!list.value.is_array() || list.value.size() != 3)
            fail(list, inQuotes(key) + " must be an array of 3, got " + describe(list.value));
        using T = decltype(read(list));
        std::array<T, 3> out;
        for (std::size_t i = 0; i < 3; ++i)
            out[i] = read(list.at(i));
        return out;
    };
    const auto vertices = readThree("vertices", [&](const Node& n) { return readVec3(n); });
    std::optional<std::array<Vec3, 3>> normals;
    std::optional<std::array<Vec2, 3>> uvs;
    if (node.has("normals"))
        normals = readThree("normals", [&](const Node& n) { return readDirection(n); });
    if (node.has("uvs")) uvs = readThree("uvs", [&](const Node& n) { return readVec2(n); });
    auto triangle = std::make_unique<Triangle>(vertices, materialOf(node), normals, uvs);
    if (!(triangle->area(0) > 0)) {
        warn(node["vertices"], "triangle has zero area and is left out");
        return {};
    }
    ++scene_.statistics().uniqueTriangles;
    ++scene_.statistics().instancedTriangles;
    return only(placed(std::move(triangle), transform));
}

SceneLoader::Reader::Shapes SceneLoader::Reader::loadMeshObject(
    const Node& node, const char* what, const std::optional<Transform>& transform) {
    const auto makeMesh = [this](const std::filesystem::path& path,
                                 const std::optional<float>& smooth) {
        if (PlyLoader::isPly(path)) return builtMesh(PlyLoader::load(path, warnings_), smooth);
        const auto loadTexture = [this](const std::filesystem::path& p,
                                        ImageReader::Content content) {
            return loadImageTexture(p, content);
        };
        std::vector<std::filesystem::path> materialFiles;
        std::shared_ptr<const Mesh> mesh;
        if (modelCache_)
            mesh = modelCache_->findObj(path, smooth, loadTexture, warnings_, materialFiles);
        if (mesh) {
            ++scene_.statistics().cachedModels;
        } else {
            ObjLoader::Geometry geometry = ObjLoader::readGeometry(path);
            geometry.triangles->materials = ObjLoader::complete(
                path, geometry.completion, loadTexture, warnings_, &materialFiles);
            mesh = builtMesh(std::move(geometry.triangles), smooth);
            if (modelCache_)
                modelCache_->storeObj(path, smooth, geometry.completion, geometry.sources, *mesh,
                                      warnings_);
        }
        for (const std::filesystem::path& file : materialFiles)
            scene_.addSourceFile(file);
        return mesh;
    };
    return loadModelObject(node, what, transform, "mesh", makeMesh);
}

SceneLoader::Reader::Shapes SceneLoader::Reader::loadGltfObject(
    const Node& node, const char* what, const std::optional<Transform>& transform) {
    const auto makeGltf = [this](const std::filesystem::path& path,
                                 const std::optional<float>& smooth) {
        std::vector<std::filesystem::path> externalFiles;
        std::shared_ptr<TriangleMesh> triangles = GltfLoader::load(path, warnings_, &externalFiles);
        for (const std::filesystem::path& file : externalFiles)
            scene_.addSourceFile(file);
        return builtMesh(std::move(triangles), smooth);
    };
    return loadModelObject(node, what, transform, "glTF model", makeGltf);
}

SceneLoader::Reader::Shapes SceneLoader::Reader::loadModelObject(
    const Node& node, const char* what, const std::optional<Transform>& transform,
    const std::string& model, const MeshMaker& make) {
    checkKeys(node, what, {"type", "file", "material", "transform", "name", "smooth"});
    std::optional<float> smooth;
    if (node.has("smooth")) {
        smooth = readNumberAtLeast(node["smooth"], 0, true);
        if (*smooth > SmoothingByAngle::kMaxDegrees)
            fail(node["smooth"], "\"smooth\" must be between 0 and 180 degrees");
    }
    std::shared_ptr<const Mesh> mesh = loadMesh(require(node, "file", what), model, make, smooth);
    scene_.statistics().instancedTriangles += mesh->triangles().triangleCount();
    // Without "material", the model's own materials (an OBJ's .mtl, a glTF's) are used.
    const Material* material = node.has("material") ? materialOf(node) : nullptr;
    return only(
        std::make_unique<Instance>(std::move(mesh), transform.value_or(Transform()), material));
}

SceneLoader::Reader::Shapes SceneLoader::Reader::loadCsg(
    const Node& node, const char* what, const std::optional<Transform>& transform) {
    checkKeys(node, what, {"type", "operation", "objects", "material", "transform", "name"});
    const auto operation = static_cast<Csg::Operation>(
        ObjectParameters(*this, node, what).choice("operation", Csg::operationNames()));
    const Node objects = require(node, "objects", what);
    requireArray(objects, "\"objects\"");
    if (objects.value.size() < 2)
        fail(objects,
             "a csg combines at least two objects, got " + std::to_string(objects.value.size()));
    // The csg's material is that of the children that name none.
    const Material* outerDefault = defaultMaterial_;
    const Material* material = materialOf(node);
    defaultMaterial_ = material;
    std::vector<std::unique_ptr<Shape>> children;
    for (std::size_t i = 0; i < objects.value.size(); ++i) {
        const Node child = objects.at(i);
        Shapes shapes = readObject(child);
        if (shapes.size() != 1 || !shapes.front()->isSolid())
            fail(child, std::string(lookUp(objectTypes(), child["type"], "object type").what) +
                            " here is not a solid (a closed surface): a csg combines spheres, " +
                            "boxes, closed cylinders and cones, tori, csgs and meshes of closed " +
                            "models");
        children.push_back(std::move(shapes.front()));
    }
    defaultMaterial_ = outerDefault;
    return only(placed(std::make_unique<Csg>(operation, std::move(children), material), transform));
}

SceneLoader::Reader::Shapes SceneLoader::Reader::loadGroupObject(
    const Node& node, const char* what, const std::optional<Transform>& transform) {
    checkKeys(node, what, {"type", "group", "transform", "name"});
    const Group& group = groupNamed(require(node, "group", what));
    scene_.statistics().instancedTriangles += group.instancedTriangles;
    Shapes shapes;
    for (const std::shared_ptr<const Shape>& shape : *group.shapes)
        shapes.push_back(std::make_unique<Instance>(shape, transform.value_or(Transform())));
    return shapes;
}

const SceneLoader::Reader::Group& SceneLoader::Reader::groupNamed(const Node& name) {
    const std::string text = readString(name);
    const auto it = groups_.find(text);
    if (it == groups_.end()) failUndefined(name, "group", text, groups_, "groups");
    const auto reading = std::find(groupsBeingRead_.begin(), groupsBeingRead_.end(), text);
    if (reading != groupsBeingRead_.end()) {
        std::string cycle;
        for (auto group = reading; group != groupsBeingRead_.end(); ++group)
            cycle += inQuotes(*group) + " places ";
        fail(name, "group cycle: " + cycle + inQuotes(text));
    }
    if (!it->second.shapes) readGroup(text, it->second);
    return it->second;
}

void SceneLoader::Reader::readGroup(const std::string& name, Group& group) {
    groupsBeingRead_.push_back(name);
    // Reading the group's objects draws nothing: each placement draws its triangles.
    std::size_t& drawn = scene_.statistics().instancedTriangles;
    const std::size_t drawnBefore = drawn;
    std::vector<std::shared_ptr<const Shape>> shapes;
    for (std::size_t i = 0; i < group.objects.value.size(); ++i)
        for (std::unique_ptr<Shape>& shape : readObject(group.objects.at(i)))
            shapes.push_back(std::move(shape));
    group.instancedTriangles = drawn - drawnBefore;
    drawn = drawnBefore;
    group.shapes = std::move(shapes);
    groupsBeingRead_.pop_back();
}

std::unique_ptr<Shape> SceneLoader::Reader::placed(std::unique_ptr<Shape> shape,
                                                   const std::optional<Transform>& transform) {
    if (!transform) return shape;
    return std::make_unique<Instance>(std::move(shape), *transform);
}

SceneLoader::Reader::Shapes SceneLoader::Reader::only(std::unique_ptr<Shape> shape) {
    Shapes shapes;
    shapes.push_back(std::move(shape));
    return shapes;
}

std::shared_ptr<const Mesh> SceneLoader::Reader::builtMesh(std::shared_ptr<TriangleMesh> triangles,
                                                           const std::optional<float>& smooth) {
    if (smooth) SmoothingByAngle::apply(*triangles, *smooth);
    const auto buildStart = std::chrono::steady_clock::now();
    auto mesh = std::make_shared<const Mesh>(std::move(*triangles));
    scene_.statistics().buildSeconds += secondsSince(buildStart);
    return mesh;
}

std::shared_ptr<const Mesh> SceneLoader::Reader::loadMesh(const Node& file,
                                                          const std::string& model,
                                                          const MeshMaker& make,
                                                          const std::optional<float>& smooth) {
    const std::filesystem::path path = folderOf(file) / readString(file);
    const std::string key = model + " " + std::filesystem::weakly_canonical(path).string() +
                            (smooth ? " smooth " + std::to_string(*smooth) : "");
    if (const auto it = meshes_.find(key); it != meshes_.end()) return it->second;
    try {
        std::shared_ptr<const Mesh> mesh = make(path, smooth);
        scene_.addSourceFile(path);
        meshes_[key] = mesh;
        scene_.statistics().uniqueTriangles += mesh->triangles().triangleCount();
        scene_.statistics().meshBytes += mesh->memoryBytes();
        return mesh;
    } catch (const InputError& e) {
        fail(file, model + " " + inQuotes(path.string()) + ": " + e.message());
    }
}

std::shared_ptr<const Texture> SceneLoader::Reader::loadImageTexture(
    const std::filesystem::path& path, ImageReader::Content content) {
    // One file may be both a colour texture and a map, read differently.
    const std::string key = std::filesystem::weakly_canonical(path).string() + " as content " +
                            std::to_string(static_cast<int>(content));
    if (const auto it = textures_.find(key); it != textures_.end()) return it->second;
    std::shared_ptr<const Texture> texture = ImageReader::readTexture(path, content);
    scene_.addSourceFile(path);
    textures_[key] = texture;
    return texture;
}

Transform SceneLoader::Reader::readTransform(const Node& node) const {
    requireObject(node, "\"transform\"");
    checkKeys(node, "a transform", {"scale", "rotate", "translate", "matrix"});
    if (node.has("matrix")) {
        const Node matrix = node["matrix"];
        if (node.value.size() > 1)
            fail(matrix,
                 "\"matrix\" replaces \"scale\", \"rotate\" and \"translate\": give one or the "
                 "others");
        // Row-major, as 4 rows of 4 numbers or as 16 numbers.
        std::vector<float> numbers;
        const auto collect = [&](const Node& list) {
            for (std::size_t i = 0; i < list.value.size(); ++i)
                numbers.push_back(readNumber(list.at(i)));
        };
        const bool nested =
            matrix.value.is_array() && matrix.value.size() == 4 &&
            std::all_of(matrix.value.begin(), matrix.value.end(),
                        [](const json& row) { return row.is_array() && row.size() == 4; });
        if (nested) {
            for (std::size_t row = 0; row < 4; ++row)
                collect(matrix.at(row));
        } else if (matrix.value.is_array() && matrix.value.size() == 16) {
            collect(matrix);
        } else {
            fail(matrix, "\"matrix\" must be 4 rows of 4 numbers (row-major), got " +
                             describe(matrix.value));
        }
        Transform::Matrix m;
        for (std::size_t i = 0; i < 16; ++i)
            m[i / 4][i % 4] = numbers[i];
        try {
            return Transform(m);
        } catch (const std::invalid_argument& e) {
            fail(matrix, std::string("\"matrix\": ") + e.what());
        }
    }
    // scale, then rotate, then translate.
    Transform result;
    if (node.has("scale")) {
        const Node scale = node["scale"];
        const Vec3 factors = scale.value.is_number() ? Vec3(readNumber(scale)) : readVec3(scale);
        if (factors.x == 0 || factors.y == 0 || factors.z == 0)
            fail(scale, "\"scale\" factors must not be 0");
        result = Transform::scale(factors);
    }
    if (node.has("rotate")) {
        const Node rotate = node["rotate"];
        if (!rotate.value.is_array() || rotate.value.size() != 4)
            fail(rotate, "\"rotate\" must be [axis x, axis y, axis z, degrees], got " +
                             describe(rotate.value));
        const Vec3 axis(readNumber(rotate.at(0)), readNumber(rotate.at(1)),
                        readNumber(rotate.at(2)));
        if (!(lengthSquared(axis) > 0)) fail(rotate, "the \"rotate\" axis must not be zero");
        result = Transform::rotate(readNumber(rotate.at(3)), axis) * result;
    }
    if (node.has("translate")) result = Transform::translate(readVec3(node["translate"])) * result;
    return result;
}

void SceneLoader::Reader::loadAnimation(const Node& node) {
    requireObject(node, "\"animation\"");
    checkKeys(node, "\"animation\"", {"frames", "fps", "interpolation", "camera", "objects"});
    AnimationSettings& animation = scene_.settings().animation.emplace();
    animation.frames =
        readInt(require(node, "frames", "\"animation\""), 1, AnimationSettings::kMaxFrames);
    if (node.has("fps")) {
        animation.framesPerSecond = readNumberAtLeast(node["fps"], 0, false);
        if (animation.framesPerSecond > AnimationSettings::kMaxFramesPerSecond)
            fail(node["fps"], "\"fps\" must be at most " +
                                  std::to_string(AnimationSettings::kMaxFramesPerSecond));
    }
    if (node.has("interpolation"))
        interpolation_ = static_cast<Keyframes::Interpolation>(
            ObjectParameters(*this, node, "\"animation\"")
                .choice("interpolation", {"linear", "smooth"}));
    // Each keyframe's frame, checked against the animation's frames.
    const auto frameOf = [&](const Node& keyframe, const std::string& what) {
        requireObject(keyframe, what);
        return readInt(require(keyframe, "frame", what), 1, animation.frames);
    };
    const auto add = [&](Keyframes& keyframes, int frame, const Node& value,
                         const std::string& pointer) {
        try {
            keyframes.add(frame, value.value, pointer);
        } catch (const std::invalid_argument& e) {
            fail(value, value.name + ": " + e.what());
        }
    };
    if (node.has("camera")) {
        const Node camera = node["camera"];
        requireArray(camera, "the animation's \"camera\"");
        for (std::size_t i = 0; i < camera.value.size(); ++i) {
            const Node keyframe = camera.at(i);
            const int frame = frameOf(keyframe, "a camera keyframe");
            if (keyframe.value.size() < 2)
                fail(keyframe,
                     "a camera keyframe gives the frame and at least one of the "
                     "camera's keys (\"position\", \"look_at\", \"vfov\"...)");
            for (const auto& [key, value] : keyframe.value.items()) {
                if (key == "frame") continue;
                if (key == "type")
                    failAtKey(keyframe[key],
                              "the camera's \"type\" cannot change from frame "
                              "to frame");
                add(cameraKeyframes_[key], frame, keyframe[key], keyframe.pointer);
            }
        }
    }
    if (node.has("objects")) {
        const Node objects = node["objects"];
        requireObject(objects, "the animation's \"objects\"");
        for (const auto& [name, ignored] : objects.value.items()) {
            const Node keyframes = objects[name];
            requireArray(keyframes, "the keyframes of " + inQuotes(name));
            if (keyframes.value.empty()) fail(keyframes, inQuotes(name) + " has no keyframe");
            for (std::size_t i = 0; i < keyframes.value.size(); ++i) {
                const Node keyframe = keyframes.at(i);
                const std::string what = "a keyframe of " + inQuotes(name);
                const int frame = frameOf(keyframe, what);
                checkKeys(keyframe, what, {"frame", "transform"});
                const Node transform = require(keyframe, "transform", what);
                readTransform(transform);
                add(objectKeyframes_[name], frame, transform, transform.pointer);
            }
        }
    }
}

std::optional<Transform> SceneLoader::Reader::readPlacement(const Node& node) {
    const std::optional<Node> name = node.has("name") ? std::optional(node["name"]) : std::nullopt;
    if (name) {
        const std::string text = readString(*name);
        if (text.empty()) fail(*name, "an object's \"name\" must not be empty");
        const auto [given, first] = objectNames_.emplace(text, placeOfKey(*name));
        if (!first)
            failAtKey(*name, "the name " + inQuotes(text) + " is already given to the object at " +
                                 given->second);
        if (const auto animated = objectKeyframes_.find(text); animated != objectKeyframes_.end()) {
            if (node.has("transform"))
                failAtKey(node["transform"],
                          inQuotes(text) +
                              " is animated: its transform is its keyframes' in \"animation\"; "
                              "give it there instead");
            const Keyframes::Value value = animated->second.at(frame_, interpolation_);
            return readTransform({value.value, value.pointer, "\"transform\"", &doc_});
        }
    }
    if (node.has("transform")) return readTransform(node["transform"]);
    return std::nullopt;
}

void SceneLoader::Reader::checkAnimatedNames() const {
    std::vector<std::string> names;
    for (const auto& [name, place] : objectNames_)
        names.push_back(name);
    for (const auto& [name, keyframes] : objectKeyframes_) {
        if (objectNames_.count(name)) continue;
        const Node root{doc_.root(), "", "the scene", &doc_};
        failAtKey(root["animation"]["objects"][name],
                  "the animation moves " + inQuotes(name) + ", but no object has that \"name\"" +
                      didYouMean(name, names) +
                      (names.empty() ? "; no object has a \"name\""
                                     : "; the objects named are " + quotedNames(names)));
    }
}

void SceneLoader::Reader::loadLight(const Node& node) {
    requireObject(node, "a light");
    const LightType& entry = lookUp(lightTypes(), require(node, "type", "a light"), "light type");
    (this->*entry.load)(node, entry.what);
}

void SceneLoader::Reader::loadEnvironment(const Node& root) {
    const Node node = root["environment"];
    if (root.has("background"))
        failAtKey(node,
                  "\"environment\" replaces \"background\" (rays that leave the scene see "
                  "the environment): give one of them");
    const char* what = "\"environment\"";
    requireObject(node, what);
    checkKeys(node, what, EnvironmentLight::keys());
    const Node file = require(node, "file", what);
    const std::filesystem::path path = folderOf(file) / readString(file);
    std::optional<Image> map;
    try {
        map = ImageReader::read(path);
    } catch (const InputError& e) {
        fail(file, "environment map " + inQuotes(path.string()) + ": " + e.message());
    }
    scene_.addSourceFile(path);
    auto environment =
        EnvironmentLight::create(ObjectParameters(*this, node, what), *std::move(map));
    environment->setShadowSamples(readShadowSamples(node));
    scene_.setEnvironment(std::move(environment));
}

int SceneLoader::Reader::readShadowSamples(const Node& node) const {
    return node.has("samples") ? readInt(node["samples"], 1) : kDefaultShadowSamples;
}

void SceneLoader::Reader::loadQuadLight(const Node& node, const char* what) {
    checkKeys(node, what, {"type", "corner", "edge1", "edge2", "radiance", "samples"});
    const Vec3 corner = readVec3(require(node, "corner", what));
    const Vec3 edge1 = readVec3(require(node, "edge1", what));
    const Vec3 edge2 = readVec3(require(node, "edge2", what));
    const auto area = static_cast<float>(length(cross(Vec3d(edge1), Vec3d(edge2))));
    if (!(area > 0) || !std::isfinite(area))
        fail(node["edge2"],
             "a quad light's \"edge1\" and \"edge2\" must be non-zero and not parallel "
             "(the quad has no area)");
    const Color radiance = readColor(require(node, "radiance", what));
    auto surface = std::make_unique<Quad>(corner, edge1, edge2, emitterOf(radiance));
    oneSidedLights_.push_back({node, surface.get(), corner, cross(edge1, edge2)});
    auto light = std::make_unique<AreaLight>(*surface, 0, radiance);
    addAreaLight(node, std::move(surface), std::move(light));
}

void SceneLoader::Reader::warnOfLightsFacingAway() const {
    if (!scene_.unboundedShapes().empty()) return;
    for (const OneSidedLight& light : oneSidedLights_) {
        const Vec3 n = normalize(light.normal);
        const auto behind = [&](const std::unique_ptr<Shape>& shape) {
            if (shape.get() == light.surface) return true;
            const Bounds3 box = shape->bounds();
            const Vec3 center = 0.5f * (box.min + box.max);
            const Vec3 halfSize = 0.5f * box.diagonal();
            const float farthest = dot(center - light.point, n) + dot(halfSize, abs(n));
            // A box that only touches the plane (a wall meeting the light's edge) is behind it;
            // rounding of the coordinates must not put it in front.
            const float touching = 1e-5f * (maxComponent(max(abs(box.min), abs(box.max))) +
                                            maxComponent(abs(light.point)));
            return farthest <= touching;
        };
        // A light alone in the scene (its own surface its only shape) has nothing to face.
        const auto& shapes = scene_.boundedShapes();
        if (shapes.size() > 1 && std::all_of(shapes.begin(), shapes.end(), behind))
            warn(light.node,
                 "the quad light faces away from every surface of the scene: it shines only on "
                 "the side \"edge1\" x \"edge2\" faces (swap the edges to turn it over)");
    }
}

void SceneLoader::Reader::loadSphereLight(const Node& node, const char* what) {
    checkKeys(node, what, {"type", "center", "radius", "radiance", "samples"});
    const Vec3 center = readVec3(require(node, "center", what));
    const float radius = readNumberAtLeast(require(node, "radius", what), 0, false);
    const Color radiance = readColor(require(node, "radiance", what));
    auto surface = std::make_unique<Sphere>(center, radius, emitterOf(radiance));
    auto light = std::make_unique<AreaLight>(*surface, 0, radiance);
    addAreaLight(node, std::move(surface), std::move(light));
}

const Material* SceneLoader::Reader::emitterOf(const Color& radiance) {
    BlinnPhongMaterial::Parameters material;
    material.diffuse = std::make_shared<ConstantTexture>(Color(0));
    material.ambient = material.diffuse;
    material.emission = radiance;
    return scene_.addMaterial(std::make_unique<BlinnPhongMaterial>(std::move(material)));
}

void SceneLoader::Reader::addAreaLight(const Node& node, std::unique_ptr<Shape> surface,
                                       std::unique_ptr<Light> light) {
    light->setShadowSamples(readShadowSamples(node));
    surface->setAreaLight(light.get());
    scene_.addShape(std::move(surface));
    scene_.addLight(std::move(light));
}

// --- reading values, with messages that say where and what ---

template <typename Entry>
const Entry& SceneLoader::Reader::lookUp(const Registry<Entry>& table, const Node& name,
                                         const std::string& what) const {
    const std::string text = readString(name);
    const Entry* entry = table.find(text);
    if (!entry) fail(name, unknownName(what, text, table.names()));
    return *entry;
}

std::filesystem::path SceneLoader::Reader::folderOf(const Node& node) {
    return std::filesystem::path(node.document->fileName()).parent_path();
}

std::string SceneLoader::Reader::placeOfKey(const Node& node) {
    const SourceLocation where = node.document->keyLocation(node.pointer);
    return node.document->fileName() + ":" + std::to_string(where.line) + ":" +
           std::to_string(where.column);
}

void SceneLoader::Reader::fail(const Node& node, const std::string& message) const {
    throw InputError(node.document->fileName(), node.document->valueLocation(node.pointer),
                     message);
}

void SceneLoader::Reader::failAtKey(const Node& node, const std::string& message) const {
    throw InputError(node.document->fileName(), node.document->keyLocation(node.pointer), message);
}

void SceneLoader::Reader::warn(const Node& node, const std::string& message) const {
    const SourceLocation where = node.document->valueLocation(node.pointer);
    warnings_.push_back(node.document->fileName() + ":" + std::to_string(where.line) + ":" +
                        std::to_string(where.column) + ": warning: " + message);
}

void SceneLoader::Reader::checkKeys(const Node& object, const std::string& what,
                                    const std::vector<std::string>& allowed) const {
    for (const auto& [key, value] : object.value.items()) {
        if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
        failAtKey(object[key], "unknown key " + inQuotes(key) + " in " + what +
                                   didYouMean(key, allowed) + "; expected " + quotedNames(allowed));
    }
}

void SceneLoader::Reader::requireObject(const Node& node, const std::string& what) const {
    if (!node.value.is_object())
        fail(node, what + " must be an object {...}, got " + describe(node.value));
}

void SceneLoader::Reader::requireArray(const Node& node, const std::string& what) const {
    if (!node.value.is_array())
        fail(node, what + " must be an array [...], got " + describe(node.value));
}

SceneLoader::Reader::Node SceneLoader::Reader::require(const Node& object, const std::string& key,
                                                       const std::string& what) const {
    if (!object.has(key)) fail(object, what + " needs " + inQuotes(key));
    return object[key];
}

bool SceneLoader::Reader::readFlag(const Node& node) const {
    if (!node.value.is_boolean())
        fail(node, node.name + " must be true or false, got " + describe(node.value));
    return node.value.get<bool>();
}

float SceneLoader::Reader::readNumber(const Node& node) const {
    if (!node.value.is_number())
        fail(node, node.name + " must be a number, got " + describe(node.value));
    const double v = node.value.get<double>();
    if (!std::isfinite(static_cast<float>(v))) fail(node, node.name + " is out of range");
    return static_cast<float>(v);
}

float SceneLoader::Reader::readNumberAtLeast(const Node& node, float minimum,
                                             bool inclusive) const {
    const float v = readNumber(node);
    if (inclusive ? v < minimum : v <= minimum)
        fail(node, node.name + " must be " + (inclusive ? "at least " : "greater than ") +
                       (minimum == 0 ? "0" : std::to_string(minimum)));
    return v;
}

int SceneLoader::Reader::readInt(const Node& node, int minimum, int maximum) const {
    if (!node.value.is_number_integer())
        fail(node, node.name + " must be a whole number, got " + describe(node.value));
    const auto v = node.value.get<long long>();
    if (v < minimum) fail(node, node.name + " must be at least " + std::to_string(minimum));
    if (v > 1'000'000'000) fail(node, node.name + " is too large");
    if (v > maximum) fail(node, node.name + " must be at most " + std::to_string(maximum));
    return static_cast<int>(v);
}

std::string SceneLoader::Reader::readString(const Node& node) const {
    if (!node.value.is_string())
        fail(node, node.name + " must be a string, got " + describe(node.value));
    return node.value.get<std::string>();
}

Vec3 SceneLoader::Reader::readVec3(const Node& node) const {
    if (!node.value.is_array() || node.value.size() != 3)
        fail(node,
             node.name + " must be an array of 3 numbers [x, y, z], got " + describe(node.value));
    Vec3 v;
    for (std::size_t i = 0; i < 3; ++i)
        v[static_cast<int>(i)] = readNumber(node.at(i));
    return v;
}

Vec3 SceneLoader::Reader::readDirection(const Node& node) const {
    const Vec3 v = readVec3(node);
    if (!(lengthSquared(v) > 0) || !isFinite(normalize(v)))
        fail(node, node.name + " must be a non-zero direction");
    return v;
}

Vec2 SceneLoader::Reader::readVec2(const Node& node) const {
    if (!node.value.is_array() || node.value.size() != 2)
        fail(node,
             node.name + " must be an array of 2 numbers [u, v], got " + describe(node.value));
    return {readNumber(node.at(0)), readNumber(node.at(1))};
}

Color SceneLoader::Reader::readColor(const Node& node) const {
    if (node.value.is_number()) {
        const float grey = readNumberAtLeast(node, 0, true);
        return Color(grey);
    }
    if (!node.value.is_array() || node.value.size() != 3)
        fail(node, node.name +
                       " must be a colour: a number or an array of 3 numbers [r, g, b], got " +
                       describe(node.value));
    Color c;
    float* channels[3] = {&c.r, &c.g, &c.b};
    for (std::size_t i = 0; i < 3; ++i)
        *channels[i] = readNumberAtLeast(node.at(i), 0, true);
    return c;
}

}  // namespace lancer
