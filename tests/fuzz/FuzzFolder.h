#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string_view>

namespace lancer::fuzz {

// A folder of the process's own, for the fuzz targets whose readers take a path: each input is
// written into it as a file before it is read. Made on first use (in /dev/shm when the machine has
// it, so that the writes cost no disk) and deleted when the process exits.
class FuzzFolder {
public:
    // Writes `bytes` to the file `name` in the folder and returns its path.
    static std::filesystem::path write(const std::string& name, std::string_view bytes);
    static const std::filesystem::path& path();
};

// The bytes of a fuzz input as text.
inline std::string_view asText(const std::uint8_t* data, std::size_t size) {
    return {reinterpret_cast<const char*>(data), size};
}

}  // namespace lancer::fuzz
