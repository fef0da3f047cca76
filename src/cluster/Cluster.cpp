#include "cluster/Cluster.h"

#include <cstdlib>
#include <iostream>
#include <utility>

#include "render/Renderer.h"

#if LANCER_WITH_MPI
#include <mpi.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <deque>
#include <mutex>
#include <thread>
#include <vector>

#include "render/PendingTiles.h"
#endif

namespace lancer {

namespace {

// Whether mpirun (Open MPI, MPICH) or srun started this process as one of a parallel job.
bool startedByMpi() {
    for (const char* variable : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK", "PMI_RANK"})
        if (std::getenv(variable)) return true;
    return false;
}

// The render of one process, its progress reported as the tiles finish.
RenderResult renderAlone(const Renderer& renderer, RenderOptions options,
                         const std::function<void(int, int)>& onProgress) {
    options.onTileDone = [&](const FinishedTile& done) {
        if (onProgress && done.index) onProgress(done.tilesDone, done.tilesTotal);
    };
    return renderer.render(options);
}

}  // namespace

#if LANCER_WITH_MPI

namespace {

// The messages of the tile protocol, by tag.
enum Tag : int {
    kAskForTiles = 1,  // worker -> leader: an int, how many tiles it wants
    kTilesGiven,       // leader -> worker: int64 tile indices, none when no tile is left
    kTileFinished,     // worker -> leader: a uint64 index, then the tile's floats (FinishedTile)
    kWorkerDone,       // worker -> leader: its counters and thread count (kDoneWords uint64)
};
constexpr int kDoneWords = 5;

// Waiting for a message sleeps between polls, from kFirstPause up to kLongestPause: MPI's
// blocking calls spin, and would take a core from the renderer's threads.
constexpr auto kFirstPause = std::chrono::microseconds(200);
constexpr auto kLongestPause = std::chrono::microseconds(1000);
// After a stop is asked for, how long the leader waits for the workers' last tiles: a worker
// killed outright never sends them.
constexpr auto kStopGrace = std::chrono::seconds(3);

class Pause {
public:
    void reset() { pause_ = kFirstPause; }
    void wait() {
        std::this_thread::sleep_for(pause_);
        pause_ = std::min(pause_ * 2,
                          std::chrono::duration_cast<std::chrono::microseconds>(kLongestPause));
    }

private:
    std::chrono::microseconds pause_ = kFirstPause;
};

// Waits for `request` to complete, pausing between tests: a process that is done early (a worker
// waiting for the leader to write the image) leaves the core to the others.
void waitFor(MPI_Request& request) {
    Pause pause;
    for (int done = 0; MPI_Test(&request, &done, MPI_STATUS_IGNORE), !done;)
        pause.wait();
}

// The pixels of a tile, as sent: the image's, then each auxiliary output's, row by row.
std::vector<float> tilePixels(const FinishedTile& done) {
    std::vector<float> floats;
    const auto append = [&](const Image& film) {
        for (int y = done.tile.y0; y < done.tile.y1; ++y)
            for (int x = done.tile.x0; x < done.tile.x1; ++x) {
                const Color& c = film.at(x, y);
                floats.insert(floats.end(), {c.r, c.g, c.b});
            }
    };
    append(done.film);
    for (const Image& aov : done.aovFilms)
        append(aov);
    return floats;
}

// The other side of tilePixels: true when `floats` is exactly the tile's pixels.
bool storeTilePixels(const float* floats, std::size_t count, const PixelWindow& tile,
                     RenderResult& into) {
    const std::size_t perFilm = static_cast<std::size_t>(tile.width() * tile.height()) * 3;
    if (count != perFilm * (1 + into.aovFilms.size())) return false;
    const auto take = [&](Image& film) {
        for (int y = tile.y0; y < tile.y1; ++y)
            for (int x = tile.x0; x < tile.x1; ++x, floats += 3)
                film.at(x, y) = Color(floats[0], floats[1], floats[2]);
    };
    take(into.film);
    for (Image& aov : into.aovFilms)
        take(aov);
    return true;
}

// A worker's tiles, asked of the leader ahead of need (two per thread, asked for when half are
// left) so that a thread seldom waits for the answer; when one had to wait all the same (tiles
// quicker to render than the answer is to come), the next batches are twice as large, up to
// kMostTilesPerThread a thread. Every MPI call of the worker is made under mutex_
// (MPI_THREAD_SERIALIZED).
class TilesFromTheLeader : public TileQueue {
public:
    static constexpr int kMostTilesPerThread = 64;

