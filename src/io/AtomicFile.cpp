#include "io/AtomicFile.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <stdexcept>
#include <system_error>

namespace lancer {

namespace {

std::string systemError() {
    return std::strerror(errno);
}

// Writes `size` bytes to a new file at `path` and makes sure they reached the disk: every system
// call is checked (FreeImage's own file output ignores a full disk for most formats). Returns
// an empty string, or why it failed; a file it created is then removed.
std::string writeNewFile(const std::filesystem::path& path, const char* data, std::size_t size) {
    const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd < 0) return systemError();
    std::string failure;
    for (std::size_t written = 0; written < size && failure.empty();) {
        const ssize_t n = ::write(fd, data + written, size - written);
        if (n > 0)
            written += static_cast<std::size_t>(n);
        else if (n < 0 && errno != EINTR)
            failure = systemError();
        else if (n == 0)
            failure = "nothing could be written";
    }
    if (failure.empty() && ::fsync(fd) != 0) failure = systemError();
    if (::close(fd) != 0 && failure.empty()) failure = systemError();
    if (!failure.empty()) ::unlink(path.c_str());
    return failure;
}

}  // namespace

void AtomicFile::write(const std::filesystem::path& path, const void* data, std::size_t size,
                       const std::string& what) {
    const auto fail = [&](const std::string& reason) {
        throw std::runtime_error(path.string() + ": cannot write the " + what + " (" + reason +
                                 ")");
    };
    // A unique name beside the target, so that the final rename stays within one file system.
    const auto stamp = std::chrono::steady_clock::now().time_since_epoch().count();
    std::filesystem::path temporary = path;
    temporary += ".tmp" + std::to_string(stamp);
    const std::string failure = writeNewFile(temporary, static_cast<const char*>(data), size);
    if (!failure.empty()) fail(failure);
    std::error_code error;
    std::filesystem::rename(temporary, path, error);
    if (error) {
        // Not into `error`, whose reason the message gives.
        std::error_code ignored;
        std::filesystem::remove(temporary, ignored);
        fail(error.message());
    }
}

}  // namespace lancer
