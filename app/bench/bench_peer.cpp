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
    const auto strataImage = settings.outDir / "peer-strata.exr";
    const auto embreeImage = settings.outDir / "peer-embree.ppm";
    const auto log = settings.outDir / "peer.log";

    RenderOptions strata;
    strata.scene = settings.scene.string();
    strata.nee = true;
    strata.rouletteDepth = -1;  // every path to depth K, as the text below says
    // The sampler stays the default (strata24-bsdf), as a user meets it: the tutorial samples its
    // BRDF too.
    strata.depth = settings.depth;
    strata.width = settings.width;
    strata.height = settings.height;
    strata.threads = threads;
    const CameraPose& pose = scene.settings.pose;
    std::vector<std::string> embreeArgs = {
        kEmbreePathTracer, "-i", settings.scene.string(),
        "--vp", number(pose.position.x), number(pose.position.y), number(pose.position.z),
        "--vi", number(pose.lookAt.x), number(pose.lookAt.y), number(pose.lookAt.z),
        "--vu", number(pose.up.x), number(pose.up.y), number(pose.up.z),
        "--fov", number(pose.fovYDegrees),
        "--size", std::to_string(settings.width), std::to_string(settings.height),
        "--spp", std::to_string(settings.spp),
        "--max-path-length", std::to_string(settings.depth + 1),
        "--threads", std::to_string(threads), "-o", embreeImage.string()};
    for (const PointLight& light : scene.scene.mesh().pointLights) {
        embreeArgs.insert(embreeArgs.end(),
                          {"--pointlight", number(light.position.x), number(light.position.y),
                           number(light.position.z), number(light.intensity.x),
                           number(light.intensity.y), number(light.intensity.z)});
    }

    std::vector<Entrant> entrants = {
        {"strata render", renderCommandLine(strata, settings.spp, strataImage), {}, {}, {}, {}},
        {kEmbreePathTracer, embreeArgs, {}, {}, {}, {}}};
    if (const auto failed = race(entrants, settings.repeats, log, "vs-embree")) {
        return "\n### Against Embree's tutorial path tracer\n\nSkipped: `" + *failed + "` failed (see " +
               log.string() + "; Debian package embree-tools).\n";
    }
    const double paths = double(settings.width) * settings.height * settings.spp;
    const double ts = entrants[0].medianWall(), te = entrants[1].medianWall();
    const double cs = entrants[0].medianCpu(), ce = entrants[1].medianCpu();
    const auto [strataMean, strataClamped] = exrMeans(strataImage);
    const double embreeMean = ppmMean(embreeImage);

    Table table{{"renderer", "wall s (median of " + std::to_string(settings.repeats) + ")",
                 "Mpaths/s", "CPU s (median)", "Mpaths/CPU-s", "image mean",
                 "image mean clamped to [0,1]"}, {}};
    table.add({"strata render --roulette-depth -1 (strata24-bsdf, NEE)", cell("%.3f", ts), cell("%.3f", paths / ts * 1e-6),
               cell("%.3f", cs), cell("%.3f", paths / cs * 1e-6), cell("%.4f", strataMean),
               cell("%.4f", strataClamped)});
    table.add({"embree pathtracer", cell("%.3f", te), cell("%.3f", paths / te * 1e-6),
               cell("%.3f", ce), cell("%.3f", paths / ce * 1e-6), "-", cell("%.4f", embreeMean)});
    writeTextFile(settings.outDir / "peer.csv", table.csv());
    return "\n### Against Embree's tutorial path tracer (" + settings.scene.string() + ")\n\n" +
           cell("%dx%d, %d spp, depth %d (Embree --max-path-length %d), %s, whole-process "
                "wall time including loading and BVH build, runs alternated.\n\n",
                settings.width, settings.height, settings.spp, settings.depth, settings.depth + 1,
                threadsText(threads).c_str()) +
           table.markdown() +
           cell("\nStrata paths/s / Embree paths/s: %.3f by wall time, %.3f by CPU time\n", te / ts,
                ce / cs) +
           "\nWhat differs: Embree's tutorial (renderPixelFunction in its pathtracer_device.cpp) "
           "stops a path once the largest component of its weight falls below 0.01 (biased, and "
           "cheaper), samples directions from its material's BRDF without strata, ignores surface emission, and writes linear values clamped to [0, 1] as 8 "
           "bits (compare the clamped means). Strata follows every path to depth K (no roulette, "
           "no cut-off) and writes linear float EXR.\n";
}

}  // namespace strata
