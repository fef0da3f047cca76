#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "accel/Mesh.h"
#include "io/JsonDocument.h"
#include "materials/Texture.h"
#include "math/Transform.h"
#include "scene/Scene.h"
#include "util/Registry.h"

namespace lancer {

// Reads a scene file (the format of docs/SCENE-FORMAT.md) into a Scene. Every mistake in the file
// is an InputError naming the file, line, column and key at fault.
class SceneLoader {
public:
    // Problems that do not stop the render (a degenerate triangle dropped...) are appended to
    // `warnings`, one line each, already prefixed with their place in the file.
    static Scene loadFile(const std::filesystem::path& path, std::vector<std::string>& warnings);
    // The same for scene text in memory; `fileName` is used in messages.
    static Scene loadString(const std::string& text, const std::string& fileName,
                            std::vector<std::string>& warnings);

private:
    using json = nlohmann::json;

    // A value of the document, where it is (a JSON pointer) and what to call it in messages.
    struct Node {
        const json& value;
        std::string pointer;
        std::string name;

        Node operator[](const std::string& key) const;  // an object's member
        Node at(std::size_t index) const;               // an array's element
        bool has(const std::string& key) const { return value.contains(key); }
    };

    SceneLoader(const JsonDocument& doc, std::filesystem::path baseDir,
                std::vector<std::string>& warnings);
    Scene load();

    void loadRender(const Node& node);
    void loadFilter(const Node& node);
    void loadAdaptive(const Node& render, const Node& node);
    void loadRadiosity(const Node& node);
    void loadCamera(const Node& node);
    void loadMaterials(const Node& node);
    std::unique_ptr<Material> loadMaterial(const Node& node);
    std::shared_ptr<const Texture> loadTexture(const Node& node);
    // A type of the "objects" or "lights" array, and the member reading its keys.
    struct ObjectType {
        const char* name;
        const char* what;  // "a sphere": the object, in messages
        void (SceneLoader::*load)(const Node& node, const char* what,
                                  const std::optional<Transform>& transform);
    };
    // An object's keys, read for the class it makes.
    class ObjectParameters;
    struct LightType {
        const char* name;
        void (SceneLoader::*load)(const Node& node);
    };
    static const Registry<ObjectType>& objectTypes();
    static const Registry<LightType>& lightTypes();

    void loadObject(const Node& node);
    // A shape that reads its own keys: ShapeType::keys() and ShapeType::create(parameters,
    // material).
    template <typename ShapeType>
    void loadShape(const Node& node, const char* what, const std::optional<Transform>& transform);
    void loadTriangle(const Node& node, const char* what,
                      const std::optional<Transform>& transform);
    void loadMeshObject(const Node& node, const char* what,
                        const std::optional<Transform>& transform);
    void addShape(std::unique_ptr<Shape> shape, const std::optional<Transform>& transform);
    std::shared_ptr<const Mesh> loadMesh(const Node& file);
    std::shared_ptr<const Texture> loadImageTexture(const std::filesystem::path& path);
    Transform readTransform(const Node& node) const;
    void loadLight(const Node& node);
    void loadPointLight(const Node& node);
    void loadDirectionalLight(const Node& node);
    void loadQuadLight(const Node& node);
    void loadSphereLight(const Node& node);
    void loadSpotLight(const Node& node);
    bool readInverseSquareFalloff(const Node& light) const;
    // A material that emits `radiance` and reflects nothing: the visible surface of an area light.
    const Material* emitterOf(const Color& radiance);
    // Adds an area light and its visible surface, linked to each other.
    void addAreaLight(const Node& node, std::unique_ptr<Shape> surface,
                      std::unique_ptr<Light> light);
    const Material* materialOf(const Node& object);

    [[noreturn]] void fail(const Node& node, const std::string& message) const;
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
    int readInt(const Node& node, int minimum) const;
    std::string readString(const Node& node) const;
    Vec3 readVec3(const Node& node) const;
    Vec3 readDirection(const Node& node) const;
    Vec2 readVec2(const Node& node) const;
    Color readColor(const Node& node) const;

    const JsonDocument& doc_;
    std::filesystem::path baseDir_;  // relative paths in the scene start here
    std::vector<std::string>& warnings_;
    Scene scene_;
    std::map<std::string, const Material*> materials_;
    const Material* defaultMaterial_ = nullptr;
    // Each model and texture file is loaded once, however many objects use it.
    std::map<std::string, std::shared_ptr<const Mesh>> meshes_;
    std::map<std::string, std::shared_ptr<const Texture>> textures_;
};

}  // namespace lancer
