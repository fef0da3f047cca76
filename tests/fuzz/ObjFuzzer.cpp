// libFuzzer target: the OBJ loader and the MTL converter. The input is the OBJ file; the text
// after a line "#--- model.mtl", if any, is its material library model.mtl (so that one input
// holds both, and the mutations reach either). A model's fault must be an InputError or a
// warning; anything else is a finding.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "FuzzFolder.h"
#include "io/ObjLoader.h"
#include "materials/ConstantTexture.h"
#include "scene/InputError.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using lancer::fuzz::FuzzFolder;
    const std::string_view input = lancer::fuzz::asText(data, size);
    constexpr std::string_view kSeparator = "#--- model.mtl\n";
    const std::size_t separator = input.find(kSeparator);
    FuzzFolder::write("model.mtl", separator == std::string_view::npos
                                       ? std::string_view{}
                                       : input.substr(separator + kSeparator.size()));
    const auto obj = FuzzFolder::write("model.obj", input.substr(0, separator));
    // Textures are the image reader's target: any name gives a constant one here.
    const auto anyTexture = [](const std::filesystem::path&) {
        return std::shared_ptr<const lancer::Texture>(
            std::make_shared<lancer::ConstantTexture>(lancer::Color(0.5f)));
    };
    std::vector<std::string> warnings;
    try {
        lancer::ObjLoader::load(obj, anyTexture, warnings);
    } catch (const lancer::InputError&) {
    }
    return 0;
}
