#include "bench/bench_command.h"

#include <CLI/App.hpp>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <memory>
#include <tbb/info.h>

#include "bench/bench_convergence.h"
#include "bench/bench_cycles.h"
#include "bench/bench_output.h"
#include "bench/bench_peer.h"
#include "bench/bench_ranks.h"
#include "bench/bench_real_scenes.h"
#include "bench/bench_throughput.h"
#include "bench/bench_viewer.h"
#include "bundled_assets.h"
#include "usage.h"
#include "sampling/direction_sampler.h"
#include "util/error.h"
#include "integrator/progressive_renderer.h"
#include "io/output_file.h"

namespace strata {
namespace {

namespace fs = std::filesystem;

struct BenchCommand {
    std::vector<std::string> scenes;
    bool quick = false;
    std::string outDir = "bench-out";
    std::vector<int> depths{5};
    bool depthsGiven = false;  // --depth was given; otherwise the Embree race runs at two lengths
    int width = 0;
    int maxSpp = 0;
    double maxSeconds = 60.0;
    bool makeReference = false;
    std::string reference;
    int referenceSpp = 0;
    bool vsEmbree = false;
    bool vsCycles = false;
    std::vector<std::string> cyclesSceneNames;  // empty: every scene of cyclesScenes()
    bool skipThroughput = false;
    bool skipRealScenes = false;
    bool allowOutsideFiles = false;
    std::string only;  // one section of kSections; empty: all that the other options select
    uint64_t seed = 0;
    int threads = 0;

