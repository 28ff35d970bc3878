#pragma once
// Drives the path tracer over the image, a pass at a time, into an accumulation buffer.
// A pass gives every pixel 24 paths (one per stratum under strata24). It can be delivered whole
// (renderPass, the batch renderer) or in 24 steps of one path per pixel (renderStep, the viewer),
// with the same samples either way. Work is split into tiles over a TBB arena of the requested
// size; a pixel's samples depend only on (seed, pixel, pass, step, bounce), so the image is
// bit-identical for any thread count. Camera rays that find no surface show the backdrop
// (film/backdrop.h), and the buffer counts those that do (its coverage).
#include <atomic>
#include <cstdint>
#include <memory>
#include <vector>
#include <tbb/task_arena.h>
#include <tbb/task_scheduler_observer.h>

#include "film/accumulation_buffer.h"
#include "film/adaptive_sampling.h"
#include "film/backdrop.h"
#include "scene/camera.h"
#include "integrator/path_integrator.h"
#include "scene/scene.h"


namespace strata {

inline constexpr int kPathsPerPass = 24;

struct RenderSettings {
    PathIntegratorSettings integrator;
    uint64_t seed = 0;
    int threads = 0;  // 0: all hardware threads
    // > 0: every thread that renders runs at this Linux nice value, so that a user interface in
    // the same process is scheduled first on a machine with few cores. The threads keep it (an
    // unprivileged process cannot raise a thread's priority again), which suits the viewer, whose
    // rendering all happens off its UI thread. Results do not depend on it.
    int niceness = 0;
    // Which pixels stop receiving passes; applied by RenderSession (render_session.h).
    AdaptiveSettings adaptive{};
    // Whether a RenderSession's buffer keeps each pixel's error estimates (accumulation_buffer.h)
    // for its owner to read; adaptive sampling keeps them whatever this says.
    PixelErrors pixelErrors = PixelErrors::Kept;
    // What camera rays that leave the scene show.
    BackdropSetting backdrop{};
};

// How much of a step to render (renderStep): the viewer renders a slow step in bands of rows so
// that the display can update as they finish, and abandons a step when the camera moves.
struct StepControl {
    const std::atomic<bool>* cancel = nullptr;   // when it becomes true, tiles not yet started are skipped
    const std::vector<uint8_t>* skip = nullptr;  // as renderPass's; must not change within a pass
    int firstRow = 0;                            // rows [firstRow, endRow) only
    int endRow = -1;                             // -1: to the last row
};

struct RenderCounters {
    uint64_t paths = 0;
    uint64_t rays = 0;
};

class ProgressiveRenderer {
public:
    ProgressiveRenderer(const Scene& scene, const Camera& camera, const RenderSettings& settings);
    ~ProgressiveRenderer();

    // All 24 paths of pass `pass` for every pixel; closes the pass in the buffer. Pixels whose
    // entry in `skip` (if given, one per pixel) is non-zero are left alone: adaptive sampling.
    void renderPass(AccumulationBuffer& buffer, uint32_t pass, const std::vector<uint8_t>* skip = nullptr);
    // Path `step` (0..23) of pass `pass` for every pixel of the rows `control` selects (all by
    // default); step 23 closes the pass for them. A cancelled step leaves the buffer partial (the
    // viewer abandons it: a camera change must not wait for a whole step).
    void renderStep(AccumulationBuffer& buffer, uint32_t pass, int step, const StepControl& control = {});
    // Steps [firstStep, endStep) of pass `pass`, as renderStep one after the other would render
    // them (the same samples), but each pixel's paths together, as renderPass does: one step at a
    // time was 2-6% slower than whole passes at 640x360 (its accumulator, likely, out of cache).
    void renderSteps(AccumulationBuffer& buffer, uint32_t pass, int firstStep, int endStep,
                     const StepControl& control = {});

    RenderCounters counters() const { return {paths_.load(), rays_.load()}; }
    const RenderSettings& settings() const { return settings_; }
    int threadCount() const;

private:
    const Scene& scene_;
    const Camera& camera_;
    RenderSettings settings_;
    PathIntegrator integrator_;
    Backdrop backdrop_;
    std::unique_ptr<tbb::task_arena> arena_;
    std::unique_ptr<tbb::task_scheduler_observer> niceness_;  // observes arena_; declared after it
    std::atomic<uint64_t> paths_{0};
    std::atomic<uint64_t> rays_{0};
};

}  // namespace strata
