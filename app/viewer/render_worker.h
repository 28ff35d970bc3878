#pragma once
// The viewer's render thread. It drives a RenderSession (integrator/render_session.h) a step or a
// group of steps at a time (a pass = 24 steps of one path per pixel) for one or two configurations
// of the same camera (the split view's sides, step for step, so both always hold equal samples)
// and publishes snapshots for the UI thread, which only ever takes the latest one under a short
// lock: it never waits for a step or a pass.
// Any change of scene, camera or setting restarts accumulation after the step in flight; a target
// (spp, render time, or every pixel under the noise threshold) or a pause blocks the thread on a
// condition variable (no CPU) until something changes.
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "scene/camera.h"
#include "sampling/direction_sampler.h"
#include "display_image.h"
#include "integrator/render_session.h"
#include "io/image_io.h"
#include "scene/scene_loader.h"

namespace strata::viewer {

struct SideConfig {
    SamplerKind sampler = SamplerKind::Strata24Bsdf;
    int depth = 5;
    bool operator==(const SideConfig&) const = default;
};

struct WorkerConfig {
    std::shared_ptr<const LoadedScene> scene;
    CameraPose pose;
    int width = 0;  // full-resolution image
    int height = 0;
    std::vector<SideConfig> sides;  // one, or two for the split view
    bool nextEventEstimation = true;
    int rouletteDepth = kRouletteDepthDefault;  // PathIntegratorSettings::rouletteDepth
    LightSamplerKind lightSampler = LightSamplerKind::Auto;  // PathIntegratorSettings::lightSampler
    float terminatorOffset = 0.0f;  // PathIntegratorSettings::terminatorOffset
    uint64_t seed = 0;
    int threads = 0;
    // Camera moving: one path per pixel at 1/kPreviewDivisor of the resolution, then wait.
    bool preview = false;
    // Reference radiance for RMSE (same size as the image), else the standard error is shown.
    std::shared_ptr<const Image> reference;
    // Adaptive sampling (renderer/film/adaptive_sampling.h): a pixel whose relative standard error is
    // at most this receives no more passes; 0: off.
    double noiseThreshold = 0.0;
    BackdropSetting backdrop;
    // These three never restart accumulation.
    uint32_t targetSpp = 0;      // 0: no limit
    double targetSeconds = 0.0;  // render time (all sides), 0: no limit
    bool paused = false;
};

inline constexpr int kPreviewDivisor = 4;

// Nice value of the viewer's render threads and of its loading threads: the UI thread stays
// responsive with every core rendering or loading.
inline constexpr int kWorkerNiceness = 5;

// Whether going from `a` to `b` restarts accumulation (anything but the targets / paused changed).
bool needsRestart(const WorkerConfig& a, const WorkerConfig& b);

// The renderer's settings for one side of `config`: the one place the viewer makes them.
RenderSettings renderSettings(const WorkerConfig& config, const SideConfig& side);

// One point of a side's error curve, taken at a completed pass.
struct ErrorSample {
    double spp;
    double seconds;  // this side's render time
    // RMSE against the reference (film/image_metrics.h), else the root mean square over pixels of
    // the estimated standard error of the mean luminance.
    double error;
};

// A side's error curve keeps at most this many points. Past it, every other point is dropped (the
// first and the newest stay), so that a render of 10^6 passes holds and copies into each snapshot
// no more than one of 10^4 does; the plot draws at most 2 * columns + 2 points (error_plot.h).
inline constexpr size_t kMaxErrorSamples = 4096;

// Appends `sample` to `history`, thinning it as kMaxErrorSamples says.
void appendErrorSample(std::vector<ErrorSample>& history, const ErrorSample& sample);

struct SideSnapshot {
    DisplayImage image;
    std::vector<ErrorSample> history;
    double seconds = 0.0;
    size_t activePixels = 0;  // pixels still receiving passes (all of them without a threshold)
};

struct WorkerSnapshot {
    uint64_t generation = 0;  // bumps on every restart
    bool preview = false;
    bool idle = false;        // a target reached, paused, or preview done
    bool againstReference = false;
    uint32_t spp = 0;         // per pixel, per side
    uint32_t passes = 0;      // completed passes per side
    double elapsedSeconds = 0.0;  // wall time since this generation began
    double renderSeconds = 0.0;   // time spent rendering it (what a target time counts)
    uint64_t paths = 0;       // this generation, all sides
    uint64_t rays = 0;
    uint64_t droppedSamples = 0;
    // Over the worker's life, for throughput figures.
    uint64_t totalPaths = 0;
    double totalRenderSeconds = 0.0;
    std::vector<SideSnapshot> sides;
    std::string error;  // a failure of this configuration (e.g. a degenerate camera)
};

class RenderWorker {
public:
    RenderWorker();
    ~RenderWorker();
    RenderWorker(const RenderWorker&) = delete;
    RenderWorker& operator=(const RenderWorker&) = delete;

    // Takes the new configuration; restarts accumulation when `restart` or when anything but
    // the targets / paused changed.
    void configure(const WorkerConfig& config, bool restart = false);
    // Stops rendering and lets go of the job: when it returns, the worker thread holds no
    // session of the configured scene and reads nothing of it until the next configure, so the
    // caller may change that scene in place (the viewer relights it). Waits for the step in
    // flight to stop at its next tile.
    void release();
    // The latest snapshot (null before the first); never waits for rendering.
    std::shared_ptr<const WorkerSnapshot> latest();
    // Called on the worker thread after each new snapshot: lets a UI that sleeps until an event
    // (GLFW's glfwWaitEvents) be woken by glfwPostEmptyEvent, which any thread may call.
    void setPublishCallback(std::function<void()> onPublish);

private:
    struct Job;
    void run();
    // Renders the job's next step, or several (stepsAtOnce in render_worker.cpp). False when
    // cancelled: the job is then stale and must not be published.
    bool renderSteps(Job& job, uint32_t targetSpp);
    // `midStep`: between two bands of a step, shown only if the UI took the last snapshot.
    void publish(const Job& job, bool idle, bool midStep = false);

    std::mutex mutex_;  // guards config_, version_, generation_, stop_, releasing_
    std::condition_variable wake_;
    std::condition_variable released_;
    bool releasing_ = false;  // release() waits for the worker thread to clear it
    WorkerConfig config_;
    uint64_t version_ = 0;
    uint64_t generation_ = 0;
    bool stop_ = false;
    // Set with a restart so that the step in flight stops at its next tile.
    std::atomic<bool> cancel_{false};

    std::mutex snapshotMutex_;  // guards latest_, taken_, onPublish_
    std::shared_ptr<const WorkerSnapshot> latest_;
    bool taken_ = true;
    std::function<void()> onPublish_;

    uint64_t totalPaths_ = 0;  // worker thread only
    double totalRenderSeconds_ = 0.0;
    std::thread thread_;
};

}  // namespace strata::viewer
