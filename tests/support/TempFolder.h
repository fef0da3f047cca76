#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace lancer::test {

namespace fs = std::filesystem;

// A fresh, empty folder under the system's temporary folder, deleted with its contents at the end.
class TempFolder {
public:
    TempFolder();
    ~TempFolder();
    TempFolder(const TempFolder&) = delete;
    TempFolder& operator=(const TempFolder&) = delete;

    const fs::path& path() const { return path_; }
    fs::path operator/(const fs::path& name) const { return path_ / name; }

    // Writes `text` to the file `name` inside the folder and returns its path.
    fs::path write(const fs::path& name, const std::string& text) const;
    // The names of the entries (files and folders, not recursive) of the folder or of one of its
    // subfolders, sorted.
    std::vector<std::string> entries(const fs::path& subfolder = {}) const;

private:
    fs::path path_;
};

}  // namespace lancer::test
