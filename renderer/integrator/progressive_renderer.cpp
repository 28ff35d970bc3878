#include "integrator/progressive_renderer.h"

#include <algorithm>
#include <array>
#include <span>
#include <string>
#include <vector>
#include <pmmintrin.h>
#include <xmmintrin.h>
#include <tbb/blocked_range2d.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#include <sys/resource.h>
#include <unistd.h>

#include "util/error.h"
#include "util/tbb_hand_off.h"

namespace strata {
namespace {
constexpr int kTileSize = 16;
constexpr int kMaxThreads = 1024;

// Sets the nice value of each thread as it joins the arena (nice values are per thread on Linux).
class ThreadNiceness : public tbb::task_scheduler_observer {
public:
    ThreadNiceness(tbb::task_arena& arena, int niceness)
        : tbb::task_scheduler_observer(arena), niceness_(niceness) {
        observe(true);
    }
    ~ThreadNiceness() override { observe(false); }
    void on_scheduler_entry(bool) override {
        setpriority(PRIO_PROCESS, static_cast<id_t>(gettid()), niceness_);  // best effort
    }

private:
    int niceness_;
};

}  // namespace

ProgressiveRenderer::ProgressiveRenderer(const Scene& scene, const Camera& camera,
                                         const RenderSettings& settings)
    : scene_(scene),
      camera_(camera),
      settings_(settings),
      integrator_(scene, settings.integrator),
      backdrop_(settings.backdrop, scene.lights().litByDefault()) {
    if (settings.threads < 0 || settings.threads > kMaxThreads) {
        throw Error("--threads must be in 1.." + std::to_string(kMaxThreads) + " (0: all cores)");
    }
    if (settings.integrator.depth < 0) throw Error("--depth must be at least 0");
    arena_ = settings.threads > 0 ? std::make_unique<tbb::task_arena>(settings.threads)
                                  : std::make_unique<tbb::task_arena>();
    if (settings.niceness > 0) niceness_ = std::make_unique<ThreadNiceness>(*arena_, settings.niceness);
}

ProgressiveRenderer::~ProgressiveRenderer() = default;

int ProgressiveRenderer::threadCount() const { return arena_->max_concurrency(); }

void ProgressiveRenderer::renderPass(AccumulationBuffer& buffer, uint32_t pass,
                                     const std::vector<uint8_t>* skip) {
    renderSteps(buffer, pass, 0, kPathsPerPass, StepControl{nullptr, skip});
}

void ProgressiveRenderer::renderStep(AccumulationBuffer& buffer, uint32_t pass, int step,
                                     const StepControl& control) {
    renderSteps(buffer, pass, step, step + 1, control);
}

void ProgressiveRenderer::renderSteps(AccumulationBuffer& buffer, uint32_t pass, int firstStep,
                                      int endStep, const StepControl& control) {
    const int width = camera_.width();
    const int height = camera_.height();
    if (buffer.width() != width || buffer.height() != height) {
        throw Error("accumulation buffer and camera differ in size");
    }
    if (firstStep < 0 || firstStep >= endStep || endStep > kPathsPerPass) {
        throw Error("renderSteps: bad step range");
    }
    const int endRow = control.endRow < 0 ? height : std::min(control.endRow, height);
    if (control.firstRow < 0 || control.firstRow > endRow) throw Error("renderStep: bad row range");
    const std::atomic<bool>* cancel = control.cancel;
    const std::vector<uint8_t>* skip = control.skip;
    // A pixel's paths share its streams (path_samples.h) when it gets more than one in this call
    // (the viewer renders the image's first step alone).
    const bool shareStreams = endStep - firstStep > 1;
    const bool lens = camera_.hasLens();
    const int depth = settings_.integrator.depth;
    arena_->execute([&] {
        tbb::parallel_for(
            tbb::blocked_range2d<int>(control.firstRow, endRow, kTileSize, 0, width, kTileSize),
            handedOff([&](const tbb::blocked_range2d<int>& tile) {
                if (cancel && cancel->load(std::memory_order_relaxed)) return;
                // Denormals are never needed for radiance; flushing them keeps every thread fast.
                _MM_SET_FLUSH_ZERO_MODE(_MM_FLUSH_ZERO_ON);
                _MM_SET_DENORMALS_ZERO_MODE(_MM_DENORMALS_ZERO_ON);
                uint64_t rays = 0;
                uint64_t paths = 0;
                // The tile's paths, pixel by pixel and step by step, go to the integrator in
                // batches, which it traces together (path_integrator.h).
                std::vector<size_t> batchPixels;
                std::vector<PathSamples> batchSamples;
                // The streams of the batch's pixels, which their samples point to: reserved for a
                // whole batch, so that none moves while the batch is filled.
                std::vector<PixelStreams> batchStreams;
                batchStreams.reserve(PathIntegrator::kBatch);
                std::vector<Ray> cameraRays;
                std::vector<float> imageHeights;  // the camera rays': 0 at the top edge, 1 at the bottom
                std::vector<glm::vec3> radiance(PathIntegrator::kBatch);
                std::array<bool, PathIntegrator::kBatch> onSurface;
                const auto traceBatch = [&] {
                    integrator_.radiance(cameraRays, batchSamples, std::span(radiance.data(), cameraRays.size()),
                                         rays, std::span(onSurface.data(), cameraRays.size()));
                    for (size_t k = 0; k < cameraRays.size(); ++k) {
                        if (!onSurface[k] && !backdrop_.showsEnvironment()) {
                            radiance[k] = backdrop_.radiance(imageHeights[k]);
                        }
                        buffer.addSample(batchPixels[k], radiance[k], onSurface[k]);
                        const bool lastStep = batchSamples[k].step() + 1 == kPathsPerPass;
                        if (lastStep) buffer.completePass(batchPixels[k]);
                    }
                    paths += cameraRays.size();
                    batchPixels.clear();
                    batchSamples.clear();
                    batchStreams.clear();
                    cameraRays.clear();
                    imageHeights.clear();
                };
                for (int y = tile.rows().begin(); y != tile.rows().end(); ++y) {
                    for (int x = tile.cols().begin(); x != tile.cols().end(); ++x) {
                        const size_t pixel = static_cast<size_t>(y) * width + x;
                        if (skip && (*skip)[pixel]) continue;
                        const PixelStreams* streams = nullptr;
                        for (int step = firstStep; step < endStep; ++step) {
                            if (shareStreams && !streams) {
                                streams = &batchStreams.emplace_back(settings_.seed, pixel, pass, depth);
                            }
                            batchPixels.push_back(pixel);
                            if (streams) {
                                batchSamples.emplace_back(*streams, step);
                            } else {
                                batchSamples.emplace_back(settings_.seed, pixel, pass, step);
                            }
                            const glm::vec2 jitter = batchSamples.back().pixelJitter();
                            cameraRays.push_back(
                                lens ? camera_.generateRay(x, y, jitter, batchSamples.back().lensPoint())
                                     : camera_.generateRay(x, y, jitter));
                            imageHeights.push_back((static_cast<float>(y) + jitter.y) / static_cast<float>(height));
                            if (cameraRays.size() == PathIntegrator::kBatch) {
                                traceBatch();
                                streams = nullptr;
                            }
                        }
                    }
                }
                if (!cameraRays.empty()) traceBatch();
                rays_.fetch_add(rays, std::memory_order_relaxed);
                paths_.fetch_add(paths, std::memory_order_relaxed);
            }),
            tbb::simple_partitioner());
    });
    receiveHandOff();
}

}  // namespace strata
