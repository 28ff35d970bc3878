#include "render_worker.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "film/accumulation_buffer.h"
#include "film/image_metrics.h"

namespace strata::viewer {
namespace {

using Clock = std::chrono::steady_clock;

// A step, or a group of steps, that takes longer than this is rendered in bands of rows, one band
// about this long, and the display shows each band as it finishes instead of waiting for them
// all. Not shorter: every snapshot is a full-image texture upload on the UI thread (44 MB for a
// 1280x720 split view), which at 20 per second pushed llvmpipe's UI frame times from 15-22 to
// 50-64 ms.
constexpr double kBandSeconds = 0.25;
constexpr int kMinBandRows = 16;  // the renderer's tile height: thinner bands waste its threads
// Bands of a job's first step, whose cost is not known yet: its first image comes sooner.
constexpr int kFirstStepBands = 4;
// Steps one at a time cost throughput: a snapshot for every step (built here, uploaded and drawn
// by the UI) cost the viewer 10% at 640x360, where a step takes 48 ms, and every call works out
// the pixels' shared streams anew (path_samples.h): with the first pass step by step and groups
// of 0.25 s the viewer took 1.19x its present time (640x360, 144 spp). So after the image's first
// step, steps are rendered in groups of about this long (within the pass), band by band
// (kBandSeconds), and the display still updates four times a second. Not longer: the sides of
// the split view take turns by group, and one should not run ahead of the other by more than this.
constexpr double kStepGroupSeconds = 2.0;

double secondsSince(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

// The steps the next renderSteps call renders: a job's first step alone, before its cost is
// known, so that the whole image shows one path per pixel as soon as it can; then as many as take
// kStepGroupSeconds, within the pass and the target spp.
int stepsAtOnce(int step, double stepSeconds, uint32_t spp, uint32_t targetSpp) {
    if (stepSeconds <= 0.0) return 1;
    const double wanted = std::ceil(kStepGroupSeconds / stepSeconds);
    int steps = static_cast<int>(std::min<double>(wanted, kPathsPerPass - step));
    if (targetSpp > spp) steps = std::min(steps, static_cast<int>(targetSpp - spp));
    return steps;
}

}  // namespace

void appendErrorSample(std::vector<ErrorSample>& history, const ErrorSample& sample) {
    history.push_back(sample);
    if (history.size() <= kMaxErrorSamples) return;
    // The points at even indices before the newest, then the newest.
    size_t kept = 0;
    for (size_t i = 0; i + 1 < history.size(); i += 2) history[kept++] = history[i];
    history[kept++] = history.back();
    history.resize(kept);
}

bool needsRestart(const WorkerConfig& a, const WorkerConfig& b) {
    return a.scene != b.scene || a.pose != b.pose || a.width != b.width ||
           a.height != b.height || a.sides != b.sides ||
           a.nextEventEstimation != b.nextEventEstimation || a.rouletteDepth != b.rouletteDepth ||
           a.lightSampler != b.lightSampler || a.terminatorOffset != b.terminatorOffset ||
           a.seed != b.seed ||
           a.threads != b.threads || a.preview != b.preview || a.reference != b.reference ||
           a.noiseThreshold != b.noiseThreshold || a.backdrop != b.backdrop;
}

RenderSettings renderSettings(const WorkerConfig& config, const SideConfig& side) {
    RenderSettings settings;
    settings.integrator.depth = side.depth;
    settings.integrator.sampler = side.sampler;
    settings.integrator.nextEventEstimation = config.nextEventEstimation;
    settings.integrator.rouletteDepth = config.rouletteDepth;
    settings.integrator.lightSampler = config.lightSampler;
    settings.integrator.terminatorOffset = config.terminatorOffset;
    settings.seed = config.seed;
    settings.threads = config.threads;
    // Render threads yield to the UI thread (and llvmpipe's) on a small machine.
    settings.niceness = kWorkerNiceness;
    // The preview's single path per pixel is no estimate to judge pixels by.
    settings.adaptive.threshold = config.preview ? 0.0 : config.noiseThreshold;
    settings.backdrop = config.backdrop;
    return settings;
}

struct RenderWorker::Job {
    struct Side {
        RenderSession session;
        bool stratified;
        double lastStepSeconds = -1.0;  // -1: no step yet
        std::vector<ErrorSample> history;
    };
    uint64_t generation = 0;
    std::shared_ptr<const LoadedScene> scene;  // keeps what the sessions reference alive
    std::unique_ptr<Camera> camera;
    std::shared_ptr<const Image> reference;
    std::vector<Side> sides;
    bool preview = false;
    Clock::time_point start = Clock::now();
    std::string error;

