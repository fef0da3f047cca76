#include "TempFolder.h"

#include <algorithm>
#include <atomic>
#include <fstream>
#include <random>
#include <stdexcept>
#include <system_error>

namespace lancer::test {

TempFolder::TempFolder() {
    // Unique across the processes that ctest runs in parallel and across folders of one process.
    static std::atomic<unsigned> counter{0};
    std::random_device random;
    for (;;) {
        path_ = fs::temp_directory_path() /
                ("lancer-test-" + std::to_string(random()) + "-" + std::to_string(counter++));
        if (fs::create_directory(path_)) return;
    }
}

TempFolder::~TempFolder() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
}

fs::path TempFolder::write(const fs::path& name, const std::string& text) const {
    const fs::path file = path_ / name;
    fs::create_directories(file.parent_path());
    std::ofstream out(file, std::ios::binary);
    out << text;
    if (!out) throw std::runtime_error("cannot write " + file.string());
    return file;
}

std::vector<std::string> TempFolder::entries(const fs::path& subfolder) const {
    std::vector<std::string> names;
    for (const fs::directory_entry& entry : fs::directory_iterator(path_ / subfolder))
        names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
}

}  // namespace lancer::test