    void run() const;
    // Whether the run includes `section` (one of kSections), selected by default unless `skipped`.
    bool runs(const std::string& section, bool skipped = false) const {
        return only.empty() ? !skipped : only == section;
    }
};

// The sections `--only` can pick, as the summary orders them.
const std::vector<std::string> kSections = {"errors", "throughput", "embree", "cycles", "viewer", "real-scenes", "ranks"};

// The shared scene collection: an optional extra for the full suite, read when the working
// directory has a sibling shared/ (a checkout beside the collection, run from its root).
const fs::path kSharedScenes = fs::path("..") / "shared" / "scenes";

// The Cornell box the speed sections measure: the shared collection's in the full suite when it
// is there, else the bundled one.
fs::path cornellBox(bool quick) {
    const fs::path shared = kSharedScenes / "cornell" / "scene.obj";
    return (!quick && fs::is_regular_file(shared)) ? shared : bundledScene("cornell");
}

struct CyclesScene {
    std::string name;  // for --vs-cycles-scene and the folder vs-cycles-NAME
    CyclesBenchSettings settings;
};

// The scenes `--vs-cycles` sets Strata against Cycles on: the Cornell box with every lever, then
// real models, one kind of input each, with the levers that tell something on them.
std::vector<CyclesScene> cyclesScenes(bool quick) {
    const fs::path wuson = kAssimpModels / "OBJ" / "WusonOBJ.obj";
    const auto scene = [](std::string name, fs::path file, CyclesLevers levers) {
        CyclesScene s{std::move(name), {}};
        s.settings.scene = std::move(file);
        s.settings.levers = levers;
        return s;
    };
    std::vector<CyclesScene> scenes;
    scenes.push_back(scene("cornell", cornellBox(quick), CyclesLevers::All));
    // Smooth normals, no material, a uniform sky.
    scenes.push_back(scene("WusonOBJ", wuson, CyclesLevers::All));
    scenes.back().settings.sky = glm::vec3(1.0f);
    // Five JPEG textures times Kd, smooth normals.
    scenes.push_back(scene("spider", kAssimpModels / "OBJ" / "spider.obj", CyclesLevers::Few));
    scenes.back().settings.sky = glm::vec3(1.0f);
    // An HDR map with a small sun.
    scenes.push_back(scene("WusonOBJ-sun-sky", wuson, CyclesLevers::Few));
    scenes.back().settings.environmentMap = bundledAssetsDir() / "sky" / "sun-sky.exr";
    // glTF, GGX: every material white metal (what Cycles' Glossy BSDF matches exactly).
    scenes.push_back(scene("2CylinderEngine-metal",
                           kAssimpModels / "glTF2" / "2CylinderEngine-glTF-Binary" / "2CylinderEngine.glb",
                           CyclesLevers::Few));
    scenes.back().settings.sky = glm::vec3(1.0f);
    scenes.back().settings.whiteMetalRoughness = 0.3f;
    // Hundreds of emissive panels: the light sampler's scene.
    scenes.push_back(scene("many-lights", bundledAssetsDir() / "many-lights" / "many-lights.obj", CyclesLevers::Few));
    return scenes;
}

// Every FOLDER/*/*.obj, sorted.
std::vector<fs::path> scenesIn(const fs::path& folder) {
    std::vector<fs::path> found;
    if (!fs::is_directory(folder)) return found;
    for (const auto& dir : fs::directory_iterator(folder)) {
        if (!dir.is_directory()) continue;
        for (const auto& file : fs::directory_iterator(dir.path())) {
            if (file.path().extension() == ".obj") found.push_back(file.path());
        }
    }
    std::sort(found.begin(), found.end());
    return found;
}

// Every sampler the renderer offers (direction_sampler.h), so new ones are benchmarked too.
std::vector<std::string> allSamplers() {
    std::vector<std::string> names;
    const std::string list = samplerNames();
    size_t start = 0;
    while (start <= list.size()) {
        const size_t bar = std::min(list.find('|', start), list.size());
        names.push_back(list.substr(start, bar - start));
        start = bar + 1;
    }
    return names;
}

std::string cpuModel() {
    std::ifstream in("/proc/cpuinfo");
    for (std::string line; std::getline(in, line);) {
        if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
    }
    return "unknown CPU";
}

// The 1-minute load average: on a shared machine it says how much the figures are inflated.
double loadAverage() {
    double load[1] = {0.0};
    return getloadavg(load, 1) == 1 ? load[0] : -1.0;
}

std::string utcNow() {
    const std::time_t now = std::time(nullptr);
    char text[64];
    std::strftime(text, sizeof text, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
    return text;
}

void BenchCommand::run() const {
    if (width < 0 || width > 65536) throw UsageError("--width: must be in 0..65536 (0: 96, or 48 with --quick)");
    if (maxSpp < 0 || maxSpp % kPathsPerPass != 0) {
        throw UsageError("--max-spp: must be a positive multiple of 24 (0: 384)");
    }
    if (referenceSpp < 0 || referenceSpp % kPathsPerPass != 0) {
        throw UsageError("--reference-spp: must be a positive multiple of 24 (0: 16 x --max-spp)");
    }
    if (!(maxSeconds > 0.0 && maxSeconds <= 1e7)) throw UsageError("--max-seconds: must be in (0, 1e7]");
    if (threads < 0 || threads > 1024) throw UsageError("--threads: must be in 0..1024 (0: all cores)");
    for (int d : depths) {
        if (d < 0 || d > 1000) throw UsageError("--depth: must be in 0..1000");
    }
    if (!only.empty() && std::find(kSections.begin(), kSections.end(), only) == kSections.end()) {
        std::string known;
        for (const auto& name : kSections) known += (known.empty() ? "" : "|") + name;
        throw UsageError("--only: unknown section '" + only + "' (use " + known + ")");
    }
    if (!reference.empty() && !fs::is_regular_file(reference)) {
        throw Error("--reference " + reference + ": no such file");
    }
    const int benchWidth = width > 0 ? width : (quick ? 48 : 96);
    const int lastSpp = maxSpp > 0 ? maxSpp : 24 * 16;
    const int refSpp = referenceSpp > 0 ? referenceSpp : 16 * lastSpp;
    const fs::path bundled = scenes.empty() ? bundledAssetsDir() : fs::path();
    const fs::path out = outDir;
    // Made when missing, and proved writable before the first run rather than after it.
    std::error_code made;
    fs::create_directories(out, made);
    if (made) throw Error("--out-dir: " + out.string() + ": cannot create the folder: " + made.message());
    try {
        requireWritable(out / "summary.md");
    } catch (const Error& e) {
        throw Error(std::string("--out-dir: ") + e.what());
    }
    const auto start = std::chrono::steady_clock::now();
    const double startLoad = loadAverage();

    ConvergenceSettings convergence;
    if (!scenes.empty()) {
        for (const auto& s : scenes) convergence.scenes.emplace_back(s);
    } else {
        // CI's quick run keeps to the bundled Cornell box and furnace, whose curves settle at its
        // budgets (the glass box's caustic does not); the full run adds every bundled scene, the
        // glossy and glass ones among them, and every shared one.
        for (const auto& s : scenesIn(bundled)) {
            const auto name = s.stem().string();
            if (!quick || name == "cornell" || name == "furnace") convergence.scenes.push_back(s);
        }
        if (!quick) {
            for (const auto& s : scenesIn(kSharedScenes)) convergence.scenes.push_back(s);
        }
    }
    convergence.samplers = allSamplers();
    convergence.depths = depths;
    convergence.width = benchWidth;
    convergence.maxPasses = static_cast<uint32_t>(lastSpp / kPathsPerPass);
    convergence.maxSeconds = maxSeconds;
    convergence.referencePasses = static_cast<uint32_t>(refSpp / kPathsPerPass);
    convergence.makeReference = makeReference || quick;  // quick references are small and cheap
    if (!reference.empty()) convergence.referenceFile = fs::path(reference);
    convergence.seed = seed;
    convergence.files.allowOutsideFiles = allowOutsideFiles;
    convergence.skips = true;
    convergence.threads = threads;
    convergence.outDir = out;

    const int threadCount = threads > 0 ? threads : tbb::info::default_concurrency();
    std::string summary = "# strata bench" + std::string(quick ? " --quick" : "") +
                          (only.empty() ? "" : " --only " + only) + "\n\n" + utcNow() + ", " + cpuModel() +
                          ", " + threadsText(threadCount) + cell(", load average %.2f at the start", startLoad) +
                          ".\n\n";
    if (runs("errors")) {
        const auto convergenceRuns = runConvergence(convergence);
        summary += convergenceSummary(convergenceRuns) + "\n" + skipsSummary(convergenceRuns);
    }

    if (runs("throughput", skipThroughput)) {
        ThroughputSettings throughput;
        throughput.scene = !scenes.empty() ? fs::path(scenes.front()) : cornellBox(quick);
        throughput.depth = depths.front();
        throughput.threads = threads;
        throughput.quick = quick;
        throughput.seed = seed;
        throughput.outDir = out;
        summary += "\n" + runThroughput(throughput);
    }
    if (runs("embree", !vsEmbree)) {
        // Path lengths 6 and 9 unless --depth says otherwise: the longer one weighs the cost per
        // bounce, the shorter the cost per path (camera ray, samples, accumulation) more.
        PeerSettings peer;
        peer.scene = kSharedScenes / "cornell_point" / "scene.obj";
        peer.spp = quick ? 24 : 96;
        peer.repeats = quick ? 1 : 3;
        peer.threads = threads;
        peer.outDir = out;
        for (int depth : depthsGiven || quick ? std::vector<int>{depths.front()} : std::vector<int>{6, 9}) {
            peer.depth = depth;
            summary += runPeerComparison(peer);
        }
    }
    if (runs("cycles", !vsCycles)) {
        std::string ratios;
        for (const CyclesScene& scene : cyclesScenes(quick)) {
            if (!cyclesSceneNames.empty() && std::find(cyclesSceneNames.begin(), cyclesSceneNames.end(),
                                                       scene.name) == cyclesSceneNames.end()) {
                continue;
            }
            CyclesBenchSettings peer = scene.settings;
            peer.repeats = quick ? 1 : 3;
            peer.threads = threads;
            peer.seed = seed;
            // Each real scene in a folder of its own: its files and cached reference apart.
            peer.outDir = scene.name == "cornell" ? out : out / ("vs-cycles-" + scene.name);
            if (!fs::is_regular_file(peer.scene)) {
                summary += "\nSkipped Cycles on " + scene.name + ": " + peer.scene.string() + " is missing" +
                           (peer.scene.string().starts_with(kAssimpModels.string())
                                ? " (apt-get install assimp-testmodels).\n"
                                : ".\n");
                continue;
            }
            const CyclesComparison comparison = runCyclesComparison(peer);
            summary += comparison.markdown;
            for (const CyclesRatio& r : comparison.ratios) {
                ratios += "| " + scene.name + " | " + std::to_string(r.cyclesSpp) + " | " + cell("%.2f", r.sameSpp) +
                          " | " + (r.equalTime > 0.0 ? cell("%.2f", r.equalTime) : std::string("-")) + " |\n";
            }
        }
        if (!ratios.empty()) {
            summary += "\n### Against Blender's Cycles: every scene\n\nrelMSE x seconds of Strata's defaults "
                       "over Cycles' (below 1 favours Strata):\n\n| scene | Cycles spp | same spp | equal time "
                       "|\n|---|---|---|---|\n" + ratios;
        }
    }
    if (runs("viewer", skipThroughput)) {
        ViewerBenchSettings viewer;
        viewer.scene = scenes.empty() ? bundledScene("cornell") : fs::path(scenes.front());
        viewer.depth = depths.front();
        viewer.threads = threads;
        viewer.outDir = out;
        if (quick) {
            viewer.spp = 48;  // start-up, the same for any length, weighs more than in the full run
            viewer.uiFrames = 60;
            viewer.repeats = 1;
        }
        summary += runViewerComparison(viewer);
    }
    if (runs("real-scenes", skipRealScenes)) {
        RealScenesSettings real;
        real.baseline = cornellBox(quick);
        real.depth = depths.front();
        real.threads = threads;
        real.outDir = out;
        if (quick) {
            real.width = 96;
            real.height = 72;
            real.ratePasses = 1;
            real.repeats = 1;
            real.viewerWidth = 640;
            real.viewerHeight = 360;
        }
        summary += runRealScenes(real);
    }
    if (runs("ranks", quick)) {
        RankSettings ranks;
        ranks.scene = bundledScene("cornell");
        ranks.depth = depths.front();
        ranks.threads = threads;
        ranks.outDir = out;
        summary += runRankComparison(ranks);
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    summary += cell("\nBench wall time: %.1f s. Files: %s/ (CSV per run, PNG plots).\n", seconds,
                    out.string().c_str());
    writeFile(out / "summary.md", summary);
    std::printf("%s", summary.c_str());
}

}  // namespace

void addBenchCommand(CLI::App& app) {
    auto command = std::make_shared<BenchCommand>();
    CLI::App* sub = app.add_subcommand(
        "bench", "Measure error against time, and throughput");
    sub->add_option("scenes", command->scenes,
                    "Scenes (.obj); default: the bundled scenes, and ../shared/scenes/*/ when present");
    sub->add_flag("--quick", command->quick,
                  "Small sizes and budgets: the CI smoke run, about 40 s on 2 idle cores");
    sub->add_option("--out-dir", command->outDir, "Folder for CSV, markdown and plots")->capture_default_str();
    CLI::Option* depth = sub->add_option("--depth", command->depths,
                                         "Recursion depth(s) K (repeatable); the Embree race's default: 6 and 9")
                             ->capture_default_str();
    sub->add_option("--width", command->width, "Image width of the error runs (default 96; quick 48)");
    sub->add_option("--max-spp", command->maxSpp, "Last checkpoint, a multiple of 24 (default 384)");
    sub->add_option("--max-seconds", command->maxSeconds, "Time budget per run (stops at the next checkpoint)")
        ->capture_default_str();
    sub->add_flag("--make-reference", command->makeReference,
                  "Render missing references (EXR keyed by a hash of scene, camera and depth)");
    sub->add_option("--reference", command->reference, "Reference EXR to compare against (one scene)");
    sub->add_option("--reference-spp", command->referenceSpp, "Reference spp (default 16x --max-spp)");
    sub->add_flag("--vs-embree", command->vsEmbree,
                  "Also race Embree's tutorial pathtracer on ../shared/scenes/cornell_point");
    sub->add_flag("--vs-cycles", command->vsCycles,
                  "Also set Strata against Blender's Cycles on the Cornell box and real models: textured, "
                  "under an HDR map, glossy glTF (needs blender)");
    sub->add_option("--vs-cycles-scene", command->cyclesSceneNames,
                    "Only these scenes of --vs-cycles (repeatable): cornell, WusonOBJ, spider, WusonOBJ-sun-sky, "
                    "2CylinderEngine-metal, many-lights");
    sub->add_flag("--skip-throughput", command->skipThroughput, "Only the error runs");
    sub->add_flag("--skip-real-scenes", command->skipRealScenes,
                  "Leave out the real scenes (assimp-testmodels: load, BVH build, first image, memory)");
    sub->add_option("--only", command->only,
                    "Run this section alone, whatever the other options leave out: errors, throughput, "
                    "embree (--vs-embree), cycles (--vs-cycles), viewer, real-scenes or ranks");
    sub->add_flag("--allow-outside-files", command->allowOutsideFiles,
                  "Read the files the scenes refer to also outside their folders (your own scenes only)");
    acceptUnsigned64(*sub->add_option("--seed", command->seed, "Random seed")->capture_default_str());
    sub->add_option("--threads", command->threads, "Render threads (0: all cores)")->capture_default_str();
    sub->callback([command, depth] {
        command->depthsGiven = depth->count() > 0;
        command->run();
    });
}

}  // namespace strata
