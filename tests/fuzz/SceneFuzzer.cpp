// libFuzzer target: the scene loader (JSON with comments, positions, every object, light,
// material and texture type). A scene file's fault must be an InputError (one line, exit status
// 2): any other exception, a crash, a leak or a hang is a finding.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "FuzzFolder.h"
#include "io/SceneLoader.h"
#include "scene/InputError.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::vector<std::string> warnings;
    try {
        // In the fuzz folder, so that the models and textures a scene names are looked up there.
        lancer::SceneLoader::loadString(std::string(lancer::fuzz::asText(data, size)),
                                        (lancer::fuzz::FuzzFolder::path() / "scene.json").string(),
                                        warnings);
    } catch (const lancer::InputError&) {
    }
    return 0;
}
