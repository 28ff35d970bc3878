#include "render_worker.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "film/accumulation_buffer.h"
#include "integrator/progressive_renderer.h"

namespace strata::viewer {
namespace {

using Clock = std::chrono::steady_clock;

// A step that takes longer than this is rendered in bands of rows, one band about this long, and
// the display shows each band as it finishes instead of waiting for the whole step. Not shorter:
// every snapshot is a full-image texture upload on the UI thread (44 MB for a 1280x720 split
// view), which at 20 per second pushed llvmpipe's UI frame times from 15-22 to 50-64 ms.
constexpr double kBandSeconds = 0.25;
constexpr int kMinBandRows = 16;  // the renderer's tile height: thinner bands waste its threads
// Nice value of the render threads: the UI thread stays responsive with every core rendering.
constexpr int kRenderNiceness = 5;
// Bands of a job's first step, whose cost is not known yet: its first image comes sooner.
constexpr int kFirstStepBands = 4;
// After the first pass a step changes the image little, and a snapshot for every step (each one
// built here, uploaded and drawn by the UI) cost the viewer 10% of its throughput at 640x360,
// where a step takes 48 ms. From the second pass on, fast steps are rendered together in groups
// that take at least this long (within the pass), and the display updates after each group.
constexpr double kStepGroupSeconds = 0.25;

bool samePose(const CameraPose& a, const CameraPose& b) {
    return a.position == b.position && a.lookAt == b.lookAt && a.up == b.up &&
           a.fovYDegrees == b.fovYDegrees;
}

double secondsSince(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

// The steps the next renderSteps call renders: one in the first pass, which the display shows
// step by step, and while a step is slow (it is split in bands instead); later, as many as take
// kStepGroupSeconds, within the pass and the target spp.
int stepsAtOnce(uint32_t pass, int step, double stepSeconds, uint32_t spp, uint32_t targetSpp) {
    if (pass == 0 || stepSeconds <= 0.0) return 1;
    const double wanted = std::ceil(kStepGroupSeconds / stepSeconds);
    int steps = static_cast<int>(std::min<double>(wanted, kPathsPerPass - step));
    if (targetSpp > spp) steps = std::min(steps, static_cast<int>(targetSpp - spp));
    return steps;
}

}  // namespace

bool needsRestart(const WorkerConfig& a, const WorkerConfig& b) {
    return a.scene != b.scene || !samePose(a.pose, b.pose) || a.width != b.width ||
           a.height != b.height || a.sides != b.sides ||
           a.nextEventEstimation != b.nextEventEstimation || a.rouletteDepth != b.rouletteDepth ||
           a.seed != b.seed ||
           a.threads != b.threads || a.preview != b.preview || a.reference != b.reference ||
           a.noiseThreshold != b.noiseThreshold;
}

struct RenderWorker::Job {
    struct Side {
        AccumulationBuffer buffer;
        std::unique_ptr<ProgressiveRenderer> renderer;
        bool stratified;
        AdaptiveSampling adaptive;
        double seconds = 0.0;
        double lastStepSeconds = -1.0;  // -1: no step yet
        std::vector<ErrorSample> history;
    };
    uint64_t generation = 0;
    std::shared_ptr<const LoadedScene> scene;  // keeps what the renderers reference alive
    std::unique_ptr<Camera> camera;
    std::shared_ptr<const Image> reference;
    std::vector<Side> sides;
    uint32_t pass = 0;
    int step = 0;
    bool preview = false;
    Clock::time_point start = Clock::now();
    std::string error;

