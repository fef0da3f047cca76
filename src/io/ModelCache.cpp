#include "io/ModelCache.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "accel/Mesh.h"
#include "io/AtomicFile.h"
#include "io/Fingerprint.h"
#include "io/ObjSupport.h"
#include "util/ByteAppend.h"

namespace lancer {

namespace fs = std::filesystem;

namespace {

constexpr char kMagic[16] = {'l', 'a', 'n', 'c', 'e', 'r', ' ',  'm',
                             'o', 'd', 'e', 'l', ' ', '1', '\n', '\0'};

constexpr const char* kEntryExtension = ".obj-model";

// An entry that cannot be used, for a reason worth a warning.
struct DamagedEntry {
    std::string why;
};

template <typename T>
void appendArray(std::string& bytes, std::span<const T> values) {
    appendBytes(bytes, std::uint64_t{values.size()});
    bytes.append(reinterpret_cast<const char*>(values.data()), values.size_bytes());
}

void appendTexts(std::string& bytes, const std::vector<std::string>& texts) {
    appendBytes(bytes, std::uint64_t{texts.size()});
    for (const std::string& text : texts)
        appendArray(bytes, std::span<const char>(text));
}

// Reads an entry's values straight from its file into their arrays (an entry is most of a
// model's memory: the file is not copied whole first), each length checked against what is
// left of the file, so that no count in a damaged entry asks for more memory than the file holds.
class EntryReader {
public:
    explicit EntryReader(const fs::path& path) : file_(path, std::ios::binary) {
        std::error_code error;
        left_ = fs::file_size(path, error);
        if (!file_ || error) throw DamagedEntry{"cannot be read"};
    }

    template <typename T>
    T read() {
        T value;
        readInto(&value, sizeof(T));
        return value;
    }
    template <typename T>
    std::vector<T> readArray() {
        const auto count = read<std::uint64_t>();
        if (count > left_ / sizeof(T)) throw DamagedEntry{"is truncated"};
        std::vector<T> values(count);
        readInto(values.data(), count * sizeof(T));
        return values;
    }
    std::vector<std::string> readTexts() {
        const auto count = read<std::uint64_t>();
        if (count > left_ / sizeof(std::uint64_t)) throw DamagedEntry{"is truncated"};
        std::vector<std::string> texts(count);  // each with its length first
        for (std::string& text : texts) {
            const auto length = read<std::uint64_t>();
            if (length > left_) throw DamagedEntry{"is truncated"};
            text.resize(length);
            readInto(text.data(), length);
        }
        return texts;
    }
    std::uint64_t left() const { return left_; }

private:
    void readInto(void* values, std::uint64_t size) {
        if (size > left_) throw DamagedEntry{"is truncated"};
        file_.read(static_cast<char*>(values), static_cast<std::streamsize>(size));
        if (!file_) throw DamagedEntry{"cannot be read"};
        left_ -= size;
    }

    std::ifstream file_;
    std::uint64_t left_ = 0;
};

}  // namespace

ModelCache::ModelCache(fs::path folder, std::string programIdentity, std::uintmax_t minimumBytes,
                       std::uintmax_t maximumBytes)
    : folder_(std::move(folder)),
      programIdentity_(std::move(programIdentity)),
      minimumBytes_(minimumBytes),
      maximumBytes_(maximumBytes) {}

std::optional<fs::path> ModelCache::defaultFolder() {
    const auto variable = [](const char* name) -> std::optional<fs::path> {
        const char* value = std::getenv(name);
        if (!value || !*value) return std::nullopt;
        return fs::path(value);
    };
    if (const auto xdg = variable("XDG_CACHE_HOME")) return *xdg / "lancer" / "models";
    if (const auto home = variable("HOME")) return *home / ".cache" / "lancer" / "models";
    if (const auto local = variable("LOCALAPPDATA")) return *local / "lancer" / "models";
    return std::nullopt;
}

bool ModelCache::keeps(const fs::path& modelPath) const {
    std::error_code error;
    const std::uintmax_t size = fs::file_size(modelPath, error);
    return !error && size >= minimumBytes_;
}

fs::path ModelCache::entryPath(const fs::path& modelPath,
                               const std::optional<float>& smooth) const {
    std::error_code error;
    const std::uint64_t name = Fingerprint()
                                   .addText(fs::weakly_canonical(modelPath, error).string())
                                   .addNumber(smooth ? std::bit_cast<std::uint32_t>(*smooth) : ~0u)
                                   .value();
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(name));
    return folder_ / (std::string(hex) + kEntryExtension);
}

std::uint64_t ModelCache::modelFingerprint(const fs::path& modelPath,
                                           const std::optional<float>& smooth,
                                           std::uint64_t modelFile) const {
    return Fingerprint()
        .addText(programIdentity_)
        .addNumber(sizeof(Vec3))
        .addNumber(sizeof(WideBvhNode))
        .addNumber(sizeof(TrianglePack))
        // The path as given, which the warnings kept in the entry name.
        .addText(modelPath.string())
        .addNumber(modelFile)
        .addNumber(smooth ? std::bit_cast<std::uint32_t>(*smooth) : ~0u)
        .value();
}

