#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "io/ObjCompletion.h"
#include "io/ObjLoader.h"

namespace lancer {

class Mesh;

// Keeps large models, once read and built, in files of their own, so that the next render of a
// model (the next frame of an animation, the other processes of a cluster on the same disk)
// reads its triangles and its BVH back instead of parsing the model and building the tree again.
//
// A model's entry is one file in the cache's folder, named after the model's path and smoothing
// angle, so that a model changed overwrites its entry. The entry holds what it was made from:
// the program's identity, the model file's path, size and time of change, and those of the MTL
// files it read. It is used only while they are all the same; otherwise it is read again and
// kept anew. An entry that cannot be used (damaged, or of another build) is never an error: the
// model is read from its file, with a warning when the entry was damaged.
//
// OBJ models only (their text parse is most of their load), of at least `minimumBytes`. The
// folder's entries are kept under `maximumBytes` in all: once an entry written takes them past
// it, the entries written longest ago are deleted.
class ModelCache {
public:
    static constexpr std::uintmax_t kDefaultMinimumBytes = std::uintmax_t{8} << 20;
    static constexpr std::uintmax_t kDefaultMaximumBytes = std::uintmax_t{4} << 30;

    // `programIdentity`: what tells this build's entries from another's (the mesh's layout and
    // tree may differ between builds).
    ModelCache(std::filesystem::path folder, std::string programIdentity,
               std::uintmax_t minimumBytes = kDefaultMinimumBytes,
               std::uintmax_t maximumBytes = kDefaultMaximumBytes);

    // The user's cache folder for models: $XDG_CACHE_HOME/lancer/models, else
    // ~/.cache/lancer/models ($HOME), else %LOCALAPPDATA%\lancer\models; nothing when none is set.
    static std::optional<std::filesystem::path> defaultFolder();

    // The OBJ model at `objPath`, smoothed by `smooth` degrees, made from its entry: its
    // materials made again by ObjLoader::complete (which adds the reading's warnings and the MTL
    // files read, as ObjLoader::load does). Null when there is no entry for the files as they
    // are now.
    std::shared_ptr<const Mesh> findObj(const std::filesystem::path& objPath,
                                        const std::optional<float>& smooth,
                                        const ObjLoader::TextureLoader& loadTexture,
                                        std::vector<std::string>& warnings,
                                        std::vector<std::filesystem::path>& materialFiles) const;
    // Keeps `mesh`, built from the OBJ model at `objPath` (ObjLoader::readGeometry's result,
    // smoothed by `smooth` degrees) and completed by `completion`, read from the files as
    // `sources` found them before reading them (so that an entry never passes for files that
    // changed while they were read). A failure to write the entry adds a warning and leaves no
    // file.
    void storeObj(const std::filesystem::path& objPath, const std::optional<float>& smooth,
                  const ObjCompletion& completion, const ObjLoader::SourceFiles& sources,
                  const Mesh& mesh, std::vector<std::string>& warnings) const;

private:
    bool keeps(const std::filesystem::path& modelPath) const;
    // Deletes the entries written longest ago, but not `newest`, until the rest fit in
    // maximumBytes.
    void makeRoomBeside(const std::filesystem::path& newest) const;
    std::filesystem::path entryPath(const std::filesystem::path& modelPath,
                                    const std::optional<float>& smooth) const;
    // What the entry of a model must have been made from, besides its MTL files: this build,
    // the smoothing, and the model's file (its Fingerprint::addFile).
    std::uint64_t modelFingerprint(const std::filesystem::path& modelPath,
                                   const std::optional<float>& smooth,
                                   std::uint64_t modelFile) const;

    std::filesystem::path folder_;
    std::string programIdentity_;
    std::uintmax_t minimumBytes_;
    std::uintmax_t maximumBytes_;
};

}  // namespace lancer
