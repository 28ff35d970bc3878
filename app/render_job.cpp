#include "render_job.h"

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <new>
#include <optional>
#include <span>
#include <vector>

#include "util/error.h"

#if STRATA_WITH_MPI
#include <mpi.h>
#endif

namespace strata {

#if STRATA_WITH_MPI
namespace {

// Open MPI's mpirun sets OMPI_COMM_WORLD_SIZE; PMIx and PMI launchers (srun) set PMIX_RANK or
// PMI_RANK. Started any other way the program is one process and never initialises MPI, so a
// plain `strata render` is the same program as in a build without MPI.
bool launchedByMpi() {
    return std::getenv("OMPI_COMM_WORLD_SIZE") || std::getenv("PMIX_RANK") ||
           std::getenv("PMI_RANK");
}

// MPI counts are ints; larger arrays go in pieces.
constexpr size_t kMaxChunk = size_t{1} << 30;

template <typename T, typename Call>
void forChunks(std::span<T> data, Call call) {
    for (size_t offset = 0; offset < data.size(); offset += kMaxChunk) {
        call(data.data() + offset, static_cast<int>(std::min(kMaxChunk, data.size() - offset)));
    }
}

void broadcast(std::string& text) {
    uint64_t size = text.size();
    MPI_Bcast(&size, 1, MPI_UINT64_T, 0, MPI_COMM_WORLD);
    text.resize(size);
    forChunks(std::span<char>(text), [](char* data, int count) {
        MPI_Bcast(data, count, MPI_CHAR, 0, MPI_COMM_WORLD);
    });
}

void broadcast(std::filesystem::path& path) {
    std::string text = path.string();
    broadcast(text);
    path = text;
}

void broadcast(SceneFile& file) {
    broadcast(file.name);
    broadcast(file.bytes);
}

void broadcast(std::vector<SceneFile>& files) {
    uint64_t count = files.size();
    MPI_Bcast(&count, 1, MPI_UINT64_T, 0, MPI_COMM_WORLD);
    files.resize(count);
    for (SceneFile& file : files) broadcast(file);
}

void broadcast(std::optional<SceneFile>& file) {
    uint8_t present = file ? 1 : 0;
    MPI_Bcast(&present, 1, MPI_UINT8_T, 0, MPI_COMM_WORLD);
    if (!present) return;
    if (!file) file.emplace();
    broadcast(*file);
}

// Adds every rank's `data` into rank 0's, element-wise.
template <typename T>
void reduceToRoot(std::span<T> data, MPI_Datatype type, bool root) {
    forChunks(data, [&](T* chunk, int count) {
        MPI_Reduce(root ? MPI_IN_PLACE : chunk, chunk, count, type, MPI_SUM, 0, MPI_COMM_WORLD);
    });
}

// The exit status main gives `failure` (usage.h).
int exitStatusOf(std::exception_ptr failure) {
    try {
        std::rethrow_exception(failure);
    } catch (const UsageError&) {
        return kUsageExitStatus;
    } catch (...) {
        return kInputExitStatus;
    }
}

std::string messageOf(std::exception_ptr failure) {
    try {
        std::rethrow_exception(failure);
    } catch (const std::exception& e) {
        return e.what();
    } catch (...) {
        return "unknown failure";
    }
}

}  // namespace
#else
namespace {

// The number of processes an MPI launcher started along with this one: Open MPI's mpirun sets
// OMPI_COMM_WORLD_SIZE, MPICH's mpiexec and Slurm's PMI PMI_SIZE. 1 when started otherwise.
int launchedProcesses() {
    for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"}) {
        if (const char* value = std::getenv(name)) return std::atoi(value);
    }
    return 1;
}

// This process's place among them, so that only the first one says why they all stop.
bool firstLaunched() {
    for (const char* name : {"OMPI_COMM_WORLD_RANK", "PMI_RANK"}) {
        if (const char* value = std::getenv(name)) return std::atoi(value) == 0;
    }
    return true;
}

}  // namespace
#endif

