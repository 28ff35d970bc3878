#pragma once
// In-process render timing shared by the bench's sections: how many paths and rays a render
// traced per second of wall time and per CPU-second.
#include <chrono>
#include <cstdint>

#include "render_options.h"
#include "scene/camera.h"
#include "scene/scene_loader.h"

namespace strata {

using Clock = std::chrono::steady_clock;

inline double secondsSince(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

// Wall and CPU time: the machine is shared, so ratios between measurements taken at different
// moments use CPU time (work per CPU-second), and wall time shows what a user waits.
struct RenderRate {
    double seconds = 0.0;
    double cpuSeconds = 0.0;
    uint64_t paths = 0;
    uint64_t rays = 0;
    double mpathsPerSecond() const { return paths / seconds * 1e-6; }
    double mraysPerSecond() const { return rays / seconds * 1e-6; }
    double mpathsPerCpuSecond() const { return paths / cpuSeconds * 1e-6; }
    double mraysPerCpuSecond() const { return rays / cpuSeconds * 1e-6; }
};

// Renders `passes` whole passes (after one untimed warm-up pass) and times them.
RenderRate measureRender(const Scene& scene, const Camera& camera, const RenderOptions& options,
                         uint32_t passes);

}  // namespace strata
