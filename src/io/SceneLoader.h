#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "scene/Scene.h"

namespace lancer {

class ModelCache;

// Reads a scene file (the format of docs/SCENE-FORMAT.md) into a Scene. Every mistake in the file
// is an InputError naming the file, line, column and key at fault.
class SceneLoader {
public:
    // Problems that do not stop the render (a degenerate triangle dropped...) are appended to
    // `warnings`, one line each, already prefixed with their place in the file.
    // `frame` is the frame of the scene's "animation" to load (from 1; frames beyond its last
    // hold its last keyframes); a scene without one is the same at every frame. With a
    // `modelCache`, large OBJ models are taken from it and kept in it.
    static Scene loadFile(const std::filesystem::path& path, std::vector<std::string>& warnings,
                          int frame = 1, const ModelCache* modelCache = nullptr);
    // The same for scene text in memory; `fileName` is used in messages.
    static Scene loadString(const std::string& text, const std::string& fileName,
                            std::vector<std::string>& warnings, int frame = 1,
                            const ModelCache* modelCache = nullptr);

    // What the scene format can name, from the tables the loader reads: the object, light,
    // material, texture, filter and integrator types, each under the key that names them.
    struct Vocabulary {
        std::string what;  // "objects", "lights"...
        std::vector<std::string> names;
    };
    static std::vector<Vocabulary> vocabulary();

private:
    // The reading of one document (the JSON and everything the reading keeps are the .cpp's).
    class Reader;
};

}  // namespace lancer