    TilesFromTheLeader(int threads, const std::atomic<bool>* cancel)
        : threads_(std::max(threads, 1)), batch_(2 * threads_), cancel_(cancel) {}

    std::optional<std::size_t> next() override {
        std::unique_lock lock(mutex_);
        Pause pause;
        bool waited = false;
        while (true) {
            if (cancel_ && cancel_->load(std::memory_order_relaxed)) return std::nullopt;
            receiveAnswer();
            if (!asked_ && !exhausted_ && given_.size() <= static_cast<std::size_t>(batch_ / 2))
                ask();
            if (!given_.empty()) {
                const std::size_t tile = given_.front();
                given_.pop_front();
                return tile;
            }
            if (exhausted_ && !asked_) return std::nullopt;
            if (!waited && answered_) {  // (the first answer is always waited for)
                waited = true;
                batch_ = std::min(2 * batch_, kMostTilesPerThread * threads_);
            }
            lock.unlock();
            pause.wait();
            lock.lock();
        }
    }

    // Sends a finished tile without waiting for the leader to take it: a blocking send spun in
    // MPI's progress loop until the leader's server thread woke (6.5% of a worker's time).
    void send(const FinishedTile& done) {
        std::vector<float> floats = tilePixels(done);
        std::vector<unsigned char> bytes(sizeof(std::uint64_t) + floats.size() * sizeof(float));
        const std::uint64_t index = *done.index;
        std::memcpy(bytes.data(), &index, sizeof index);
        std::memcpy(bytes.data() + sizeof index, floats.data(), floats.size() * sizeof(float));
        std::lock_guard lock(mutex_);
        forgetSentTiles();
        TileInFlight& tile = inFlight_.emplace_back(TileInFlight{std::move(bytes), {}});
        MPI_Isend(tile.bytes.data(), static_cast<int>(tile.bytes.size()), MPI_BYTE, 0,
                  kTileFinished, MPI_COMM_WORLD, &tile.request);
    }

    void sendDone(const RenderResult& result) {
        std::lock_guard lock(mutex_);
        // An answer still on its way is taken, so that no message is left unread, and every tile
        // is sent before the message that says there are no more.
        while (asked_) {
            receiveAnswer();
            if (asked_) std::this_thread::sleep_for(kFirstPause);
        }
        for (TileInFlight& tile : inFlight_)
            waitFor(tile.request);
        inFlight_.clear();
        const RenderCounters& c = result.counters;
        const std::uint64_t words[kDoneWords] = {c.rays, c.samples, c.pixels, c.nonFiniteSamples,
                                                 static_cast<std::uint64_t>(result.threads)};
        MPI_Send(words, kDoneWords, MPI_UINT64_T, 0, kWorkerDone, MPI_COMM_WORLD);
    }

private:
    void ask() {
        MPI_Send(&batch_, 1, MPI_INT, 0, kAskForTiles, MPI_COMM_WORLD);
        answer_.assign(static_cast<std::size_t>(batch_), 0);
        MPI_Irecv(answer_.data(), batch_, MPI_INT64_T, 0, kTilesGiven, MPI_COMM_WORLD, &request_);
        asked_ = true;
    }

    // Drops the tiles the leader has taken, oldest first.
    void forgetSentTiles() {
        while (!inFlight_.empty()) {
            int sent = 0;
            MPI_Test(&inFlight_.front().request, &sent, MPI_STATUS_IGNORE);
            if (!sent) return;
            inFlight_.pop_front();
        }
    }

