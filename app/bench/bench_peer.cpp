#include "bench/bench_peer.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <tbb/info.h>
#include <vector>

#include "bench/bench_output.h"
#include "bench/bench_race.h"
#include "bench/strata_child.h"
#include "scene/scene_loader.h"
#include "util/error.h"
#include "io/image_io.h"
#include "io/output_file.h"

namespace strata {
namespace {

constexpr const char* kEmbreePathTracer = "pathtracer";

// Mean of an 8-bit binary PPM (P6) as values in [0, 1] per channel.
double ppmMean(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::string magic;
    int width = 0, height = 0, maxValue = 0;
    in >> magic >> width >> height >> maxValue;
    in.get();
    if (!in || magic != "P6" || maxValue != 255 || width <= 0 || height <= 0) {
        throw Error(path.string() + ": not an 8-bit binary PPM");
    }
    std::vector<unsigned char> bytes(size_t(width) * height * 3);
    in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    if (!in) throw Error(path.string() + ": truncated PPM");
    double sum = 0.0;
    for (unsigned char b : bytes) sum += b / 255.0;
    return sum / bytes.size();
}

// Means of a linear EXR: as is, and clamped to [0, 1] as an 8-bit writer would store it.
std::pair<double, double> exrMeans(const std::filesystem::path& path) {
    const Image image = readExr(path);
    double sum = 0.0, clamped = 0.0;
    for (const auto& p : image.pixels) {
        for (int c = 0; c < 3; ++c) {
            sum += p[c];
            clamped += std::clamp(p[c], 0.0f, 1.0f);
        }
    }
    const double n = 3.0 * image.pixels.size();
    return {sum / n, clamped / n};
}

std::string number(double v) { return cell("%.9g", v); }

}  // namespace

std::string runPeerComparison(const PeerSettings& settings) {
    const auto sidecar = std::filesystem::path(settings.scene).replace_extension(".json");
    if (!std::filesystem::is_regular_file(settings.scene) || !std::filesystem::is_regular_file(sidecar)) {
        return "\n### Against Embree's tutorial path tracer\n\nSkipped: " + settings.scene.string() +
               " (or its JSON sidecar) is missing.\n";
    }
    const LoadedScene scene = loadScene(settings.scene);
    const int threads = settings.threads > 0 ? settings.threads : tbb::info::default_concurrency();
    // Files of one path length apart from another's: the bench races at several.
    const std::string suffix = "-depth" + std::to_string(settings.depth);
    const auto embreeImage = settings.outDir / ("peer-embree" + suffix + ".ppm");
    const auto log = settings.outDir / ("peer" + suffix + ".log");

    // Strata three times: the default sampler (Sobol'-refined warped strata) followed to depth K
    // like the tutorial's paths, the paper's strata24 likewise (plain random points in the
    // strata, which shows what the refinement costs per path), and the defaults as a user meets
    // them, whose Russian roulette ends some paths early: unbiased, but not the same work per
    // path, so that row is for reading against the other two, not a like-for-like race.
    struct StrataRun {
        std::string label;
        std::string sampler;
        int rouletteDepth;
        std::filesystem::path image;
    };
    const RenderOptions defaults;
    const StrataRun strataRuns[] = {
        {"strata render --roulette-depth -1 (defaults: " + defaults.sampler + ", NEE)", defaults.sampler, -1,
         settings.outDir / ("peer-strata" + suffix + ".exr")},
        {"strata render --roulette-depth -1 --sampler strata24 (NEE)", "strata24", -1,
         settings.outDir / ("peer-strata24" + suffix + ".exr")},
        {"strata render (defaults, roulette from bounce " + std::to_string(defaults.rouletteDepth) + ")",
         defaults.sampler, defaults.rouletteDepth, settings.outDir / ("peer-strata-roulette" + suffix + ".exr")}};
    std::vector<Entrant> entrants;
    for (const StrataRun& run : strataRuns) {
        RenderOptions options;
        options.scene = settings.scene.string();
        options.nee = true;
        options.rouletteDepth = run.rouletteDepth;
        options.sampler = run.sampler;
        options.depth = settings.depth;
        options.width = settings.width;
        options.height = settings.height;
        options.threads = threads;
        entrants.push_back({run.label, renderCommandLine(options, settings.spp, run.image), {}, {}, {}});
    }
    const CameraPose& pose = scene.settings.pose;
    std::vector<std::string> embreeArgs = {
        kEmbreePathTracer, "-i", settings.scene.string(),
        "--vp", number(pose.position.x), number(pose.position.y), number(pose.position.z),
        "--vi", number(pose.lookAt.x), number(pose.lookAt.y), number(pose.lookAt.z),
        "--vu", number(pose.up.x), number(pose.up.y), number(pose.up.z),
        "--fov", number(pose.fovYDegrees),
        "--size", std::to_string(settings.width), std::to_string(settings.height),
        "--spp", std::to_string(settings.spp),
        "--max-path-length", std::to_string(settings.depth),
        "--threads", std::to_string(threads), "-o", embreeImage.string()};
    for (const PointLight& light : scene.scene.mesh().pointLights) {
        embreeArgs.insert(embreeArgs.end(),
                          {"--pointlight", number(light.position.x), number(light.position.y),
                           number(light.position.z), number(light.intensity.x),
                           number(light.intensity.y), number(light.intensity.z)});
    }

    entrants.push_back({kEmbreePathTracer, embreeArgs, {}, {}, {}});
    if (const auto failed = race(entrants, settings.repeats, log, "vs-embree")) {
        return "\n### Against Embree's tutorial path tracer\n\nSkipped: `" + *failed + "` failed (see " +
               log.string() + "; Debian package embree-tools).\n";
    }
    const double paths = double(settings.width) * settings.height * settings.spp;
    const Entrant& embree = entrants.back();
    Table table{{"renderer", "wall s (median of " + std::to_string(settings.repeats) + ")",
                 "Mpaths/s", "CPU s (median)", "Mpaths/CPU-s", "image mean",
                 "image mean clamped to [0,1]"}, {}};
    std::string ratios;
    for (size_t i = 0; i < std::size(strataRuns); ++i) {
        const Entrant& run = entrants[i];
        const auto [mean, clamped] = exrMeans(strataRuns[i].image);
        table.add({run.name, cell("%.3f", run.medianWall()), cell("%.3f", paths / run.medianWall() * 1e-6),
                   cell("%.3f", run.medianCpu()), cell("%.3f", paths / run.medianCpu() * 1e-6),
                   cell("%.4f", mean), cell("%.4f", clamped)});
        ratios += cell("\n%s: paths/s / Embree's %.3f by wall time, %.3f by CPU time\n", run.name.c_str(),
                       embree.medianWall() / run.medianWall(), embree.medianCpu() / run.medianCpu());
    }
    table.add({"embree pathtracer", cell("%.3f", embree.medianWall()), cell("%.3f", paths / embree.medianWall() * 1e-6),
               cell("%.3f", embree.medianCpu()), cell("%.3f", paths / embree.medianCpu() * 1e-6), "-",
               cell("%.4f", ppmMean(embreeImage))});
    writeFile(settings.outDir / ("peer" + suffix + ".csv"), table.csv());
    return "\n### Against Embree's tutorial path tracer (" + settings.scene.string() + ")\n\n" +
           cell("%dx%d, %d spp, depth %d (Embree --max-path-length %d: both render the light of up "
                "to %d bounces), %s, whole-process wall time including loading and BVH build, runs "
                "alternated.\n\n",
                settings.width, settings.height, settings.spp, settings.depth, settings.depth, settings.depth,
                threadsText(threads).c_str()) +
           table.markdown() + ratios +
           "\nWhat differs: Embree's tutorial (renderPixelFunction in its pathtracer_device.cpp) "
           "stops a path once the largest component of its weight falls below 0.01 (biased, and "
           "cheaper), samples directions from its material's BRDF without strata, ignores surface "
           "emission, and writes linear values clamped to [0, 1] as 8 bits (compare the clamped "
           "means). Strata's first two rows follow every path to depth K (no roulette, no cut-off); "
           "all write linear float EXR.\n";
}

}  // namespace strata