    uint32_t spp() const { return pass * kPathsPerPass + static_cast<uint32_t>(step); }
    double renderSeconds() const {
        double total = 0.0;
        for (const Side& side : sides) total += side.seconds;
        return total;
    }
    // Every pixel of every side under the noise threshold (checked at complete passes only).
    bool converged() const {
        return !sides.empty() && step == 0 && std::all_of(sides.begin(), sides.end(), [](const Side& side) {
                   return side.adaptive.enabled() && side.adaptive.activePixels() == 0;
               });
    }
    bool finished(const WorkerConfig& config) const {
        return !error.empty() || sides.empty() || config.paused ||
               (config.targetSpp > 0 && spp() >= config.targetSpp) ||
               (config.targetSeconds > 0.0 && renderSeconds() >= config.targetSeconds) || converged() ||
               (preview && spp() >= 1);
    }
};

RenderWorker::RenderWorker() : thread_([this] { run(); }) {}

RenderWorker::~RenderWorker() {
    {
        std::lock_guard lock(mutex_);
        stop_ = true;
    }
    wake_.notify_all();
    thread_.join();
}

void RenderWorker::configure(const WorkerConfig& config, bool restart) {
    {
        std::lock_guard lock(mutex_);
        if (restart || version_ == 0 || needsRestart(config_, config)) {
            ++generation_;
            cancel_ = true;
        }
        config_ = config;
        ++version_;
    }
    wake_.notify_all();
}

std::shared_ptr<const WorkerSnapshot> RenderWorker::latest() {
    std::lock_guard lock(snapshotMutex_);
    taken_ = true;
    return latest_;
}

void RenderWorker::setPublishCallback(std::function<void()> onPublish) {
    std::lock_guard lock(snapshotMutex_);
    onPublish_ = std::move(onPublish);
}

void RenderWorker::run() {
    std::unique_ptr<Job> job;
    uint64_t seenVersion = 0;
    bool idle = false;
    for (;;) {
        WorkerConfig config;
        uint64_t generation = 0;
        {
            std::unique_lock lock(mutex_);
            wake_.wait(lock, [&] { return stop_ || (version_ != 0 && (!idle || version_ != seenVersion)); });
            if (stop_) return;
            seenVersion = version_;
            config = config_;
            generation = generation_;
            cancel_ = false;  // under the lock: a restart after this point cancels the next step
        }
        if (!job || job->generation != generation) {
            job = std::make_unique<Job>();
            job->generation = generation;
            job->scene = config.scene;
            job->reference = config.reference;
            job->preview = config.preview;
            try {
                const int divisor = config.preview ? kPreviewDivisor : 1;
                job->camera = std::make_unique<Camera>(config.pose, std::max(1, config.width / divisor),
                                                       std::max(1, config.height / divisor));
                for (const SideConfig& side : config.sides) {
                    RenderSettings settings;
                    settings.integrator.depth = side.depth;
                    settings.integrator.sampler = side.sampler;
                    settings.integrator.nextEventEstimation = config.nextEventEstimation;
                    settings.integrator.rouletteDepth = config.rouletteDepth;
                    settings.seed = config.seed;
                    settings.threads = config.threads;
                    // Render threads yield to the UI thread (and llvmpipe's) on a small machine.
                    settings.niceness = kRenderNiceness;
                    const size_t pixels = static_cast<size_t>(job->camera->width()) * job->camera->height();
                    job->sides.push_back(Job::Side{
                        AccumulationBuffer(job->camera->width(), job->camera->height()),
                        std::make_unique<ProgressiveRenderer>(config.scene->scene, *job->camera, settings),
                        stratifies(side.sampler),
                        AdaptiveSampling({config.preview ? 0.0 : config.noiseThreshold}, pixels), 0.0, -1.0, {}});
                }
            } catch (const std::exception& e) {
                job->sides.clear();
                job->error = e.what();
            }
        }
        idle = job->finished(config);
        if (idle) {
            publish(*job, true);
            continue;
        }
        if (renderSteps(*job, config.targetSpp)) publish(*job, false);
    }
}

bool RenderWorker::renderSteps(Job& job, uint32_t targetSpp) {
    double stepSeconds = 0.0;  // all sides, one step
    for (const auto& side : job.sides) stepSeconds += std::max(0.0, side.lastStepSeconds);
    const int steps = stepsAtOnce(job.pass, job.step, stepSeconds, job.spp(), targetSpp);
    for (auto& side : job.sides) {
        const uint64_t before = side.renderer->counters().paths;
        const auto* skip = side.adaptive.enabled() ? &side.adaptive.doneMask() : nullptr;
        const int height = side.buffer.height();
        const int wanted = side.lastStepSeconds < 0.0
                               ? kFirstStepBands
                               : static_cast<int>(side.lastStepSeconds * steps / kBandSeconds);
        const int bands = std::clamp(wanted, 1, std::max(1, height / kMinBandRows));
        double seconds = 0.0;  // rendering only, not the snapshots between bands
        for (int band = 0; band < bands && !cancel_; ++band) {
            const auto bandStart = Clock::now();
            side.renderer->renderSteps(side.buffer, job.pass, job.step, job.step + steps,
                                       {&cancel_, skip, height * band / bands, height * (band + 1) / bands});
            seconds += secondsSince(bandStart);
            if (band + 1 < bands && !cancel_) publish(job, false, true);
        }
        side.lastStepSeconds = seconds / steps;
        side.seconds += seconds;
        totalRenderSeconds_ += seconds;
        totalPaths_ += side.renderer->counters().paths - before;
        if (cancel_) return false;
    }
    job.step += steps;
    if (job.step < kPathsPerPass) return true;
    job.step = 0;
    ++job.pass;
    // The mask changes only between passes, so every pixel's passes stay complete.
    for (auto& side : job.sides) {
        if (side.adaptive.enabled()) side.adaptive.update(side.buffer);
    }
    // Noise is measured at complete passes; strata24's estimate needs two pass means.
    if (job.pass < 2) return true;
    for (auto& side : job.sides) {
        const AccumulationBuffer& buffer = side.buffer;
        const bool againstReference = job.reference && job.reference->width == buffer.width() &&
                                      job.reference->height == buffer.height();
        double squares = 0.0;
        for (size_t p = 0; p < buffer.pixelCount(); ++p) {
            const double e = againstReference
                                 ? luminance(buffer.mean(p)) - luminance(glm::dvec3(job.reference->pixels[p]))
                                 : pixelStandardError(buffer, p, side.stratified);
            squares += e * e;
        }
        side.history.push_back({static_cast<double>(job.spp()), side.seconds,
                                std::sqrt(squares / static_cast<double>(buffer.pixelCount()))});
    }
    return true;
}

void RenderWorker::publish(const Job& job, bool idle, bool midStep) {
    {
        std::lock_guard lock(snapshotMutex_);
        // Build a new image only when the UI has taken the last one, a pass just closed, or the
        // worker is about to rest (its last state must be shown).
        const bool passClosed = job.step == 0 && !midStep;
        if (!taken_ && !passClosed && !idle) return;
    }
    auto snapshot = std::make_shared<WorkerSnapshot>();
    snapshot->generation = job.generation;
    snapshot->preview = job.preview;
    snapshot->idle = idle;
    snapshot->againstReference = job.reference && job.camera && job.reference->width == job.camera->width() &&
                                 job.reference->height == job.camera->height();
    snapshot->spp = job.spp();
    snapshot->passes = job.pass;
    snapshot->elapsedSeconds = secondsSince(job.start);
    snapshot->renderSeconds = job.renderSeconds();
    snapshot->totalPaths = totalPaths_;
    snapshot->totalRenderSeconds = totalRenderSeconds_;
    snapshot->error = job.error;
    for (const auto& side : job.sides) {
        const RenderCounters counters = side.renderer->counters();
        snapshot->paths += counters.paths;
        snapshot->rays += counters.rays;
        snapshot->droppedSamples += side.buffer.droppedSamples();
        const auto* done = side.adaptive.enabled() ? &side.adaptive.doneMask() : nullptr;
        snapshot->sides.push_back({DisplayImage::fromBuffer(side.buffer, side.stratified, done), side.history,
                                   side.seconds, side.adaptive.enabled() ? side.adaptive.activePixels()
                                                                         : side.buffer.pixelCount()});
    }
    std::function<void()> onPublish;
    {
        std::lock_guard lock(snapshotMutex_);
        latest_ = std::move(snapshot);
        taken_ = false;
        onPublish = onPublish_;
    }
    if (onPublish) onPublish();
}

}  // namespace strata::viewer
