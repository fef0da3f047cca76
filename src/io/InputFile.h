#pragma once

#include <cstdint>
#include <filesystem>
#include <fstream>
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

    // The bytes of a file that passes check(); InputError naming the file if it cannot be read
    // (aKind, kinds as for check(): "a scene file", "scene files").
    static std::string read(const std::filesystem::path& path, const std::string& aKind,
                            const std::string& kinds, std::uintmax_t maxBytes) {
        check(path, aKind, kinds, maxBytes);
        std::ifstream in(path, std::ios::binary);
        // "a scene file" -> "the scene file"
        const std::string theKind = "the " + aKind.substr(aKind.find(' ') + 1);
        if (!in) throw InputError(path.string(), "cannot open " + theKind + " (does it exist?)");
        // Read in blocks, so that a pipe that never ends stops at the limit too; a file's bytes
        // are given its size at once (not up to twice that by doubling).
        std::string bytes;
        std::error_code sizeUnknown;
        if (const std::uintmax_t size = std::filesystem::file_size(path, sizeUnknown); !sizeUnknown)
            bytes.reserve(static_cast<std::size_t>(size));
        std::string block(1 << 16, '\0');
        while (in.read(block.data(), static_cast<std::streamsize>(block.size())) ||
               in.gcount() > 0) {
            bytes.append(block.data(), static_cast<std::size_t>(in.gcount()));
            if (bytes.size() > maxBytes) throw tooLarge(path, kinds, maxBytes);
        }
        return bytes;
    }

    // The error of a file (or a pipe, found out while reading it) beyond its kind's limit.
    static InputError tooLarge(const std::filesystem::path& path, const std::string& kinds,
                               std::uintmax_t maxBytes) {
        // Limits that depend on the image (resume files) may be below a gibibyte.
        const bool gibibytes = maxBytes >= kGiB;
        const std::string limit = gibibytes ? std::to_string(maxBytes / kGiB) + " GiB"
                                            : std::to_string(maxBytes) + " byte";
        return InputError(path.string(), "is larger than the " + limit + " limit for " + kinds);
    }
};

}  // namespace lancer
