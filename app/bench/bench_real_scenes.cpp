#include "bench/bench_real_scenes.h"

#include <algorithm>
#include <tbb/info.h>
#include <vector>

#include "bench/bench_output.h"
#include "bench/bench_race.h"
#include "bench/process_memory.h"
#include "bench/render_rate.h"
#include "bench/strata_child.h"
#include "scene/scene_format.h"
#include "io/output_file.h"

namespace strata {
namespace {

namespace fs = std::filesystem;

const std::string kRealScenesTitle = "\n### Real scenes: loading, BVH build, first image, throughput, memory\n\n";

struct RealScene {
    std::string name;
    fs::path path;
};

// The phases before the first path, timed apart in this process: the files read, their format
// parsed into a mesh, the Scene built from it (Embree's BVH, the emitter tables).
struct LoadTiming {
    double readSeconds = 0.0;
    double parseSeconds = 0.0;
    double buildSeconds = 0.0;
    size_t triangles = 0;
};

LoadTiming timeLoading(const RenderOptions& options) {
    LoadTiming timing;
    auto start = Clock::now();
    const SceneBundle bundle = options.readSceneBundle();
    timing.readSeconds = secondsSince(start);
    start = Clock::now();
    MeshData mesh = parseSceneFile(bundle).mesh;
    timing.parseSeconds = secondsSince(start);
    start = Clock::now();
    const Scene scene(std::move(mesh));
    timing.buildSeconds = secondsSince(start);
    timing.triangles = scene.summary().triangles;
    return timing;
}

}  // namespace

std::string runRealScenes(const RealScenesSettings& settings) {
    const fs::path engine = kAssimpModels / "glTF2" / "2CylinderEngine-glTF-Binary" / "2CylinderEngine.glb";
    const fs::path spider = kAssimpModels / "OBJ" / "spider.obj";
    if (!fs::is_regular_file(engine) && !fs::is_regular_file(spider)) {
        return kRealScenesTitle + "Skipped: the models of assimp-testmodels are not installed "
                        "(apt-get install assimp-testmodels).\n";
    }
    std::vector<RealScene> scenes = {{"Cornell box", settings.baseline}};
    std::string missing;
    for (const RealScene& s : {RealScene{"2CylinderEngine", engine}, RealScene{"spider", spider}}) {
        if (fs::is_regular_file(s.path)) {
            scenes.push_back(s);
        } else {
            missing += "Skipped: " + s.path.string() + " not installed (apt-get install assimp-testmodels).\n";
        }
    }

    const int threads = settings.threads > 0 ? settings.threads : tbb::info::default_concurrency();
    RenderOptions options;
    options.sampler = "strata24";
    options.depth = settings.depth;
    options.threads = threads;
    options.width = settings.width;  // one size for all: the same paths per image
    options.height = settings.height;

    // Whole processes, alternated: start-up, loading, the build and the first image, as a user
    // waits for them, from `strata render` and from the viewer (offscreen, its default split
    // view, until one path per pixel of both sides is shown). The viewer's runs race apart: where
    // they cannot run (no offscreen OpenGL, or a sanitizer build stopping on Mesa's leaks), the
    // rest of the section stands.
    std::vector<Entrant> renders, views;
    // The renders' own peak resident sets, from their reports (process_memory.h), per scene.
    std::vector<long> peakKiB(scenes.size(), 0);
    for (size_t k = 0; k < scenes.size(); ++k) {
        const RealScene& s = scenes[k];
        RenderOptions o = options;
        o.scene = s.path.string();
        std::vector<std::string> argv = renderCommandLine(o, settings.spp);
        argv.push_back("--json");
        const auto readPeak = [&peak = peakKiB[k]](const fs::path& log) {
            const long reported = reportedPeakResidentKiB(log);
            peak = std::max(peak, reported);
            return reported >= 0;
        };
        renders.push_back({s.name, std::move(argv), readPeak, {}, {}});
        o.width.reset();  // the viewer's image follows its window
        o.height.reset();
        views.push_back({s.name + " (strata view)",
                         strataCommandLine("view", o,
                                           {"--headless", "--window", std::to_string(settings.viewerWidth),
                                            std::to_string(settings.viewerHeight), "--frames", "1",
                                            "--target-spp", "1"}),
                         {}, {}, {}});
    }
    const fs::path log = settings.outDir / "real-scenes.log";
    if (const auto failed = race(renders, settings.repeats, log, "real scenes")) {
        return kRealScenesTitle + "Skipped: `strata render` of " + *failed + " failed (see " + log.string() + ").\n";
    }
    const fs::path viewLog = settings.outDir / "real-scenes-view.log";
    const auto viewFailed = race(views, settings.repeats, viewLog, "real scenes, viewer");

    Table table{{"scene", "triangles", "read ms", "parse ms", "BVH build ms", "first image s",
                 "viewer first image s", "Mpaths/CPU-s", "vs Cornell box", "peak RSS MiB"}, {}};
    double baselineRate = 0.0;
    for (size_t k = 0; k < scenes.size(); ++k) {
        RenderOptions o = options;
        o.scene = scenes[k].path.string();
        const LoadTiming loading = timeLoading(o);
        const LoadedScene loaded = o.loadScene();
        const RenderRate rate = measureRender(loaded.scene, o.makeCamera(loaded), o,
                                              static_cast<uint32_t>(settings.ratePasses));
        if (k == 0) baselineRate = rate.mpathsPerCpuSecond();
        const Entrant& render = renders[k];
        table.add({scenes[k].name, std::to_string(loading.triangles), cell("%.1f", loading.readSeconds * 1e3),
                   cell("%.1f", loading.parseSeconds * 1e3), cell("%.1f", loading.buildSeconds * 1e3),
                   cell("%.3f", render.medianWall()), viewFailed ? "-" : cell("%.3f", views[k].medianWall()),
                   cell("%.3f", rate.mpathsPerCpuSecond()),
                   cell("%.3f", rate.mpathsPerCpuSecond() / baselineRate), cell("%.1f", peakKiB[k] / 1024.0)});
    }
    writeFile(settings.outDir / "real-scenes.csv", table.csv());
    // cell() formats at most 255 characters: the note is put together from short pieces.
    return kRealScenesTitle +
           cell("%dx%d, depth %d, strata24, %s. ", settings.width, settings.height, settings.depth,
                threadsText(threads).c_str()) +
           "Read, parse and BVH build: in this process, once. " +
           cell("First image: `strata render --spp %d`, the whole process, median of %d alternated "
                "run(s); peak RSS: the largest those runs reported of their own (VmHWM). ",
                settings.spp, settings.repeats) +
           cell("Viewer first image: `strata view --headless --window %d %d --target-spp 1`, the whole "
                "process until both sides of its split view hold one path per pixel, median of %d "
                "alternated run(s)", settings.viewerWidth, settings.viewerHeight, settings.repeats) +
           (viewFailed ? " (not measured: `strata view` of " + *viewFailed + " failed, see " + viewLog.string() + "). "
                       : std::string(". ")) +
           cell("Mpaths/CPU-s: in this process, %d pass(es) after a warm-up. ", settings.ratePasses) +
           "Scenes without lights render under the default white sky.\n\n" +
           table.markdown() + (missing.empty() ? "" : "\n" + missing);
}

}  // namespace strata