RenderJob::RenderJob() {
#if STRATA_WITH_MPI
    if (!launchedByMpi()) return;
    // Only the main thread calls MPI; the TBB workers never do.
    int provided = 0;
    MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
    mpi_ = true;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &ranks_);
#else
    // Each process would render the whole image alone and they would all write the same files.
    const int processes = launchedProcesses();
    if (processes <= 1) return;
    if (!firstLaunched()) throw ErrorReportedByRankZero{};
    throw Error("this strata was built without MPI (STRATA_WITH_MPI=OFF) but was started by "
                "mpirun with " + std::to_string(processes) +
                " processes; rebuild with libopenmpi-dev installed, or run it without mpirun");
#endif
}

RenderJob::~RenderJob() {
#if STRATA_WITH_MPI
    if (mpi_) MPI_Finalize();
#endif
}

void RenderJob::settle(std::exception_ptr failure) {
    if (!mpi_) {
        if (failure) std::rethrow_exception(failure);
        return;
    }
#if STRATA_WITH_MPI
    // The lowest failing rank and its failure's exit status (MINLOC keeps the status of the
    // lowest rank), which rank 0 reports and exits with.
    struct {
        int rank;
        int exitStatus;
    } first{failure ? rank_ : ranks_, failure ? exitStatusOf(failure) : 0};
    MPI_Allreduce(MPI_IN_PLACE, &first, 1, MPI_2INT, MPI_MINLOC, MPI_COMM_WORLD);
    if (first.rank == ranks_) return;
    constexpr int kMessageTag = 1;
    if (first.rank == rank_ && !isRoot()) {
        const std::string message = messageOf(failure);
        MPI_Send(message.data(), static_cast<int>(message.size()), MPI_CHAR, 0, kMessageTag,
                 MPI_COMM_WORLD);
    }
    if (!isRoot()) throw ErrorReportedByRankZero{};
    if (first.rank == 0) std::rethrow_exception(failure);
    MPI_Status status;
    MPI_Probe(first.rank, kMessageTag, MPI_COMM_WORLD, &status);
    int size = 0;
    MPI_Get_count(&status, MPI_CHAR, &size);
    std::string message(static_cast<size_t>(size), '\0');
    MPI_Recv(message.data(), size, MPI_CHAR, first.rank, kMessageTag, MPI_COMM_WORLD,
             MPI_STATUS_IGNORE);
    message = "rank " + std::to_string(first.rank) + " of " + std::to_string(ranks_) + ": " + message;
    if (first.exitStatus == kUsageExitStatus) throw UsageError(message);
    throw Error(message);
#endif
}

SceneBundle RenderJob::shareSceneBundle(const std::function<SceneBundle()>& read) {
    if (!mpi_) return read();
    SceneBundle bundle;
#if STRATA_WITH_MPI
    collectively([&] {
        if (isRoot()) bundle = read();
    });
    broadcast(bundle.path);
    broadcast(bundle.files);
    broadcast(bundle.description);
    broadcast(bundle.camera);
    broadcast(bundle.environmentMap);
#endif
    return bundle;
}

// Bit-identity with the single-process image is not arranged, and cannot be without shipping
// every pass's values: one process adds a pixel's samples left to right over all passes, while
// here each rank sums its own block of passes and MPI_SUM then adds the ranks' sums in an order
// the MPI standard leaves to the implementation (a tree, for Open MPI's larger jobs). The counts
// are integers and add exactly. Each double is a sum of n = spp values (fewer for the pass
// statistics); any two orders of summing n non-negative values lie within gamma_{n-1} =
// (n-1)u/(1-(n-1)u), u = 2^-53, of the exact sum relative to it (Higham, Accuracy and Stability
// of Numerical Algorithms, 2nd ed., §4.2), hence within 2*gamma_{n-1} of each other: 5.3e-14 at
// 240 spp. Strata's radiance is non-negative (Kd, Ke >= 0 are enforced; only a point light given
// a negative intensity would break this, and make the bound relative to the sum of magnitudes
// instead), so after the division by n and the rounding to float an output pixel channel equals
// the single-process one or is the adjacent float (2^-23 relative), when the double lies next to
// a rounding boundary. tests/app/test_mpi_render.cpp checks that bound against the single-process
// render, tests/film/test_accumulation_buffer.cpp the double-level bound for combined buffers.
void RenderJob::reduce([[maybe_unused]] AccumulationBuffer& buffer,
                       [[maybe_unused]] RenderCounters& counters) {
    if (!mpi_) return;
#if STRATA_WITH_MPI
    for (const auto array : buffer.realArrays()) reduceToRoot(array, MPI_DOUBLE, isRoot());
    for (const auto array : buffer.countArrays()) reduceToRoot(array, MPI_UINT32_T, isRoot());
    uint64_t totals[2] = {counters.paths, counters.rays};
    reduceToRoot(std::span<uint64_t>(totals), MPI_UINT64_T, isRoot());
    counters = {totals[0], totals[1]};
#endif
}