    void receiveAnswer() {
        if (!asked_) return;
        int arrived = 0;
        MPI_Status status;
        MPI_Test(&request_, &arrived, &status);
        if (!arrived) return;
        asked_ = false;
        answered_ = true;
        int count = 0;
        MPI_Get_count(&status, MPI_INT64_T, &count);
        if (count == 0) exhausted_ = true;
        for (int i = 0; i < count; ++i)
            given_.push_back(static_cast<std::size_t>(answer_[static_cast<std::size_t>(i)]));
    }

    // A finished tile being sent: its bytes stay until the send completes.
    struct TileInFlight {
        std::vector<unsigned char> bytes;
        MPI_Request request;
    };

    const int threads_;
    int batch_;  // the tiles asked for at once
    const std::atomic<bool>* cancel_;
    std::mutex mutex_;
    std::deque<std::size_t> given_;
    std::deque<TileInFlight> inFlight_;
    std::vector<std::int64_t> answer_;
    MPI_Request request_ = MPI_REQUEST_NULL;
    bool asked_ = false;
    bool answered_ = false;
    bool exhausted_ = false;
};

// The leader's side of the protocol, on a thread of its own while the leader renders: hands out
// the tiles of `queue` (which the leader's threads draw from too) and keeps the tiles the workers
// send in `remote`, until every worker is done. Only this thread calls MPI meanwhile.
class TileServer {
public:
    TileServer(int workers, TileQueue& queue, const std::vector<PixelWindow>& tiles,
               RenderResult& remote, const std::atomic<bool>* cancel,
               const std::function<void()>& onTileArrived)
        : workers_(workers),
          queue_(queue),
          tiles_(tiles),
          remote_(remote),
          cancel_(cancel),
          onTileArrived_(onTileArrived) {}

