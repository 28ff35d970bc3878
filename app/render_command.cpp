#include "render_command.h"

#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>

#include "adaptive_sampling.h"
#include "error.h"
#include "image_io.h"
#include "progress.h"
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
    double noiseThreshold = 0.0;
    bool earlyOut = true;

    void run() const;
};

void RenderCommand::run() const {
    if (spp < kPathsPerPass || spp % kPathsPerPass != 0) {
        throw Error("--spp: must be a positive multiple of 24 (one pass = 24 paths per pixel), got " +
                    std::to_string(spp));
    }
    const auto tonemapKind = parseTonemap(tonemap);
    if (!tonemapKind) throw Error("--tonemap: unknown tonemap '" + tonemap + "' (use " + tonemapNames() + ")");
    for (const auto& out : outputs) imageFormatOf(out);  // reject a bad extension before rendering
    if (noiseThreshold < 0.0) throw Error("--noise-threshold: must be at least 0 (0: off)");
    const LoadedScene loaded = render.loadScene();
    const RenderSettings settings = render.renderSettings(loaded);
    const Camera camera = render.makeCamera(loaded);
    std::fprintf(stderr, "%s\n", describeScene(loaded).c_str());
    if (!loaded.scene.mesh().pointLights.empty() && !settings.integrator.nextEventEstimation) {
        std::fprintf(stderr, "note: the scene's point lights need --nee; without it they are dark\n");
    }
    if (outputs.empty()) std::fprintf(stderr, "note: no --out given, no image will be written\n");

    AccumulationBuffer buffer(camera.width(), camera.height());
    ProgressiveRenderer renderer(loaded.scene, camera, settings);
    const auto passes = static_cast<uint32_t>(spp / kPathsPerPass);
    AdaptiveSampling adaptive({noiseThreshold}, buffer.pixelCount());
    const auto dark = whyBlack(loaded.scene, settings.integrator);
    if (dark && earlyOut) {
        // Every path would carry zero: the exact image is black, at no cost.
        std::fprintf(stderr, "the image is black: %s (--no-early-out renders it anyway)\n", dark->c_str());
    }
    ProgressReporter progress("render", passes, kPathsPerPass);
    uint32_t passesDone = 0;
    while (passesDone < passes && !(dark && earlyOut)) {
        renderer.renderPass(buffer, passesDone, adaptive.enabled() ? &adaptive.doneMask() : nullptr);
        ++passesDone;
        progress.update(passesDone, renderer.counters().paths);
        if (adaptive.enabled() && adaptive.update(buffer) == 0) break;
    }
    if (passesDone > 0) progress.finish(passesDone, renderer.counters().paths);
    const double seconds = progress.elapsedSeconds();

    const Image image = Image::fromMeans(buffer);
    for (const auto& out : outputs) {
        writeImage(out, image, PngSettings{exposure, *tonemapKind});
        std::fprintf(stderr, "wrote %s\n", out.c_str());
    }

    const RenderCounters counters = renderer.counters();
    const glm::dvec3 mean = buffer.imageMean();
    if (json) {
        nlohmann::json report{
            {"scene", loaded.objPath.string()},
            {"width", camera.width()},
            {"height", camera.height()},
            {"sampler", samplerName(settings.integrator.sampler)},
            {"depth", settings.integrator.depth},
            {"seed", settings.seed},
            {"threads", renderer.threadCount()},
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
            {"noise_threshold", noiseThreshold},
            {"pixels_done_early", buffer.pixelCount() - adaptive.activePixels()},
            {"mean_spp", static_cast<double>(counters.paths) / buffer.pixelCount()},
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
    sub->add_option("--tonemap", command->tonemap, "PNG tonemap: " + tonemapNames())->capture_default_str();
    sub->add_flag("--json", command->json, "Print a JSON report on stdout");
    sub->add_option("--noise-threshold", command->noiseThreshold,
                    "Adaptive sampling: a pixel stops at this relative standard error (0: off)")
        ->capture_default_str();
    sub->add_flag("!--no-early-out", command->earlyOut,
                  "Render even a scene that cannot be anything but black");
    sub->callback([command] { command->run(); });
}

}  // namespace strata
