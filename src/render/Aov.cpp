#include "render/Aov.h"

#include <algorithm>
#include <sstream>
#include <stdexcept>

#include "util/DidYouMean.h"

namespace lancer {

namespace {

Color albedoOf(const AovSample& sample) {
    return sample.albedo;
}

Color normalOf(const AovSample& sample) {
    return {sample.normal.x, sample.normal.y, sample.normal.z};
}

Color depthOf(const AovSample& sample) {
    return Color(sample.depth);
}

}  // namespace

const Registry<Aov>& Aov::types() {
    static const Registry<Aov> types{
        {"albedo", &albedoOf},
        {"normal", &normalOf},
        {"depth", &depthOf},
    };
    return types;
}

std::vector<const Aov*> Aov::parseList(const std::string& list) {
    // Each message starts with the list, for the option's name to go before it.
    const std::string quotedList = "\"" + list + "\": ";
    const std::invalid_argument emptyName(
        quotedList + "an empty name; expected names separated by commas from " +
        types().quotedNames());
    // getline would skip the empty name after a trailing comma.
    if (list.empty() || list.back() == ',') throw emptyName;
    std::vector<const Aov*> aovs;
    std::istringstream in(list);
    for (std::string name; std::getline(in, name, ',');) {
        if (name.empty()) throw emptyName;
        const Aov* aov = types().find(name);
        if (!aov)
            throw std::invalid_argument(quotedList + unknownName("output", name, types().names()));
        if (std::find(aovs.begin(), aovs.end(), aov) != aovs.end())
            throw std::invalid_argument(quotedList + "\"" + name + "\" is named twice");
        aovs.push_back(aov);
    }
    return aovs;
}

std::filesystem::path Aov::pathBeside(const std::filesystem::path& output) const {
    std::filesystem::path path = output;
    return path.replace_extension(std::string(".") + name + ".exr");
}

}  // namespace lancer
