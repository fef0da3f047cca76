// libFuzzer target: the image reader (FreeImage behind our checks of the declared size). The file
// is named image.tga, as TGA is the one format known only by its extension; the others are
// recognised from their contents. A bad image must be an InputError; anything else, or memory
// beyond what the documented limits allow, is a finding.

#include <cstddef>
#include <cstdint>

#include "FuzzFolder.h"
#include "io/ImageReader.h"
#include "scene/InputError.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const auto path =
        lancer::fuzz::FuzzFolder::write("image.tga", lancer::fuzz::asText(data, size));
    try {
        lancer::ImageReader::read(path);
    } catch (const lancer::InputError&) {
    }
    return 0;
}
