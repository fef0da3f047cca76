// libFuzzer target: the loader of saved radiosity solutions (--load-radiosity). A damaged file
// must be an InputError; anything else is a finding.

#include <cstddef>
#include <cstdint>

#include "FuzzFolder.h"
#include "radiosity/RadiositySolution.h"
#include "scene/InputError.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const auto path =
        lancer::fuzz::FuzzFolder::write("solution.rad", lancer::fuzz::asText(data, size));
    try {
        lancer::RadiositySolution::load(path);
    } catch (const lancer::InputError&) {
    }
    return 0;
}
