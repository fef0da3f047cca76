#pragma once

#include <cstdint>
#include <filesystem>

#include "render/PixelWindow.h"
#include "render/RenderResult.h"

namespace lancer {

// What an interrupted render leaves beside its output for --resume (OUT.resume): the tiles it
// finished, their pixels and auxiliary outputs as the films held them (linear, before exposure),
// and its counts, under the fingerprint of what the image depends on (the program, the scene's
// files, the options). Binary: a header, a flag per tile, the finished tiles' pixels, and a
// checksum of all that, so that a truncated or altered file is refused rather than half-used.
class ResumeFile {
public:
    // OUT.resume, beside OUT.
    static std::filesystem::path pathBeside(const std::filesystem::path& output);

    // Writes the finished tiles of `partial`, a render of `window` (Renderer::tiles(window)),
    // atomically (AtomicFile), so that a resume file is whole or absent. Throws
    // std::runtime_error when it cannot.
    static void write(const std::filesystem::path& path, std::uint64_t fingerprint,
                      const PixelWindow& window, const RenderResult& partial);

    // The partial render `write` saved, for RenderOptions::resumeFrom: films of width x height
    // (black outside the finished tiles), aovCount auxiliary ones. Throws InputError naming the
    // file when it is not a resume file, is damaged, or was made for another render (another
    // fingerprint, image size, window or set of outputs).
    static RenderResult read(const std::filesystem::path& path, std::uint64_t fingerprint,
                             int width, int height, const PixelWindow& window,
                             std::size_t aovCount);

    // No resume file of a width x height image with this many auxiliary outputs is larger: every
    // tile finished.
    static std::uintmax_t maxBytes(int width, int height, std::size_t aovCount);
};

}  // namespace lancer