    // Until every worker has said it is done, or a while after a stop was asked for. The workers'
    // counters and threads are added to `remote`'s.
    void serve() {
        Pause pause;
        std::optional<std::chrono::steady_clock::time_point> stopAsked;
        for (int done = 0; done < workers_;) {
            const bool stopping = cancel_ && cancel_->load(std::memory_order_relaxed);
            if (stopping && !stopAsked) stopAsked = std::chrono::steady_clock::now();
            if (stopAsked && std::chrono::steady_clock::now() - *stopAsked > kStopGrace) break;
            int arrived = 0;
            MPI_Status status;
            MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &arrived, &status);
            if (!arrived) {
                pause.wait();
                continue;
            }
            pause.reset();
            if (status.MPI_TAG == kAskForTiles) {
                int wanted = 0;
                MPI_Recv(&wanted, 1, MPI_INT, status.MPI_SOURCE, kAskForTiles, MPI_COMM_WORLD,
                         MPI_STATUS_IGNORE);
                std::vector<std::int64_t> given;
                while (!stopping && static_cast<int>(given.size()) < wanted)
                    if (const std::optional<std::size_t> t = queue_.next())
                        given.push_back(static_cast<std::int64_t>(*t));
                    else
                        break;
                MPI_Send(given.data(), static_cast<int>(given.size()), MPI_INT64_T,
                         status.MPI_SOURCE, kTilesGiven, MPI_COMM_WORLD);
            } else if (status.MPI_TAG == kTileFinished) {
                receiveTile(status);
            } else {
                std::uint64_t words[kDoneWords];
                MPI_Recv(words, kDoneWords, MPI_UINT64_T, status.MPI_SOURCE, kWorkerDone,
                         MPI_COMM_WORLD, MPI_STATUS_IGNORE);
                remote_.counters += RenderCounters{words[0], words[1], words[2], words[3]};
                remote_.threads += static_cast<int>(words[4]);
                ++done;
            }
        }
    }

private:
    void receiveTile(const MPI_Status& status) {
        int byteCount = 0;
        MPI_Get_count(&status, MPI_BYTE, &byteCount);
        std::vector<unsigned char> bytes(static_cast<std::size_t>(byteCount));
        MPI_Recv(bytes.data(), byteCount, MPI_BYTE, status.MPI_SOURCE, kTileFinished,
                 MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        std::uint64_t index = 0;
        if (bytes.size() < sizeof index) return;
        std::memcpy(&index, bytes.data(), sizeof index);
        if (index >= tiles_.size()) return;
        std::vector<float> floats((bytes.size() - sizeof index) / sizeof(float));
        std::memcpy(floats.data(), bytes.data() + sizeof index, floats.size() * sizeof(float));
        if (!storeTilePixels(floats.data(), floats.size(), tiles_[index], remote_)) return;
        remote_.finishedTiles[index] = true;
        onTileArrived_();
    }

    const int workers_;
    TileQueue& queue_;
    const std::vector<PixelWindow>& tiles_;
    RenderResult& remote_;
    const std::atomic<bool>* cancel_;
    const std::function<void()>& onTileArrived_;
};

}  // namespace

Cluster::Cluster(int& argc, char**& argv) {
    if (!startedByMpi()) return;
    int provided = 0;
    MPI_Init_thread(&argc, &argv, MPI_THREAD_SERIALIZED, &provided);
    joined_ = true;
    if (provided < MPI_THREAD_SERIALIZED) {
        std::cerr << "lancer: error: this MPI library cannot be called from more than one thread "
                     "(MPI_THREAD_SERIALIZED)\n";
        MPI_Abort(MPI_COMM_WORLD, 1);
    }
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
    if (!leader()) standardError_ = std::cerr.rdbuf(heldBack_.rdbuf());
}

Cluster::~Cluster() {
    if (standardError_) std::cerr.rdbuf(standardError_);
    if (joined_) MPI_Finalize();
}

std::string Cluster::describe() {
    char version[MPI_MAX_LIBRARY_VERSION_STRING];
    int length = 0;
    MPI_Get_library_version(version, &length);
    std::string text(version, static_cast<std::size_t>(length));
    // "Open MPI v4.1.4, package: ...": the first part.
    text = text.substr(0, text.find(','));
    while (!text.empty() && (text.back() == '\n' || text.back() == ' '))
        text.pop_back();
    return "with " + text;
}

int Cluster::settle(int status) {
    if (settled_) return *settled_ != 0 ? *settled_ : status;
    if (size_ == 1) return *(settled_ = status);
    std::vector<int> statuses(static_cast<std::size_t>(size_));
    MPI_Request gathered;
    MPI_Iallgather(&status, 1, MPI_INT, statuses.data(), 1, MPI_INT, MPI_COMM_WORLD, &gathered);
    waitFor(gathered);
    const auto failed = std::find_if(statuses.begin(), statuses.end(), [](int s) { return s; });
    const int agreed = failed == statuses.end() ? 0 : *failed;
    // The first failed worker's message, when the leader did not fail: the leader prints it.
    const int reporter = statuses[0] == 0 && failed != statuses.end()
                             ? static_cast<int>(failed - statuses.begin())
                             : 0;
    if (reporter != 0) {
        if (rank_ == reporter) {
            const std::string text = heldBack_.str();
            MPI_Send(text.data(), static_cast<int>(text.size()), MPI_CHAR, 0, 0, MPI_COMM_WORLD);
        } else if (leader()) {
            MPI_Status probe;
            MPI_Probe(reporter, 0, MPI_COMM_WORLD, &probe);
            int length = 0;
            MPI_Get_count(&probe, MPI_CHAR, &length);
            std::string text(static_cast<std::size_t>(length), '\0');
            MPI_Recv(text.data(), length, MPI_CHAR, reporter, 0, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
            std::cerr << text << std::flush;
        }
    }
    if (standardError_) {
        std::cerr.rdbuf(standardError_);
        standardError_ = nullptr;
    }
    return *(settled_ = agreed);
}

RenderResult Cluster::render(const Renderer& renderer, RenderOptions options, int width, int height,
                             const std::function<void(int, int)>& onProgress) {
    if (size_ == 1) return renderAlone(renderer, std::move(options), onProgress);
    const auto start = std::chrono::steady_clock::now();
    const PixelWindow window = options.crop.value_or(PixelWindow{0, 0, width, height});
    const std::vector<PixelWindow> tiles = Renderer::tiles(window);
    const int tilesTotal = static_cast<int>(tiles.size());
    if (!leader()) {
        TilesFromTheLeader fromTheLeader(
            options.threads > 0 ? options.threads
                                : static_cast<int>(std::thread::hardware_concurrency()),
            options.cancel);
        options.tileQueue = &fromTheLeader;
        options.onTileDone = [&](const FinishedTile& done) {
            if (done.index) fromTheLeader.send(done);
        };
        const RenderResult result = renderer.render(options);
        fromTheLeader.sendDone(result);
        return result;
    }

    // The workers' tiles, kept apart until the leader's render ends.
    RenderResult remote{Image(width, height)};
    remote.aovFilms.assign(options.aovs.size(), Image(width, height));
    remote.finishedTiles.assign(tiles.size(), false);
    PendingTiles queue(options.resumeFrom ? options.resumeFrom->finishedTiles
                                          : std::vector<bool>(tiles.size(), false));
    std::mutex progressMutex;
    int tilesDone = 0;
    const std::function<void()> countTile = [&] {
        std::lock_guard lock(progressMutex);
        if (onProgress) onProgress(++tilesDone, tilesTotal);
    };
    options.tileQueue = &queue;
    options.onTileDone = [&](const FinishedTile& done) {
        if (done.index) countTile();
    };
    TileServer server(size_ - 1, queue, tiles, remote, options.cancel, countTile);
    std::thread serving([&] { server.serve(); });
    RenderResult result = renderer.render(options);
    serving.join();

    for (std::size_t t = 0; t < tiles.size(); ++t) {
        if (!remote.finishedTiles[t]) continue;
        const PixelWindow& tile = tiles[t];
        for (int y = tile.y0; y < tile.y1; ++y)
            for (int x = tile.x0; x < tile.x1; ++x) {
                result.film.at(x, y) = remote.film.at(x, y);
                for (std::size_t i = 0; i < result.aovFilms.size(); ++i)
                    result.aovFilms[i].at(x, y) = remote.aovFilms[i].at(x, y);
            }
        result.finishedTiles[t] = true;
    }
    result.interrupted = std::find(result.finishedTiles.begin(), result.finishedTiles.end(),
                                   false) != result.finishedTiles.end();
    result.counters += remote.counters;
    result.threads += remote.threads;
    result.processes = size_;
    result.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

int Cluster::fromLeader(int value) {
    if (size_ > 1) {
        MPI_Request given;
        MPI_Ibcast(&value, 1, MPI_INT, 0, MPI_COMM_WORLD, &given);
        waitFor(given);
    }
    return value;
}

int Cluster::finish(int status) {
    return fromLeader(status);
}

#else  // a build without MPI: always a cluster of one

Cluster::Cluster(int&, char**&) {
    if (startedByMpi())
        std::cerr << "lancer: warning: started by mpirun, but this lancer was built without MPI: "
                     "every process renders the whole image alone\n";
}

Cluster::~Cluster() = default;

std::string Cluster::describe() {
    return "without MPI";
}

int Cluster::settle(int status) {
    if (settled_) return *settled_ != 0 ? *settled_ : status;
    return *(settled_ = status);
}

RenderResult Cluster::render(const Renderer& renderer, RenderOptions options, int, int,
                             const std::function<void(int, int)>& onProgress) {
    return renderAlone(renderer, std::move(options), onProgress);
}

int Cluster::fromLeader(int value) {
    return value;
}

int Cluster::finish(int status) {
    return status;
}

#endif

}  // namespace lancer
