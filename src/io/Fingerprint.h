#pragma once

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string_view>

#include "sampling/Sampling.h"

namespace lancer {

// A 64-bit hash built up from numbers, texts, bytes and files: what a saved state (a resume file)
// was made from, to refuse the state once that has changed. Not cryptographic: it tells honest
// changes apart.
class Fingerprint {
public:
    Fingerprint& addNumber(std::uint64_t v) {
        hash_ = extendHash(hash_, v);
        return *this;
    }
    Fingerprint& addText(std::string_view bytes) {
        addNumber(bytes.size());
        std::size_t i = 0;
        for (; i + 8 <= bytes.size(); i += 8) {
            std::uint64_t word;
            std::memcpy(&word, bytes.data() + i, 8);
            addNumber(word);
        }
        std::uint64_t last = 0;
        if (i < bytes.size()) std::memcpy(&last, bytes.data() + i, bytes.size() - i);
        return addNumber(last);
    }
    // A file by its path, size and time of last change, as make judges files, not by its bytes
    // (a model of gigabytes is not read again): a file rewritten with the same content counts as
    // changed. A file that cannot be examined counts by its path alone.
    Fingerprint& addFile(const std::filesystem::path& path) {
        std::error_code error;
        addText(std::filesystem::weakly_canonical(path, error).string());
        const std::uintmax_t size = std::filesystem::file_size(path, error);
        addNumber(error ? 0 : size);
        const auto changed = std::filesystem::last_write_time(path, error);
        return addNumber(error ? 0
                               : static_cast<std::uint64_t>(changed.time_since_epoch().count()));
    }

    std::uint64_t value() const { return hash_; }

private:
    std::uint64_t hash_ = beginHash(0x6c616e636572);  // "lancer"
};

}  // namespace lancer
