// libFuzzer target: the PLY loader (its header and body readers). Each
// input is written as model.ply, ASCII or binary as its header says. A model's fault must be an
// InputError or a warning; anything else is a finding.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "FuzzFolder.h"
#include "io/PlyLoader.h"
#include "scene/InputError.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using lancer::fuzz::FuzzFolder;
    const auto model = FuzzFolder::write("model.ply", lancer::fuzz::asText(data, size));
    std::vector<std::string> warnings;
    try {
        lancer::PlyLoader::load(model, warnings);
    } catch (const lancer::InputError&) {
    }
    return 0;
}
