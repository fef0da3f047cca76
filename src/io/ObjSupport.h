#pragma once

#include <algorithm>
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace lancer {

// What the model loaders (OBJ and its MTL material converter, PLY) share: warnings in the loaders'
// format, names quoted and things counted in messages, and the file names written inside OBJ and
// MTL files.

inline void warn(std::vector<std::string>& warnings, const std::filesystem::path& file,
                 const std::string& message) {
    warnings.push_back(file.string() + ": warning: " + message);
}

inline std::string inQuotes(const std::string& s) {
    return "\"" + s + "\"";
}

// "1 face", "3 faces".
inline std::string countOf(std::size_t count, const std::string& noun) {
    return std::to_string(count) + " " + noun + (count == 1 ? "" : "s");
}

// A file named inside an OBJ or MTL file: relative to that file's folder, and written with
// Windows separators as often as not.
inline std::filesystem::path resolvePath(const std::filesystem::path& folder, std::string name) {
    std::replace(name.begin(), name.end(), '\\', '/');
    const std::filesystem::path path(name);
    return (path.is_absolute() ? path : folder / path).lexically_normal();
}

}  // namespace lancer
