#pragma once

// Writes a PFM file as the netpbm definition has it (little-endian, the bottom row first), without
// FreeImage, whose PFM writer stores the top row first: the texture tests' images and the
// environment maps of the end-to-end tests. (Header-only: the suites that include it link the
// core library, whose Image it writes.)

#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "image/Image.h"

namespace lancer::test {

inline void writePfm(const lancer::Image& image, const std::filesystem::path& path) {
    std::ofstream out(path, std::ios::binary);
    out << "PF\n" << image.width() << ' ' << image.height() << "\n-1.0\n";
    for (int y = image.height() - 1; y >= 0; --y)
        for (int x = 0; x < image.width(); ++x) {
            const Color& c = image.at(x, y);
            const float rgb[3] = {c.r, c.g, c.b};
            out.write(reinterpret_cast<const char*>(rgb), sizeof rgb);
        }
    if (!out) throw std::runtime_error("cannot write the test image " + path.string());
}

}  // namespace lancer::test
