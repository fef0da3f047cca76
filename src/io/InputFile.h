#pragma once

#include <cstdint>
#include <filesystem>
#include <string>

#include "scene/InputError.h"

namespace lancer {

// The checks an input file passes before it is read, so that no input grows memory without end:
// a folder or a device (/dev/zero, /dev/urandom) is refused, and a file larger than the limit of
// its kind (docs/SCENE-FORMAT.md, "Limits") is refused by its size before a byte is read.
struct InputFile {
    static constexpr std::uintmax_t kGiB = std::uintmax_t{1} << 30;
    static constexpr std::uintmax_t kMaxSceneBytes = 1 * kGiB;
    static constexpr std::uintmax_t kMaxModelBytes = 4 * kGiB;

    // aKind and kinds name the file in messages: "a scene file", "scene files".
    static void check(const std::filesystem::path& path, const std::string& aKind,
                      const std::string& kinds, std::uintmax_t maxBytes) {
        std::error_code error;
        const std::filesystem::file_status status = std::filesystem::status(path, error);
        if (std::filesystem::is_directory(status))
            throw InputError(path.string(), "is a folder, not " + aKind);
        if (std::filesystem::is_character_file(status) || std::filesystem::is_block_file(status))
            throw InputError(path.string(), "is a device, not " + aKind);
        if (!std::filesystem::is_regular_file(status)) return;  // a pipe: its reader caps it
        if (const std::uintmax_t size = std::filesystem::file_size(path, error);
            !error && size > maxBytes)
            throw tooLarge(path, kinds, maxBytes);
    }

    // The error of a file (or a pipe, found out while reading it) beyond its kind's limit.
    static InputError tooLarge(const std::filesystem::path& path, const std::string& kinds,
                               std::uintmax_t maxBytes) {
        return InputError(path.string(), "is larger than the " + std::to_string(maxBytes / kGiB) +
                                             " GiB limit for " + kinds);
    }
};

}  // namespace lancer
