#pragma once

#include <cstddef>
#include <filesystem>
#include <string>

namespace lancer {

// Writes an output file whole or not at all: the bytes go to a new temporary file beside the
// target, with every system call checked and the data synced to the disk, and the temporary file
// is then renamed over the target. A reader (or a crash) never sees half a file.
class AtomicFile {
public:
    // Throws std::runtime_error "PATH: cannot write the WHAT (reason)" when it cannot; no
    // temporary file is left then.
    static void write(const std::filesystem::path& path, const void* data, std::size_t size,
                      const std::string& what);
};

}  // namespace lancer
