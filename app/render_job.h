#pragma once
// The processes of one `strata render`: the ranks of an MPI job when the program was started by an
// MPI launcher (mpirun, srun) and built with STRATA_WITH_MPI, else this one process as a job of one
// rank, for which every call below is the plain single-process behaviour. All the MPI glue lives in
// render_job.cpp, so the render command is written once for both.
#include <cstdint>
#include <exception>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <type_traits>

#include "film/accumulation_buffer.h"
#include "integrator/progressive_renderer.h"
#include "scene/scene_loader.h"
#include "usage.h"

namespace strata {

// Thrown on the ranks other than 0 when a step failed: rank 0 prints the one message for the job
// and exits with its status (usage.h), which becomes the launcher's; the others exit with 0. A
// launcher ends the whole job as soon as one rank exits non-zero, and a rank that did so could
// have rank 0 killed before it printed the message.
struct ErrorReportedByRankZero {};

class RenderJob {
public:
    // MPI_Init_thread when launched by an MPI launcher. A build without MPI started by one with
    // several processes throws: each would render the whole image into the same files.
    RenderJob();
    ~RenderJob();  // MPI_Finalize
    RenderJob(const RenderJob&) = delete;
    RenderJob& operator=(const RenderJob&) = delete;

    int rank() const { return rank_; }
    int ranks() const { return ranks_; }
    bool isRoot() const { return rank_ == 0; }
    // Started by an MPI launcher (even with one rank).
    bool underMpi() const { return mpi_; }

    // Runs `step` on every rank, then all ranks compare notes: when it threw anywhere, every rank
    // throws (rank 0 the failure of the lowest failing rank, named "rank N" when not its own, a
    // UsageError when that was one; the others ErrorReportedByRankZero), so no rank is left
    // waiting in a later collective call and the job ends before any output is written. One
    // rank: runs `step`, exceptions pass through.
    template <typename Step>
    auto collectively(Step&& step) -> std::invoke_result_t<Step&>;

    // Rank 0 reads the scene's files with `read`; every rank gets their names and bytes
    // (MPI_Bcast) and so parses the very same scene, even when the hosts' file systems differ.
    SceneBundle shareSceneBundle(const std::function<SceneBundle()>& read);

    // Adds every rank's buffer and counters into rank 0's (MPI_Reduce); the other ranks' are then
    // meaningless. Ranks must have rendered disjoint passes (passesOfRank).
    void reduce(AccumulationBuffer& buffer, RenderCounters& counters);

private:
    // The collective half of `collectively`: returns when no rank failed, else throws as above.
    void settle(std::exception_ptr failure);

    int rank_ = 0;
    int ranks_ = 1;
    bool mpi_ = false;
};

// The passes rendered so far and their paths, for progress.
struct PassTally {
    uint64_t passes = 0;
    uint64_t paths = 0;
};

// The whole job's progress, for rank 0's progress bar: every rank adds each pass it finishes to a
// tally that rank 0 holds in an MPI window (one-sided, so no rank waits for another's passes).
// One process: the tally of its own passes. Making and destroying it are collective under MPI, so
// do both at the same point on every rank and outside any `collectively` step: a step may fail
// on some ranks only, but `collectively` then throws on all of them, and the tally's destructor
// runs on every rank alike.
class JobProgress {
public:
    explicit JobProgress(const RenderJob& job);
    ~JobProgress();
    JobProgress(const JobProgress&) = delete;
    JobProgress& operator=(const JobProgress&) = delete;

    // Counts one finished pass of this rank that traced `paths` paths, without waiting for rank 0:
    // the pass may reach rank 0's tally only once rank 0 next calls MPI.
    void addPass(uint64_t paths);
    // Waits until every pass this rank added is in rank 0's tally. Called by each rank after its
    // last pass of a `collectively` step, so that once the step has settled the tally is complete.
    void flush();
    // What all ranks have counted so far (as far as it has reached rank 0).
    PassTally tally();

private:
    struct Window;                    // rank 0's tally, defined in render_job.cpp
    std::unique_ptr<Window> window_;  // null when not under MPI
    PassTally own_;
};

template <typename Step>
auto RenderJob::collectively(Step&& step) -> std::invoke_result_t<Step&> {
    using Result = std::invoke_result_t<Step&>;
    std::exception_ptr failure;
    if constexpr (std::is_void_v<Result>) {
        try {
            step();
        } catch (...) {
            failure = std::current_exception();
        }
        settle(failure);
    } else {
        std::optional<Result> result;
        try {
            result.emplace(step());
        } catch (...) {
            failure = std::current_exception();
        }
        settle(failure);
        return std::move(*result);
    }
}

}  // namespace strata
