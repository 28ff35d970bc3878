#include "bench/render_rate.h"

#include "bench/ray_throughput.h"
#include "integrator/render_session.h"

namespace strata {

RenderRate measureRender(const Scene& scene, const Camera& camera, const RenderOptions& options,
                         uint32_t passes) {
    RenderSession session(scene, camera, options.renderSettings(scene));
    session.run({kPathsPerPass});
    const RenderCounters before = session.counters();
    const double cpuStart = processCpuSeconds();
    const auto start = Clock::now();
    session.run({(1 + passes) * kPathsPerPass});
    const RenderCounters after = session.counters();
    return {secondsSince(start), processCpuSeconds() - cpuStart, after.paths - before.paths,
            after.rays - before.rays};
}

}  // namespace strata
