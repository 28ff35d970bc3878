#include "render_command.h"

#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>

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

    void run() const;
};

void RenderCommand::run() const {
    if (spp < kPathsPerPass || spp % kPathsPerPass != 0) {
        throw Error("--spp: must be a positive multiple of 24 (one pass = 24 paths per pixel), got " +
                    std::to_string(spp));
    }
    const auto tonemapKind = parseTonemap(tonemap);
    if (!tonemapKind) throw Error("--tonemap: unknown tonemap '" + tonemap + "' (use clamp|reinhard|aces)");
    for (const auto& out : outputs) imageFormatOf(out);  // reject a bad extension before rendering
    const RenderSettings settings = render.renderSettings();
    const LoadedScene loaded = render.loadScene();
    const Camera camera = render.makeCamera(loaded);
    std::fprintf(stderr, "%s\n", describeScene(loaded).c_str());
    if (!loaded.scene.mesh().pointLights.empty() && !settings.integrator.nextEventEstimation) {
        std::fprintf(stderr, "note: the scene's point lights need --nee; without it they are dark\n");
    }
    if (outputs.empty()) std::fprintf(stderr, "note: no --out given, no image will be written\n");

    AccumulationBuffer buffer(camera.width(), camera.height());
    ProgressiveRenderer renderer(loaded.scene, camera, settings);
    const auto passes = static_cast<uint32_t>(spp / kPathsPerPass);
    ProgressReporter progress("render", passes, kPathsPerPass);
    for (uint32_t pass = 0; pass < passes; ++pass) {
        renderer.renderPass(buffer, pass);
        progress.update(pass + 1, renderer.counters().paths);
    }
    progress.finish(passes, renderer.counters().paths);
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
