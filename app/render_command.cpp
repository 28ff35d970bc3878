#include "render_command.h"

#include <CLI/App.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>
#include <nlohmann/json.hpp>

#include "bench/process_memory.h"
#include "util/error.h"
#include "io/auto_exposure.h"
#include "io/image_io.h"
#include "io/output_file.h"
#include "integrator/pass_partition.h"
#include "integrator/render_session.h"
#include "progress.h"
#include "render_job.h"
#include "render_options.h"
#include "usage.h"

namespace strata {
namespace {

struct RenderCommand {
    RenderOptions render;
    int spp = 240;
    std::vector<std::string> outputs;
    std::optional<float> exposure;  // unset: auto (io/auto_exposure.h), or 0 under the clamp
    std::string tonemap = std::string(tonemapName(kDefaultTonemap));
    bool json = false;
    bool earlyOut = true;

    // The checks that need no scene, so a bad option or an output that cannot be written fails
    // before a large scene is read or any pass is rendered.
    Tonemap checkOptions(const RenderJob& job) const;
    void run() const;
};

Tonemap RenderCommand::checkOptions(const RenderJob& job) const {
    if (spp < kPathsPerPass || spp % kPathsPerPass != 0) {
        throw UsageError("--spp: must be a positive multiple of 24 (one pass = 24 paths per pixel), got " +
                         std::to_string(spp));
    }
    const auto tonemapKind = parseTonemap(tonemap);
    if (!tonemapKind) throw UsageError("--tonemap: unknown tonemap '" + tonemap + "' (use " + tonemapNames() + ")");
    if (exposure && !(std::abs(*exposure) <= kExposureLimit)) {
        const std::string limit = std::to_string(static_cast<int>(kExposureLimit));
        throw UsageError("--exposure: must be in -" + limit + ".." + limit + " stops");
    }
    render.backdrop();  // a bad --background before the scene is read
    render.threadCount();  // a bad --threads too
    // Adaptive sampling decides per pixel from all its passes; ranks each hold only some.
    if (render.noiseThreshold > 0.0 && job.ranks() > 1) {
        throw UsageError("--noise-threshold: not available under MPI");
    }
    // Only rank 0 writes: the other ranks' hosts need not have the folder.
    for (const auto& out : outputs) checkOutputOption("--out", out, job.isRoot());
    return *tonemapKind;
}

void RenderCommand::run() const {
    // Under mpirun the ranks split the passes (render_job.h); every step that can fail runs on all
    // ranks at once, so a failure anywhere ends the job there, reported once by rank 0.
    RenderJob job;
    const Tonemap tonemapKind = job.collectively([&] { return checkOptions(job); });
    // An EXR map in the scene is decoded, and the EXR output encoded, on the render's threads.
    setExrThreads(render.threadCount());
    SceneBundle files = job.shareSceneBundle([&] { return render.readSceneBundle(); });
    const LoadedScene loaded = job.collectively([&] { return render.parseScene(std::move(files)); });
    RenderSettings settings = job.collectively([&] { return render.renderSettings(loaded.scene); });
    // Only the image is written: the buffer keeps no pixel's error estimates unless adaptive
    // sampling needs them (render_session.cpp).
    settings.pixelErrors = PixelErrors::NotKept;
    const Camera camera = job.collectively([&] { return render.makeCamera(loaded); });
    const auto dark = whyBlack(loaded.scene, settings.integrator);
    if (job.isRoot()) {
        std::fprintf(stderr, "%s\n%s", describeScene(loaded).c_str(), describeWarnings(loaded).c_str());
        if (loaded.scene.lights().litByDefault()) {
            std::fprintf(stderr, "note: %s\n", defaultEnvironmentNote(loaded.scene.lights()).c_str());
        }
        if (!loaded.scene.mesh().pointLights.empty() && !settings.integrator.nextEventEstimation) {
            std::fprintf(stderr,
                         "note: the scene's point lights need next-event estimation; with --no-nee they are dark\n");
        }
        if (outputs.empty()) {
            std::fprintf(stderr, "note: no --out given, no image will be written\n");
        }
        if (dark && earlyOut) {
            // Every path would carry zero: the exact image is black, at no cost.
            std::fprintf(stderr, "the image is black: %s (--no-early-out renders it anyway)\n",
                         dark->c_str());
        }
    }

    const auto passes = static_cast<uint32_t>(spp / kPathsPerPass);
    const uint32_t passesToRender = dark && earlyOut ? 0 : passes;
    RenderSession session = job.collectively([&] {
        return RenderSession(loaded.scene, camera, settings,
                             passesOfRank(passesToRender, job.rank(), job.ranks()));
    });
    // mpirun binds each rank to a core (for 2 ranks or fewer) or a socket unless told otherwise,
    // and TBB keeps to the cores a process may use: say so when that leaves cores idle.
    if (job.underMpi() && job.isRoot() && settings.threads == 0 &&
        session.threadCount() < static_cast<int>(std::thread::hardware_concurrency())) {
        std::fprintf(stderr,
                     "note: rank 0 renders with %d of its host's %u hardware threads because "
                     "mpirun bound it to fewer cores; run mpirun with --bind-to none to use them "
                     "all\n",
                     session.threadCount(), std::thread::hardware_concurrency());
    }
    // Rank 0 reports the whole job's progress: JobProgress adds up every rank's passes.
    std::optional<ProgressReporter> progress;
    if (job.isRoot()) progress.emplace("render", passesToRender, kPathsPerPass);
    // The PNG's exposure, unless given: from rank 0's first pass, the first pass of the image.
    const bool writesPng = std::any_of(outputs.begin(), outputs.end(), [](const std::string& out) {
        return imageFormatOf(out) == ImageFormat::Png;
    });
    const bool meterExposure = writesPng && !exposure && tonemapKind != Tonemap::Clamp;
    float pngExposure = exposure.value_or(0.0f);
    bool metered = false;
    {
        // Made and destroyed on every rank alike, around (not in) the step that may fail on some.
        JobProgress jobProgress(job);
        job.collectively([&] {
            // The session stops at the end of this rank's passes, or (one process only:
            // checkOptions refuses it under MPI) once adaptive sampling has finished every pixel.
            session.run({}, [&](const PassReport& report) {
                jobProgress.addPass(report.paths);
                if (meterExposure && job.isRoot() && !metered) {
                    pngExposure = autoExposure(session.buffer().meanImage());
                    metered = true;
                }
                if (progress) {
                    const PassTally done = jobProgress.tally();
                    progress->update(done.passes, done.paths);
                }
            });
            jobProgress.flush();
        });
        if (progress) {
            // Once the step has settled, the tally holds every rank's passes.
            const PassTally done = jobProgress.tally();
            if (done.passes > 0) progress->finish(done.passes, done.paths);
        }
    }
    AccumulationBuffer& buffer = session.buffer();
    RenderCounters counters = session.counters();
    job.reduce(buffer, counters);
    if (!job.isRoot()) return;
    const double seconds = progress->elapsedSeconds();
    if (job.ranks() > 1) {
        std::fprintf(stderr,
                     "render: %u passes (%d spp) on %d ranks in %.1fs, %.2f Msamples/s for the "
                     "whole job\n",
                     passes, spp, job.ranks(), seconds, counters.paths / seconds * 1e-6);
    }

    // Every output is encoded before any replaces its file: a failure leaves all of them as they were.
    const Image image = buffer.meanImage();
    if (metered) {
        std::fprintf(stderr, "note: PNG exposure %+.2f stops, from the first pass (--exposure fixes it)\n",
                     pngExposure);
    }
    std::vector<std::unique_ptr<OutputFile>> outputFiles;
    for (const auto& out : outputs) {
        outputFiles.push_back(std::make_unique<OutputFile>(out));
        writeImage(*outputFiles.back(), image, PngSettings{pngExposure, tonemapKind});
    }
    for (const auto& file : outputFiles) {
        file->commit();
        std::fprintf(stderr, "wrote %s\n", file->target().c_str());
    }

    const glm::dvec3 mean = buffer.imageMean();
    if (json) {
        nlohmann::json report{
            {"scene", loaded.scenePath().string()},
            {"width", camera.width()},
            {"height", camera.height()},
            {"sampler", samplerName(settings.integrator.sampler)},
            {"depth", settings.integrator.depth},
            {"nee", settings.integrator.nextEventEstimation},
            {"light_sampler", lightSamplerName(settings.integrator.lightSampler)},
            {"roulette_depth", settings.integrator.rouletteDepth},
            {"terminator_offset", settings.integrator.terminatorOffset},
            {"seed", settings.seed},
            {"ranks", job.ranks()},
            {"threads", session.threadCount()},  // per rank
            {"seconds", seconds},
            {"spp", spp},
            {"passes", passes},
            {"paths", counters.paths},
            {"rays", counters.rays},
            {"paths_per_second", counters.paths / seconds},
            {"rays_per_second", counters.rays / seconds},
            {"mean_rgb", {mean.x, mean.y, mean.z}},
            {"nonfinite_samples", buffer.droppedSamples()},
            {"black_early_out", dark && earlyOut},
            {"noise_threshold", settings.adaptive.threshold},
            {"pixels_done_early", buffer.pixelCount() - session.adaptive().activePixels()},
            {"mean_spp", static_cast<double>(counters.paths) / buffer.pixelCount()},
            {"outputs", outputs},
            {"tonemap", tonemap},
            {"exposure", writesPng ? nlohmann::json(pngExposure) : nlohmann::json()},  // the PNG's
            {"peak_rss_mib", peakResidentKiB() / 1024.0},  // this process's own (process_memory.h)
        };
        std::printf("%s\n", report.dump().c_str());
    } else if (buffer.droppedSamples() > 0) {
        std::fprintf(stderr, "warning: %llu non-finite samples dropped\n",
                     static_cast<unsigned long long>(buffer.droppedSamples()));
    }
}

}  // namespace

void addRenderCommand(CLI::App& app) {
    auto command = std::make_shared<RenderCommand>();
    CLI::App* sub = app.add_subcommand("render", "Render headless, progressively, to image files");
    command->render.addTo(*sub);
    sub->add_option("--spp", command->spp, "Samples per pixel, a multiple of 24")->capture_default_str();
    sub->add_option("--out", command->outputs,
                    "Output image (repeatable): .exr or .pfm linear, .png sRGB, in any letter case; its "
                    "folder must exist and be writable (checked before rendering)");
    sub->add_option("--exposure", command->exposure,
                    "PNG exposure in stops (default: auto, middle grey 0.18 for the first pass's "
                    "log-average luminance; 0 with --tonemap clamp)");
    sub->add_option("--tonemap", command->tonemap,
                    "PNG tonemap: " + tonemapNames() + " (aces: ACES filmic, Narkowicz's fit; clamp: linear, cut at 1)")
        ->capture_default_str();
    sub->add_flag("--json", command->json, "Print a JSON report on stdout");
    sub->add_flag("!--no-early-out", command->earlyOut,
                  "Render even a scene that cannot be anything but black");
    sub->callback([command] { command->run(); });
}

}  // namespace strata
