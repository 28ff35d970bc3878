#include "render_command.h"

#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <nlohmann/json.hpp>

#include "error.h"
#include "image_io.h"
#include "pass_partition.h"
#include "progress.h"
#include "render_job.h"
#include "render_options.h"

namespace strata {
namespace {

struct RenderCommand {
    RenderOptions render;
    int spp = 240;
    std::vector<std::string> outputs;
    float exposure = 0.0f;
    std::string tonemap = "clamp";
    bool json = false;

    struct Checked {
        RenderSettings settings;
        Tonemap tonemap;
    };
    Checked checkOptions() const;
    void run() const;
};

RenderCommand::Checked RenderCommand::checkOptions() const {
    if (spp < kPathsPerPass || spp % kPathsPerPass != 0) {
        throw Error("--spp: must be a positive multiple of 24 (one pass = 24 paths per pixel), got " +
                    std::to_string(spp));
    }
    const auto tonemapKind = parseTonemap(tonemap);
    if (!tonemapKind) throw Error("--tonemap: unknown tonemap '" + tonemap + "' (use clamp|reinhard|aces)");
    for (const auto& out : outputs) imageFormatOf(out);  // reject a bad extension before rendering
    return {render.renderSettings(), *tonemapKind};
}

void RenderCommand::run() const {
    // Under mpirun the ranks split the passes (render_job.h); every step that can fail runs on all
    // ranks at once, so a failure anywhere ends the job there, reported once by rank 0.
    RenderJob job;
    const auto [settings, tonemapKind] = job.collectively([&] { return checkOptions(); });
    const SceneFiles files = job.shareSceneFiles([&] { return render.readSceneFiles(); });
    const LoadedScene loaded = job.collectively([&] { return parseScene(files); });
    const Camera camera = job.collectively([&] { return render.makeCamera(loaded); });
    if (job.isRoot()) {
        std::fprintf(stderr, "%s\n", describeScene(loaded).c_str());
        if (!loaded.scene.mesh().pointLights.empty() && !settings.integrator.nextEventEstimation) {
            std::fprintf(stderr,
                         "note: the scene's point lights need --nee; without it they are dark\n");
        }
        if (outputs.empty()) {
            std::fprintf(stderr, "note: no --out given, no image will be written\n");
        }
    }

    const auto passes = static_cast<uint32_t>(spp / kPathsPerPass);
    const PassRange mine = passesOfRank(passes, job.rank(), job.ranks());
    AccumulationBuffer buffer =
        job.collectively([&] { return AccumulationBuffer(camera.width(), camera.height()); });
    ProgressiveRenderer renderer(loaded.scene, camera, settings);
    // mpirun binds each rank to a core (for 2 ranks or fewer) or a socket unless told otherwise,
    // and TBB keeps to the cores a process may use: say so when that leaves cores idle.
    if (job.underMpi() && job.isRoot() && settings.threads == 0 &&
        renderer.threadCount() < static_cast<int>(std::thread::hardware_concurrency())) {
        std::fprintf(stderr,
                     "note: rank 0 renders with %d of its host's %u hardware threads because "
                     "mpirun bound it to fewer cores; run mpirun with --bind-to none to use them "
                     "all\n",
                     renderer.threadCount(), std::thread::hardware_concurrency());
    }
    // Rank 0 reports the progress of its own passes: it has the largest share and the ranks run
    // alike, so its share is the job's progress, but only an estimate of it; the label says so.
    const std::string label = job.ranks() == 1
        ? "render"
        : "render, rank 0's share (passes " + std::to_string(mine.begin + 1) + "-" +
              std::to_string(mine.end) + " of " + std::to_string(passes) + ")";
    std::optional<ProgressReporter> progress;
    if (job.isRoot()) progress.emplace(label, mine.size(), kPathsPerPass);
    job.collectively([&] {
        for (uint32_t pass = mine.begin; pass < mine.end; ++pass) {
            renderer.renderPass(buffer, pass);
            if (progress) progress->update(pass - mine.begin + 1, renderer.counters().paths);
        }
    });
    if (progress) progress->finish(mine.size(), renderer.counters().paths);
    RenderCounters counters = renderer.counters();
    job.reduce(buffer, counters);
    if (!job.isRoot()) return;
    const double seconds = progress->elapsedSeconds();
    if (job.ranks() > 1) {
        std::fprintf(stderr,
                     "render: %u passes (%d spp) on %d ranks in %.1fs, %.2f Msamples/s for the "
                     "whole job\n",
                     passes, spp, job.ranks(), seconds, counters.paths / seconds * 1e-6);
    }

    const Image image = Image::fromMeans(buffer);
    for (const auto& out : outputs) {
        writeImage(out, image, PngSettings{exposure, tonemapKind});
        std::fprintf(stderr, "wrote %s\n", out.c_str());
    }

    const glm::dvec3 mean = buffer.imageMean();
    if (json) {
        nlohmann::json report{
            {"scene", loaded.objPath.string()},
            {"width", camera.width()},
            {"height", camera.height()},
            {"sampler", samplerName(settings.integrator.sampler)},
            {"depth", settings.integrator.depth},
            {"seed", settings.seed},
            {"ranks", job.ranks()},
            {"threads", renderer.threadCount()},  // per rank
            {"seconds", seconds},
            {"spp", spp},
            {"passes", passes},
            {"paths", counters.paths},
            {"rays", counters.rays},
            {"paths_per_second", counters.paths / seconds},
            {"rays_per_second", counters.rays / seconds},
            {"mean_rgb", {mean.x, mean.y, mean.z}},
            {"nonfinite_samples", buffer.droppedSamples()},
            {"outputs", outputs},
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
    CLI::App* sub = app.add_subcommand("render", "Render a scene headless, progressively, to image files");
    command->render.addTo(*sub, true);
    sub->add_option("--spp", command->spp, "Samples per pixel, a multiple of 24")->capture_default_str();
    sub->add_option("--out", command->outputs, "Output image(s): .exr/.pfm linear, .png sRGB (repeatable)");
    sub->add_option("--exposure", command->exposure, "PNG exposure in stops")->capture_default_str();
    sub->add_option("--tonemap", command->tonemap, "PNG tonemap: clamp|reinhard|aces")->capture_default_str();
    sub->add_flag("--json", command->json, "Print a JSON report on stdout");
    sub->callback([command] { command->run(); });
}

}  // namespace strata