std::shared_ptr<const Mesh> ModelCache::findObj(const fs::path& objPath,
                                                const std::optional<float>& smooth,
                                                const ObjLoader::TextureLoader& loadTexture,
                                                std::vector<std::string>& warnings,
                                                std::vector<fs::path>& materialFiles) const {
    if (!keeps(objPath)) return nullptr;
    const fs::path entry = entryPath(objPath, smooth);
    std::error_code error;
    if (!fs::is_regular_file(entry, error)) return nullptr;
    try {
        EntryReader reader(entry);
        if (reader.left() < sizeof kMagic ||
            std::memcmp(reader.read<std::array<char, sizeof kMagic>>().data(), kMagic,
                        sizeof kMagic) != 0) {
            warn(warnings, entry,
                 "not a lancer model cache entry; the model is read from its file");
            return nullptr;
        }
        const auto madeFromModel = reader.read<std::uint64_t>();
        ObjCompletion completion;
        completion.libraryNames = reader.readTexts();
        const auto madeFromLibraries = reader.read<std::uint64_t>();
        const ObjLoader::SourceFiles now = ObjLoader::sourceFiles(objPath, completion);
        if (madeFromModel != modelFingerprint(objPath, smooth, now.obj) ||
            madeFromLibraries != now.libraries)
            return nullptr;
        completion.materialSources = reader.readArray<int>();
        completion.warningsBeforeMaterials = reader.readTexts();
        completion.warningsAfterMaterials = reader.readTexts();
        Mesh::Parts parts;
        parts.triangles.positions = reader.readArray<Vec3>();
        parts.triangles.normals = reader.readArray<Vec3>();
        parts.triangles.uvs = reader.readArray<Vec2>();
        parts.triangles.indices = reader.readArray<std::uint32_t>();
        parts.triangles.faceMaterials = reader.readArray<std::uint32_t>();
        parts.bounds = reader.read<Bounds3>();
        parts.nodes = reader.readArray<WideBvhNode>();
        parts.packs = reader.readArray<TrianglePack>();
        if (reader.left() != 0) throw DamagedEntry{"has bytes after its end"};
        // The model's warnings and files count only if the parts make a mesh.
        std::vector<std::string> modelWarnings;
        std::vector<fs::path> modelMaterialFiles;
        parts.triangles.materials = ObjLoader::complete(objPath, completion, loadTexture,
                                                        modelWarnings, &modelMaterialFiles);
        auto mesh = std::make_shared<const Mesh>(std::move(parts));
        warnings.insert(warnings.end(), modelWarnings.begin(), modelWarnings.end());
        materialFiles.insert(materialFiles.end(), modelMaterialFiles.begin(),
                             modelMaterialFiles.end());
        return mesh;
    } catch (const DamagedEntry& damaged) {
        warn(warnings, entry,
             "the model cache entry " + damaged.why + "; the model is read from its file");
    } catch (const std::invalid_argument& misfit) {
        warn(warnings, entry,
             std::string("the model cache entry is damaged (") + misfit.what() +
                 "); the model is read from its file");
    }
    return nullptr;
}

void ModelCache::makeRoomBeside(const fs::path& newest) const {
    struct Entry {
        fs::file_time_type written;
        std::uintmax_t bytes;
        fs::path path;
    };
    std::vector<Entry> others;
    std::error_code error;
    std::uintmax_t total = fs::file_size(newest, error);
    for (const fs::directory_entry& file : fs::directory_iterator(folder_, error)) {
        if (file.path().extension() != kEntryExtension || file.path() == newest) continue;
        Entry entry{file.last_write_time(error), file.file_size(error), file.path()};
        if (error) continue;  // gone meanwhile (another process made room too)
        total += entry.bytes;
        others.push_back(std::move(entry));
    }
    std::sort(others.begin(), others.end(),
              [](const Entry& a, const Entry& b) { return a.written < b.written; });
    for (const Entry& oldest : others) {
        if (total <= maximumBytes_) break;
        if (fs::remove(oldest.path, error)) total -= oldest.bytes;
    }
}

void ModelCache::storeObj(const fs::path& objPath, const std::optional<float>& smooth,
                          const ObjCompletion& completion, const ObjLoader::SourceFiles& sources,
                          const Mesh& mesh, std::vector<std::string>& warnings) const {
    if (!keeps(objPath)) return;
    const TriangleMesh& triangles = mesh.triangles();
    std::string bytes(kMagic, sizeof kMagic);
    // The arrays' bytes, with room for the rest: the entry is built in place, never moved.
    bytes.reserve(mesh.memoryBytes() + (std::size_t{1} << 16));
    appendBytes(bytes, modelFingerprint(objPath, smooth, sources.obj));
    appendTexts(bytes, completion.libraryNames);
    appendBytes(bytes, sources.libraries);
    appendArray(bytes, std::span<const int>(completion.materialSources));
    appendTexts(bytes, completion.warningsBeforeMaterials);
    appendTexts(bytes, completion.warningsAfterMaterials);
    appendArray(bytes, std::span<const Vec3>(triangles.positions));
    appendArray(bytes, std::span<const Vec3>(triangles.normals));
    appendArray(bytes, std::span<const Vec2>(triangles.uvs));
    appendArray(bytes, std::span<const std::uint32_t>(triangles.indices));
    appendArray(bytes, std::span<const std::uint32_t>(triangles.faceMaterials));
    appendBytes(bytes, mesh.bounds());
    appendArray(bytes, mesh.bvhNodes());
    appendArray(bytes, mesh.packs());
    const fs::path entry = entryPath(objPath, smooth);
    try {
        std::error_code error;
        fs::create_directories(folder_, error);
        AtomicFile::write(entry, bytes.data(), bytes.size(), "model cache entry");
        makeRoomBeside(entry);
    } catch (const std::runtime_error& e) {
        warn(warnings, objPath,
             std::string("not kept in the model cache: ") + e.what() +
                 " (--no-model-cache leaves the cache alone)");
    }
}

}  // namespace lancer