    // The sides render step for step, one after the other: while one renders, those before it
    // are a group of steps ahead, and the job is where the last of them is.
    uint32_t spp() const {
        uint32_t spp = sides.empty() ? 0 : sides.front().session.spp();
        for (const Side& side : sides) spp = std::min(spp, side.session.spp());
        return spp;
    }
    uint32_t pass() const { return spp() / kPathsPerPass; }
    int step() const { return static_cast<int>(spp() % kPathsPerPass); }
    double renderSeconds() const {
        double total = 0.0;
        for (const Side& side : sides) total += side.session.renderSeconds();
        return total;
    }
    // The reference is of this image's size, so the error curves measure against it.
    bool againstReference() const {
        return reference && camera && reference->width == camera->width() &&
               reference->height == camera->height();
    }
    // Every pixel of every side under the noise threshold (checked at complete passes only).
    bool converged() const {
        return !sides.empty() && std::all_of(sides.begin(), sides.end(), [](const Side& side) {
                   return side.session.converged();
               });
    }
    bool finished(const WorkerConfig& config) const {
        return !error.empty() || sides.empty() || config.paused ||
               (config.targetSpp > 0 && spp() >= config.targetSpp) ||
               (config.targetSeconds > 0.0 && renderSeconds() >= config.targetSeconds) || converged() ||
               (preview && spp() >= 1);
    }
    // A point of the side's error curve: RMSE against the reference as film/image_metrics.h
    // defines it (the bench's measure), else the root mean square over pixels of the estimated
    // standard error of the mean luminance, from the spread of the pass means for every sampler.
    // No spread within one render is its error: a pixel's samples are stratified over all its
    // paths (path_samples.h), so both spreads overstate it, the per-sample one by more and by
    // more where a pixel's footprint varies more. Measured alike, the two sides' ratio is the
    // one independent renders show (test_render_worker.cpp); each side's own spread (uniform's
    // per sample, strata24's per pass) put uniform's error 2-3 times too high against strata24's.
    double curveError(const Side& side) const {
        const AccumulationBuffer& buffer = side.session.buffer();
        if (againstReference()) return imageError(buffer.meanImage(), *reference).rmse;
        double squares = 0.0;
        for (size_t p = 0; p < buffer.pixelCount(); ++p) {
            const double e = buffer.passStandardError(p);
            squares += e * e;
        }
        return std::sqrt(squares / static_cast<double>(buffer.pixelCount()));
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

void RenderWorker::release() {
    std::unique_lock lock(mutex_);
    releasing_ = true;
    cancel_ = true;
    wake_.notify_all();
    released_.wait(lock, [&] { return !releasing_; });
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
            wake_.wait(lock, [&] {
                return stop_ || releasing_ || (version_ != 0 && (!idle || version_ != seenVersion));
            });
            if (stop_) return;
            if (releasing_) {
                // Rest until the next configure, which will bring a new job.
                job.reset();
                idle = true;
                seenVersion = version_;
                releasing_ = false;
                released_.notify_all();
                continue;
            }
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
                    job->sides.push_back(Job::Side{
                        RenderSession(config.scene->scene, *job->camera, renderSettings(config, side)),
                        stratifies(side.sampler), -1.0, {}});
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
    const int steps = stepsAtOnce(job.step(), stepSeconds, job.spp(), targetSpp);
    for (auto& side : job.sides) {
        RenderSession& session = side.session;
        const uint64_t pathsBefore = session.counters().paths;
        const double secondsBefore = session.renderSeconds();
        const int height = session.buffer().height();
        const int wanted = side.lastStepSeconds < 0.0
                               ? kFirstStepBands
                               : static_cast<int>(side.lastStepSeconds * steps / kBandSeconds);
        const int bands = std::clamp(wanted, 1, std::max(1, height / kMinBandRows));
        const bool rendered = session.renderSteps(steps, bands, &cancel_, [&] { publish(job, false, true); });
        // Rendering only, not the snapshots between bands.
        const double seconds = session.renderSeconds() - secondsBefore;
        side.lastStepSeconds = seconds / steps;
        totalRenderSeconds_ += seconds;
        totalPaths_ += session.counters().paths - pathsBefore;
        if (!rendered) return false;
    }
    // Noise is measured at complete passes; strata24's estimate needs two pass means.
    if (job.step() != 0 || job.pass() < 2) return true;
    for (auto& side : job.sides) {
        appendErrorSample(side.history,
                          {static_cast<double>(job.spp()), side.session.renderSeconds(), job.curveError(side)});
    }
    return true;
}

void RenderWorker::publish(const Job& job, bool idle, bool midStep) {
    {
        std::lock_guard lock(snapshotMutex_);
        // Build a new image only when the UI has taken the last one, a pass just closed, or the
        // worker is about to rest (its last state must be shown).
        const bool passClosed = job.step() == 0 && !midStep;
        if (!taken_ && !passClosed && !idle) return;
    }
    auto snapshot = std::make_shared<WorkerSnapshot>();
    snapshot->generation = job.generation;
    snapshot->preview = job.preview;
    snapshot->idle = idle;
    snapshot->againstReference = job.againstReference();
    snapshot->spp = job.spp();
    snapshot->passes = job.pass();
    snapshot->elapsedSeconds = secondsSince(job.start);
    snapshot->renderSeconds = job.renderSeconds();
    snapshot->totalPaths = totalPaths_;
    snapshot->totalRenderSeconds = totalRenderSeconds_;
    snapshot->error = job.error;
    for (const auto& side : job.sides) {
        const RenderSession& session = side.session;
        const RenderCounters counters = session.counters();
        snapshot->paths += counters.paths;
        snapshot->rays += counters.rays;
        snapshot->droppedSamples += session.buffer().droppedSamples();
        const AdaptiveSampling& adaptive = session.adaptive();
        const auto* done = adaptive.enabled() ? &adaptive.doneMask() : nullptr;
        const size_t active = adaptive.enabled() ? adaptive.activePixels() : session.buffer().pixelCount();
        snapshot->sides.push_back({DisplayImage::fromBuffer(session.buffer(), side.stratified, done),
                                   side.history, session.renderSeconds(), active});
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
