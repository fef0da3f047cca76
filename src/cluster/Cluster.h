#pragma once

#include <functional>
#include <memory>
#include <sstream>
#include <string>

#include "render/RenderOptions.h"
#include "render/RenderResult.h"

namespace lancer {

class Renderer;

// The processes of an MPI run (`mpirun -np N lancer ...`, or Slurm's srun), or this process
// alone: every process loads the scene and renders tiles that the leader (rank 0, which renders
// too) hands out as they are asked for; the workers send their finished tiles back, and the
// leader alone writes the output. The only place lancer calls MPI, so that a build without it
// (or a run without mpirun) is the same program with a cluster of one.
class Cluster {
public:
    // Joins the MPI run this process was started in, as the environment mpirun or srun set says;
    // otherwise, or in a build without MPI, makes a cluster of this process alone. A worker's
    // standard error is held back until settle().
    Cluster(int& argc, char**& argv);
    ~Cluster();
    Cluster(const Cluster&) = delete;
    Cluster& operator=(const Cluster&) = delete;

    int size() const { return size_; }
    bool leader() const { return rank_ == 0; }
    // "with Open MPI 4.1.4" or "without MPI", for lancer --version.
    static std::string describe();

    // Called by every process once it has set up its render, or failed to, with its exit status
    // so far (0: ready). Returns the status every process goes on with: the leader's if it
    // failed, else the first failed worker's. A failure every process shares is reported once,
    // by the leader; a worker's own is printed by the leader from what the worker held back.
    // Only the first call does something: a later one returns the failure it found, if any, or
    // else its own status (that of the work done since).
    int settle(int status);

    // Renders the image of `renderer` with every process (`options.tileQueue` and `onTileDone`
    // are the cluster's). The leader's result holds every finished tile, its counters summed
    // over the processes; `onProgress(tilesDone, tilesTotal)` is called on the leader. A
    // worker's result is of no use. After settle(0).
    RenderResult render(const Renderer& renderer, RenderOptions options, int width, int height,
                        const std::function<void(int, int)>& onProgress);

    // The leader's `value`, in every process: what the leader alone could decide (a frame that
    // --resume skips). Called by every process alike.
    int fromLeader(int value);

    // The leader's exit status, given to every process (mpirun reports the lowest rank's).
    int finish(int status);

private:
    int rank_ = 0;
    int size_ = 1;
    bool joined_ = false;  // MPI was initialised
    std::optional<int> settled_;
    std::ostringstream heldBack_;  // a worker's standard error until settle()
    std::streambuf* standardError_ = nullptr;
};

}  // namespace lancer
