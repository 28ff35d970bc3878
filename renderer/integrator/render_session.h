#pragma once
// One progressive render: the accumulation buffer, the renderer that fills it, adaptive
// sampling's mask, and where the render stands (its pass and step). Every front end renders
// through it: `strata render` (each MPI rank its share of the passes), the bench, and the viewer's
// worker, which renders a step or a group of steps at a time and in bands of rows.
//
// A session renders the image's passes in order from the first of its pass range. Its samples
// are those of ProgressiveRenderer for the same (seed, pixel, pass, step), however the passes are
// cut into calls: whole passes, steps, groups of steps or bands of rows give bit-identical
// buffers. A session over a pass range holds exactly those passes, so the sessions of MPI ranks
// over a partition of the passes (pass_partition.h) add up to the whole render, up to the order
// of the additions (render_job.cpp).
#include <atomic>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>

#include "film/accumulation_buffer.h"
#include "film/adaptive_sampling.h"
#include "integrator/pass_partition.h"
#include "integrator/progressive_renderer.h"
#include "scene/camera.h"
#include "scene/scene.h"

namespace strata {

inline constexpr PassRange kEveryPass{0, std::numeric_limits<uint32_t>::max()};

// When a session stops. Besides these, it stops at the end of its pass range and once adaptive
// sampling has finished every pixel (RenderSettings::adaptive: the noise budget).
struct RenderBudget {
    uint32_t spp = 0;      // paths per pixel rendered by this session; 0: no limit. Met exactly.
    double seconds = 0.0;  // render time; 0: no limit. Checked after each pass.
};

// What `run` reports after each pass it completes.
struct PassReport {
    uint32_t pass = 0;    // the pass's index in the image's sequence of passes
    uint32_t passes = 0;  // passes this session has completed, that one included
    uint64_t paths = 0;   // paths that pass traced (fewer than one per pixel and step when
                          // adaptive sampling skips pixels)
};

class RenderSession {
public:
    // Throws strata::Error for settings the renderer refuses.
    RenderSession(const Scene& scene, const Camera& camera, const RenderSettings& settings,
                  PassRange passes = kEveryPass);

    // Renders until finished(budget) or `cancel` becomes true: the rest of the pass in flight,
    // then whole passes, the last one cut short when budget.spp ends inside it. `onPass` is called
    // after every pass that completes, on the calling thread.
    void run(const RenderBudget& budget, const std::function<void(const PassReport&)>& onPass = {},
             const std::atomic<bool>* cancel = nullptr);

    // The next `steps` steps (one path per pixel each) of the pass in flight, which they must not
    // go past, over the image's rows in `bands` bands of about equal height rendered one after
    // the other; `betweenBands` is called after every band but the last (the viewer shows them).
    // Returns false when `cancel` became true: the buffer then holds part of the steps, and the
    // session must be abandoned.
    bool renderSteps(int steps, int bands = 1, const std::atomic<bool>* cancel = nullptr,
                     const std::function<void()>& betweenBands = {});

    bool finished(const RenderBudget& budget) const;
    // Adaptive sampling is on and has finished every pixel (decided at complete passes only).
    bool converged() const;

    // Paths per pixel this session has rendered, counting the pixels adaptive sampling skipped.
    uint32_t spp() const { return completedPasses_ * kPathsPerPass + static_cast<uint32_t>(step_); }
    uint32_t completedPasses() const { return completedPasses_; }
    // The pass in flight (index in the image's sequence) and its next step.
    uint32_t pass() const { return passes_.begin + completedPasses_; }
    int step() const { return step_; }
    // Wall time spent rendering (and updating the adaptive mask), not in callbacks.
    double renderSeconds() const { return renderSeconds_; }

    const AccumulationBuffer& buffer() const { return buffer_; }
    AccumulationBuffer& buffer() { return buffer_; }  // e.g. for the MPI reduction
    const AdaptiveSampling& adaptive() const { return adaptive_; }
    RenderCounters counters() const { return renderer_->counters(); }
    int threadCount() const { return renderer_->threadCount(); }
    const RenderSettings& settings() const { return renderer_->settings(); }

private:
    PassRange passes_;
    AccumulationBuffer buffer_;
    std::unique_ptr<ProgressiveRenderer> renderer_;  // on the heap: a session can be moved
    AdaptiveSampling adaptive_;
    uint32_t completedPasses_ = 0;
    int step_ = 0;
    double renderSeconds_ = 0.0;
    uint64_t pathsBeforePass_ = 0;  // the renderer's path count when the pass in flight began
    uint64_t lastPassPaths_ = 0;    // paths the last completed pass traced
};

}  // namespace strata