// Rank 0's PassTally, as two uint64 (passes, paths) in an MPI window; the other ranks expose none.
struct JobProgress::Window {
#if STRATA_WITH_MPI
    MPI_Win handle = MPI_WIN_NULL;
#endif
};

JobProgress::JobProgress(const RenderJob& job) {
    if (!job.underMpi()) return;
#if STRATA_WITH_MPI
    static_assert(sizeof(PassTally) == 2 * sizeof(uint64_t));
    window_ = std::make_unique<Window>();
    void* memory = nullptr;
    MPI_Win_allocate(job.isRoot() ? sizeof(PassTally) : 0, sizeof(uint64_t), MPI_INFO_NULL,
                     MPI_COMM_WORLD, &memory, &window_->handle);
    if (job.isRoot()) new (memory) PassTally{};
    // One shared lock on every rank for the tally's whole life (no rank ever locks exclusively):
    // adding a pass is then a lone accumulate, and the render loop has no collective call in it.
    MPI_Win_lock_all(MPI_MODE_NOCHECK, window_->handle);
    // Rank 0's zeros are in the window before any rank adds to them.
    MPI_Win_sync(window_->handle);
    MPI_Barrier(MPI_COMM_WORLD);
#endif
}

JobProgress::~JobProgress() {
#if STRATA_WITH_MPI
    if (!window_) return;
    MPI_Win_unlock_all(window_->handle);
    MPI_Win_free(&window_->handle);
#endif
}

void JobProgress::addPass(uint64_t paths) {
    if (!window_) {
        own_ = {own_.passes + 1, own_.paths + paths};
        return;
    }
#if STRATA_WITH_MPI
    const uint64_t pass[2] = {1, paths};
    MPI_Accumulate(pass, 2, MPI_UINT64_T, 0, 0, 2, MPI_UINT64_T, MPI_SUM, window_->handle);
    // Local completion only (`pass` may go). A full MPI_Win_flush would wait for rank 0 to apply
    // the sum, and where rank 0 does that in its own MPI calls (Open MPI 4.1's osc/pt2pt, its
    // one-sided transport over TCP between hosts) that is when rank 0 ends its current pass: with
    // a flush per pass, 2 ranks over TCP took 4.1-6.8 s instead of 3.4-3.9 s for the Cornell box
    // at 128x128, 240 spp.
    MPI_Win_flush_local(0, window_->handle);
#endif
}

void JobProgress::flush() {
#if STRATA_WITH_MPI
    if (window_) MPI_Win_flush(0, window_->handle);
#endif
}

PassTally JobProgress::tally() {
    if (!window_) return own_;
    uint64_t total[2] = {0, 0};
#if STRATA_WITH_MPI
    // An atomic read: the other ranks' accumulates may land at any moment.
    MPI_Get_accumulate(nullptr, 0, MPI_UINT64_T, total, 2, MPI_UINT64_T, 0, 0, 2, MPI_UINT64_T,
                       MPI_NO_OP, window_->handle);
    MPI_Win_flush(0, window_->handle);
#endif
    return {total[0], total[1]};
}

}  // namespace strata
