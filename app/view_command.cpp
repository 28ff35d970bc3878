#include "view_command.h"

#include <CLI/App.hpp>
#include <cmath>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>

#include "bench/process_memory.h"
#include "io/auto_exposure.h"
#include "io/image_io.h"
#include "util/error.h"
#include "render_options.h"
#include "usage.h"
#include "viewer_run.h"

namespace strata {
namespace {

struct ViewCommand {
    RenderOptions render;
    std::string headless;  // "" windowed; "auto", "egl" or "osmesa" offscreen
    int frames = 0;
    std::string screenshot;
    std::string reference;
    std::vector<int> window{1280, 720};
    bool split = true;
    int targetSpp = 0;
    float targetSeconds = 0.0f;
    float scale = 1.0f;
    std::optional<float> exposure;  // unset: auto (io/auto_exposure.h), or 0 under the clamp
    std::string tonemap = std::string(tonemapName(kDefaultTonemap));
    bool json = false;

    void run() const;
};

void ViewCommand::run() const {
    if (targetSpp < 0) throw UsageError("--target-spp: must be at least 0 (0: no limit)");
    if (!(targetSeconds >= 0.0f && targetSeconds <= 1e7f)) {
        throw UsageError("--target-seconds: must be in 0..1e7 (0: no limit)");
    }
    if (frames < 0) throw UsageError("--frames: must be at least 0");
    if (!(scale >= 0.05f && scale <= 1.0f)) throw UsageError("--scale: must be in 0.05..1");
    const auto tonemapKind = parseTonemap(tonemap);
    if (!tonemapKind) throw UsageError("--tonemap: unknown tonemap '" + tonemap + "' (use " + tonemapNames() + ")");
    if (exposure && !(std::abs(*exposure) <= kExposureLimit)) {
        const std::string limit = std::to_string(static_cast<int>(kExposureLimit));
        throw UsageError("--exposure: must be in -" + limit + ".." + limit + " stops");
    }
    const BackdropSetting backdrop = render.backdrop();
    // EXR maps, the --reference image and saved images are decoded and encoded on the render's
    // threads.
    setExrThreads(render.threadCount());
    if (!screenshot.empty()) {
        if (frames == 0) throw UsageError("--screenshot needs --frames N");
        if (checkOutputOption("--screenshot", screenshot) != ImageFormat::Png) {
            throw UsageError("--screenshot: " + screenshot + ": must be a .png file");
        }
    }

    // Decoded once: the map lights the first scene and stays in the settings for the scenes
    // opened after it.
    Environment environment;
    auto scene = std::make_shared<LoadedScene>(render.parseScene(render.readSceneBundle(), &environment));
    const RenderSettings settings = render.renderSettings(scene->scene);
    std::fprintf(stderr, "%s\n%s", describeScene(*scene).c_str(), describeWarnings(*scene).c_str());
    if (scene->scene.lights().litByDefault()) {
        std::fprintf(stderr, "note: %s\n", defaultEnvironmentNote(scene->scene.lights()).c_str());
    }
    std::shared_ptr<const Image> referenceImage;
    if (!reference.empty()) referenceImage = std::make_shared<const Image>(readExr(reference));

    viewer::ViewerSettings viewerSettings;
    viewerSettings.environment = environment;
    viewerSettings.traversal = render.watertight ? Traversal::Watertight : Traversal::Automatic;
    viewerSettings.files = render.readOptions();
    viewerSettings.budget = render.sceneBudget();
    viewerSettings.split = split;
    viewerSettings.single = {settings.integrator.sampler, settings.integrator.depth};
    for (auto& half : viewerSettings.halves) half.depth = settings.integrator.depth;
    viewerSettings.nextEventEstimation = settings.integrator.nextEventEstimation;
    viewerSettings.rouletteDepth = settings.integrator.rouletteDepth;
    viewerSettings.lightSampler = settings.integrator.lightSampler;
    viewerSettings.terminatorOffset = settings.integrator.terminatorOffset;
    if (render.epsilon) {
        viewerSettings.depthFromEpsilon = true;
        viewerSettings.epsilon = static_cast<float>(*render.epsilon);
    }
    viewerSettings.seed = settings.seed;
    viewerSettings.threads = settings.threads;
    viewerSettings.targetSpp = targetSpp;
    viewerSettings.targetSeconds = targetSeconds;
    viewerSettings.noiseThreshold = static_cast<float>(settings.adaptive.threshold);
    viewerSettings.resolutionScale = scale;
    viewerSettings.display.exposure = exposure.value_or(0.0f);
    viewerSettings.display.tonemap = *tonemapKind;
    viewerSettings.autoExposure = !exposure && *tonemapKind != Tonemap::Clamp;
    viewerSettings.backdrop = backdrop;

    viewer::ViewRunOptions run;
    run.headless = !headless.empty();
    if (run.headless) run.backend = viewer::parseOffscreenBackend(headless);
    run.width = window.at(0);
    run.height = window.at(1);
    run.frames = frames;
    if (!screenshot.empty()) run.screenshot = screenshot;
    // The image has the window less the panel beside it; --width/--height set the image instead,
    // and the window is made that much wider than it.
    if (render.width) {
        if (*render.width < 1 || *render.width > 65536) throw UsageError("--width: must be in 1..65536");
        run.width = *render.width + static_cast<int>(viewer::kPanelWidth);
    }
    if (render.height) {
        if (*render.height < 1 || *render.height > 65536) throw UsageError("--height: must be in 1..65536");
        run.height = *render.height;
    }

    const viewer::ViewRunReport report = viewer::runViewer(scene, viewerSettings, referenceImage, run);
    if (!screenshot.empty()) std::fprintf(stderr, "wrote %s\n", screenshot.c_str());
    if (!json) return;
    const auto* last = report.last.get();
    nlohmann::json sides = nlohmann::json::array();
    if (last) {
        for (size_t i = 0; i < last->sides.size(); ++i) {
            const auto& side = last->sides[i];
            const auto config = viewerSettings.sides().at(i);
            sides.push_back({{"sampler", samplerName(config.sampler)},
                             {"depth", config.depth},
                             {"render_seconds", side.seconds},
                             {"error", side.history.empty() ? nlohmann::json(nullptr)
                                                            : nlohmann::json(side.history.back().error)}});
        }
    }
    const double renderSeconds = last ? last->totalRenderSeconds : 0.0;
    const nlohmann::json out{
        {"scene", scene->scenePath().string()},
        {"context", report.context},
        {"width", run.width},  // the window's
        {"height", run.height},
        {"image_width", last && !last->sides.empty() ? last->sides[0].image.width : 0},
        {"image_height", last && !last->sides.empty() ? last->sides[0].image.height : 0},
        {"frames", report.frameSeconds.size()},
        {"frame_ms_p50", 1e3 * viewer::percentile(report.frameSeconds, 50.0)},
        {"frame_ms_p95", 1e3 * viewer::percentile(report.frameSeconds, 95.0)},
        {"wall_seconds", report.wallSeconds},
        {"spp", last ? last->spp : 0},
        {"passes", last ? last->passes : 0},
        {"paths", last ? last->totalPaths : 0},
        {"render_seconds", renderSeconds},
        {"msamples_per_second", renderSeconds > 0.0 && last ? last->totalPaths / renderSeconds * 1e-6 : 0.0},
        {"msamples_per_wall_second", last ? last->totalPaths / report.wallSeconds * 1e-6 : 0.0},
        {"error_against_reference", last && last->againstReference},
        {"sides", sides},
        {"peak_rss_mib", peakResidentKiB() / 1024.0},  // this process's own (process_memory.h)
    };
    std::printf("%s\n", out.dump().c_str());
}

}  // namespace

void addViewCommand(CLI::App& app) {
    auto command = std::make_shared<ViewCommand>();
    CLI::App* sub = app.add_subcommand(
        "view", "Open the interactive progressive viewer");
    command->render.addTo(*sub);
    sub->add_option("--headless", command->headless,
                    "Run offscreen: egl (surfaceless Mesa) or osmesa; bare --headless tries both")
        ->expected(0, 1)
        ->default_str("auto");
    sub->add_option("--frames", command->frames, "Stop after N UI frames (and once a target is reached, if given)");
    sub->add_option("--screenshot", command->screenshot,
                    "Write the last frame (image + panel) as PNG (.png in any letter case; its folder "
                    "must exist and be writable)");
    sub->add_option("--reference", command->reference, "Reference EXR: the noise plots show RMSE against it");
    sub->add_option("--window", command->window,
                    "Window size W H; the image has it less the panel (--width/--height set the image)")
        ->expected(2)
        ->capture_default_str();
    sub->add_flag("--split,!--no-split", command->split, "Split view: uniform left, strata24 right");
    sub->add_option("--target-spp", command->targetSpp, "Stop rendering at this spp (0: no limit)")
        ->capture_default_str();
    sub->add_option("--target-seconds", command->targetSeconds, "Stop rendering after this much render time (0: no limit)")
        ->capture_default_str();
    sub->add_option("--scale", command->scale,
                    "Render resolution as a fraction of the image area (the window less the panel)")
        ->capture_default_str();
    sub->add_option("--exposure", command->exposure,
                    "Exposure in stops (default: auto, middle grey 0.18 for the first image's "
                    "log-average luminance; 0 with --tonemap clamp)");
    sub->add_option("--tonemap", command->tonemap,
                    tonemapNames() + " (aces: ACES filmic, Narkowicz's fit; clamp: linear, cut at 1)")
        ->capture_default_str();
    sub->add_flag("--json", command->json, "Print frame-time p50/p95 and throughput as JSON on stdout");
    sub->callback([command] { command->run(); });
}

}  // namespace strata
