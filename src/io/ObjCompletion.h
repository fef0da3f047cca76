#pragma once

#include <string>
#include <vector>

namespace lancer {

// What turns an OBJ model's triangles, once read (or found in the model cache), into the model:
// its materials, made again from the MTL files, and the warnings its reading gave, in their order.
struct ObjCompletion {
    std::vector<std::string> libraryNames;  // the mtllib names tinyobjloader tried, in order
    // Per material of the mesh: its index among the materials the libraries define, in their
    // order; -1 for the default grey material.
    std::vector<int> materialSources;
    std::vector<std::string> warningsBeforeMaterials, warningsAfterMaterials;
};

}  // namespace lancer
