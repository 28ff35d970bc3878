#include "integrator/render_session.h"

#include <algorithm>
#include <chrono>
#include <vector>

#include "util/error.h"

namespace strata {
namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace

RenderSession::RenderSession(const Scene& scene, const Camera& camera, const RenderSettings& settings,
                             PassRange passes)
    : passes_(passes),
      buffer_(camera.width(), camera.height(),
              settings.adaptive.enabled() ? PixelErrors::Kept : settings.pixelErrors),
      renderer_(std::make_unique<ProgressiveRenderer>(scene, camera, settings)),
      adaptive_(settings.adaptive, buffer_.pixelCount()) {
    if (passes.end < passes.begin) throw Error("a session's pass range must not end before it begins");
}

void RenderSession::run(const RenderBudget& budget, const std::function<void(const PassReport&)>& onPass,
                        const std::atomic<bool>* cancel) {
    while (!finished(budget)) {
        int steps = kPathsPerPass - step_;
        if (budget.spp > 0) steps = static_cast<int>(std::min<uint32_t>(steps, budget.spp - spp()));
        if (!renderSteps(steps, 1, cancel)) return;
        if (step_ == 0 && onPass) onPass({pass() - 1, completedPasses_, lastPassPaths_});
    }
}

bool RenderSession::renderSteps(int steps, int bands, const std::atomic<bool>* cancel,
                                const std::function<void()>& betweenBands) {
    if (steps < 1 || step_ + steps > kPathsPerPass) throw Error("renderSteps: the steps leave the pass");
    if (bands < 1) throw Error("renderSteps: at least one band");
    if (pass() >= passes_.end) throw Error("renderSteps: the session's passes are all rendered");
    const auto cancelled = [cancel] { return cancel && cancel->load(std::memory_order_relaxed); };
    const int height = buffer_.height();
    bands = std::min(bands, height);
    // The mask changes only between passes, so every pixel's passes stay complete.
    const std::vector<uint8_t>* skip = adaptive_.enabled() ? &adaptive_.doneMask() : nullptr;
    for (int band = 0; band < bands && !cancelled(); ++band) {
        const auto start = Clock::now();
        renderer_->renderSteps(buffer_, pass(), step_, step_ + steps,
                               {cancel, skip, height * band / bands, height * (band + 1) / bands});
        renderSeconds_ += secondsSince(start);
        if (band + 1 < bands && !cancelled() && betweenBands) betweenBands();
    }
    if (cancelled()) return false;
    step_ += steps;
    if (step_ < kPathsPerPass) return true;
    step_ = 0;
    ++completedPasses_;
    lastPassPaths_ = counters().paths - pathsBeforePass_;
    pathsBeforePass_ = counters().paths;
    if (adaptive_.enabled()) {
        const auto start = Clock::now();
        adaptive_.update(buffer_);
        renderSeconds_ += secondsSince(start);
    }
    return true;
}

bool RenderSession::finished(const RenderBudget& budget) const {
    return pass() >= passes_.end || converged() || (budget.spp > 0 && spp() >= budget.spp) ||
           (budget.seconds > 0.0 && renderSeconds_ >= budget.seconds);
}

bool RenderSession::converged() const {
    return adaptive_.enabled() && adaptive_.activePixels() == 0 && step_ == 0;
}

}  // namespace strata
