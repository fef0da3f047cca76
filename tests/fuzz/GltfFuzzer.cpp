// libFuzzer target: the glTF loader. An input that starts with GLB's magic ("glTF") is written as
// model.glb, any other as model.gltf (JSON), so that the mutations reach both readers, the
// buffers (data URIs, the GLB chunk, files beside the model) and the images tinygltf decodes. A
// model's fault must be an InputError or a warning; anything else is a finding.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "FuzzFolder.h"
#include "io/GltfLoader.h"
#include "scene/InputError.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using lancer::fuzz::FuzzFolder;
    const std::string_view input = lancer::fuzz::asText(data, size);
    const bool binary = input.substr(0, 4) == "glTF";
    const auto model = FuzzFolder::write(binary ? "model.glb" : "model.gltf", input);
    std::vector<std::string> warnings;
    try {
        lancer::GltfLoader::load(model, warnings);
    } catch (const lancer::InputError&) {
    }
    return 0;
}
