#include "bench/bench_throughput.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <tbb/info.h>
#include <vector>

#include "bench/bench_output.h"
#include "bench/bench_process.h"
#include "bench/process_memory.h"
#include "bench/strata_child.h"
#include "util/constants.h"
#include "sampling/hemisphere.h"
#include "progress.h"
#include "integrator/render_session.h"
#include "render_options.h"
#include "sampling/random.h"
#include "bench/ray_throughput.h"
#include "bench/reference_cache.h"
#include "bench/render_rate.h"
#include "scene/scene_loader.h"
#include "sampling/strata24.h"
#include "sampling/stratum_schedule.h"
#include "io/output_file.h"

namespace strata {
namespace {
Camera cameraOfWidth(const LoadedScene& loaded, int width) {
    const int height = std::max(1, static_cast<int>(std::lround(
        static_cast<double>(width) * loaded.settings.height / loaded.settings.width)));
    return Camera(loaded.settings.pose, width, height);
}

// A closed white box with a ceiling light and a lat-long sphere of about `triangles` triangles in
// it: the scene for cost against triangle count (only the sphere's tessellation changes).
MeshData tessellatedScene(size_t triangles) {
    MeshData mesh;
    mesh.materials = {Material{"white", glm::vec3(0.7f), glm::vec3(0.0f)},
                      Material{"light", glm::vec3(0.0f), glm::vec3(8.0f)}};
    auto quad = [&](glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d, uint32_t material) {
        const auto base = static_cast<uint32_t>(mesh.positions.size());
        mesh.positions.insert(mesh.positions.end(), {a, b, c, d});
        mesh.triangles.push_back({base, base + 1, base + 2});
        mesh.triangles.push_back({base, base + 2, base + 3});
        mesh.triangleMaterials.insert(mesh.triangleMaterials.end(), {material, material});
    };
    // Walls face inward, the light (just below the ceiling) faces down.
    const float s = 1.0f;
    quad({-s, -s, -s}, {s, -s, -s}, {s, -s, s}, {-s, -s, s}, 0);  // floor, normal +y
    quad({-s, s, s}, {s, s, s}, {s, s, -s}, {-s, s, -s}, 0);      // ceiling, normal -y
    quad({-s, -s, -s}, {-s, s, -s}, {s, s, -s}, {s, -s, -s}, 0);  // back, normal +z
    quad({-s, -s, s}, {-s, s, s}, {-s, s, -s}, {-s, -s, -s}, 0);  // left, normal +x
    quad({s, -s, -s}, {s, s, -s}, {s, s, s}, {s, -s, s}, 0);      // right, normal -x
    quad({-0.3f, 0.99f, -0.3f}, {0.3f, 0.99f, -0.3f}, {0.3f, 0.99f, 0.3f}, {-0.3f, 0.99f, 0.3f}, 1);
    // Sphere: `rings` latitude bands of 2 * rings segments give about 4 rings^2 triangles.
    const int rings = std::max(2, static_cast<int>(std::lround(std::sqrt(triangles / 4.0))));
    const int segments = 2 * rings;
    const auto base = static_cast<uint32_t>(mesh.positions.size());
    for (int r = 0; r <= rings; ++r) {
        const float theta = kPi * r / rings;
        for (int k = 0; k < segments; ++k) {
            const float phi = 2.0f * kPi * k / segments;
            mesh.positions.push_back(glm::vec3(0.0f, -0.4f, 0.0f) +
                                     0.5f * glm::vec3(std::sin(theta) * std::cos(phi), std::cos(theta),
                                                      std::sin(theta) * std::sin(phi)));
        }
    }
    auto vertex = [&](int r, int k) { return base + static_cast<uint32_t>(r * segments + k % segments); };
    for (int r = 0; r < rings; ++r) {
        for (int k = 0; k < segments; ++k) {
            if (r > 0) mesh.triangles.push_back({vertex(r, k), vertex(r, k + 1), vertex(r + 1, k)});
            if (r < rings - 1) {
                mesh.triangles.push_back({vertex(r, k + 1), vertex(r + 1, k + 1), vertex(r + 1, k)});
            }
        }
    }
    mesh.triangleMaterials.resize(mesh.triangles.size(), 0);
    return mesh;
}

// Peak resident memory (KiB) of a child `strata render` of a 1920x1080 image at depth 0
// (memory does not depend on depth); -1 when the child failed.
long peakRssOfFullHdRender(const std::filesystem::path& scene, const std::filesystem::path& outDir,
                           int threads) {
    RenderOptions options;
    options.scene = scene.string();
    options.width = 1920;
    options.height = 1080;
    options.depth = 0;
    options.threads = threads;
    const auto image = outDir / "rss-probe.exr";
    const auto log = outDir / "rss-probe.log";
    std::vector<std::string> argv = renderCommandLine(options, kPathsPerPass, image);
    argv.push_back("--json");
    const ProcessTiming t = runTimed(argv, log);
    std::filesystem::remove(image);
    return t.ok() ? reportedPeakResidentKiB(log) : -1;
}

// ns per call of `sample(i)` over `count` calls; the checksum keeps the work from being removed.
template <typename Sample>
double nanosecondsPerSample(uint64_t count, Sample sample) {
    float checksum = 0.0f;
    const auto start = Clock::now();
    for (uint64_t i = 0; i < count; ++i) checksum += sample(i);
    const double seconds = secondsSince(start);
    if (checksum == 12345.678f) std::fprintf(stderr, " ");  // practically never; defeats DCE
    return seconds * 1e9 / static_cast<double>(count);
}

// All three components feed the checksum: with one, the compiler (inlining across files under
// LTO, and knowing sin and cos are pure) drops the work that only the others need.
float componentSum(const glm::vec3& v) { return v.x + v.y + v.z; }

glm::vec2 randomPoint(uint64_t i) {
    const uint64_t bits = mixBits(i);
    return {uniformFloat(bits), uniformFloat(bits << 24)};
}

}  // namespace

std::string runThroughput(const ThroughputSettings& settings) {
    const bool quick = settings.quick;
    const int maxThreads = settings.threads > 0 ? settings.threads
                                                : tbb::info::default_concurrency();
    const LoadedScene loaded = loadScene(settings.scene);
    const std::string name = sceneName(loaded.scenePath());
    const bool nee = !loaded.scene.mesh().pointLights.empty();
    const Camera camera = cameraOfWidth(loaded, quick ? 96 : 256);
    const uint32_t passes = quick ? 2 : 6;
    RenderOptions options;
    options.depth = settings.depth;
    options.nee = nee;
    // Every path goes to depth K, so that paths/s measures a fixed amount of work per path.
    options.rouletteDepth = -1;
    options.seed = settings.seed;
    options.threads = settings.threads;
    const auto withSampler = [&](const char* sampler) {
        RenderOptions o = options;
        o.sampler = sampler;
        return o;
    };
    std::string summary;
    ProgressReporter progress("throughput", 7, "stage");
    uint64_t stage = 0;
    auto advance = [&] { progress.update(++stage, 0); };

    // 1. The path tracer, per sampler: strata24's bookkeeping (the stratum schedule) should cost
    // little, within 10% of uniform's speed.
    Table rates{{"scene", "sampler", "depth", "size", "threads", "Mpaths/s", "Mrays/s",
                 "Mpaths/CPU-s", "Mrays/CPU-s", "rays/path"}, {}};
    const RenderRate uniform = measureRender(loaded.scene, camera, withSampler("uniform"), passes);
    const RenderRate strata = measureRender(loaded.scene, camera, withSampler("strata24"), passes);
    for (const auto& [sampler, rate] : {std::pair{"uniform", uniform}, std::pair{"strata24", strata}}) {
        rates.add({name, sampler, std::to_string(settings.depth),
                   cell("%dx%d", camera.width(), camera.height()), std::to_string(maxThreads),
                   cell("%.3f", rate.mpathsPerSecond()), cell("%.3f", rate.mraysPerSecond()),
                   cell("%.3f", rate.mpathsPerCpuSecond()), cell("%.3f", rate.mraysPerCpuSecond()),
                   cell("%.2f", double(rate.rays) / rate.paths)});
    }
    writeFile(settings.outDir / "throughput-pathtracer.csv", rates.csv());
    const double speedRatio = strata.mpathsPerCpuSecond() / uniform.mpathsPerCpuSecond();
    advance();

    // 2. Embree's ceiling on the same scene.
    Table ceiling{{"query", "threads", "Mrays/s", "Mrays/CPU-s", "hit fraction",
                   "path tracer (strata24) / this, per CPU-s"}, {}};
    double singleCeiling = 0.0;
    std::string bars = cell("\"path tracer (strata24)\" %.3f\n\"path tracer (uniform)\" %.3f\n",
                            strata.mraysPerCpuSecond(), uniform.mraysPerCpuSecond());
    for (RayQuery query : kRayQueries) {
        const RayThroughput t = measureRandomRays(loaded.scene, query, settings.threads,
                                                  quick ? 0.3 : 1.5, settings.seed);
        const double mrays = t.raysPerCpuSecond() * 1e-6;
        if (query == RayQuery::Single) singleCeiling = mrays;
        ceiling.add({std::string(rayQueryName(query)), std::to_string(maxThreads),
                     cell("%.3f", t.raysPerSecond() * 1e-6), cell("%.3f", mrays),
                     cell("%.3f", double(t.hits) / t.rays),
                     cell("%.1f%%", 100.0 * strata.mraysPerCpuSecond() / mrays)});
        bars += cell("\"%s (random rays)\" %.3f\n", std::string(rayQueryName(query)).c_str(), mrays);
    }
    writeFile(settings.outDir / "throughput-ceiling.csv", ceiling.csv());
    writeFile(settings.outDir / "throughput-bars.dat", bars);
    runGnuplot(settings.outDir, "throughput-bars",
               "set terminal pngcairo noenhanced size 800,440 font ',10'\nset output 'throughput-bars.png'\n"
               "set rmargin 20\n"
               "set style fill solid 0.8\nset boxwidth 0.6\nset grid ytics\nset yrange [0:*]\n"
               "set offsets 0, 0, graph 0.12, 0\n"
               "set ylabel 'Mrays per CPU-second'\nset xtics rotate by -25 left\nset bmargin 7\n"
               "set title 'Path tracer against Embree random-ray ceiling, " + name + ", " +
                   threadsText(maxThreads) + "'\n"
               "plot 'throughput-bars.dat' using 0:2:xtic(1) with boxes lc rgb '#3070b0' notitle, "
               "'' using 0:2:(sprintf('%.1f',$2)) with labels offset 0,0.7 notitle\n");
    advance();

    // 3. Thread scaling.
    Table scaling{{"threads", "Mpaths/s (wall)", "speed-up", "efficiency", "Mpaths/CPU-s"}, {}};
    double oneThread = 0.0;
    for (int t = 1; t <= maxThreads; ++t) {
        RenderOptions threadOptions = withSampler("strata24");
        threadOptions.threads = t;
        const RenderRate r = measureRender(loaded.scene, camera, threadOptions, passes);
        if (t == 1) oneThread = r.mpathsPerSecond();
        scaling.add({std::to_string(t), cell("%.3f", r.mpathsPerSecond()),
                     cell("%.2f", r.mpathsPerSecond() / oneThread),
                     cell("%.0f%%", 100.0 * r.mpathsPerSecond() / oneThread / t),
                     cell("%.3f", r.mpathsPerCpuSecond())});
    }
    writeFile(settings.outDir / "throughput-threads.csv", scaling.csv());
    advance();

    // 4. Cost against resolution.
    Table resolution{{"size", "pixels", "seconds/pass", "CPU ns/path", "Mpaths/s"}, {}};
    for (int width : quick ? std::vector<int>{32, 64, 128} : std::vector<int>{64, 128, 256, 512}) {
        const Camera c = cameraOfWidth(loaded, width);
        const RenderRate r = measureRender(loaded.scene, c, withSampler("strata24"), quick ? 1 : 2);
        const uint32_t timedPasses = quick ? 1 : 2;
        resolution.add({cell("%dx%d", c.width(), c.height()),
                        std::to_string(size_t(c.width()) * c.height()),
                        cell("%.4f", r.seconds / timedPasses), cell("%.1f", r.cpuSeconds * 1e9 / r.paths),
                        cell("%.3f", r.mpathsPerSecond())});
    }
    writeFile(settings.outDir / "throughput-resolution.csv", resolution.csv());
    advance();

    // 5. Cost against triangle count (synthetic scene).
    Table triangles{{"triangles", "BVH build s", "path tracer Mrays/CPU-s",
                     "rtcIntersect1 ceiling Mrays/CPU-s", "fraction"}, {}};
    std::string triangleData;
    const size_t largest = quick ? 10000 : 1000000;
    for (size_t n = 1000; n <= largest; n *= 10) {
        const auto buildStart = Clock::now();
        const Scene scene(tessellatedScene(n));
        const double build = secondsSince(buildStart);
        const Camera c(CameraPose{{0.0f, 0.0f, 3.4f}, {0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, 40.0f},
                       quick ? 64 : 128, quick ? 64 : 128);
        RenderOptions unlit = withSampler("strata24");
        unlit.nee = false;  // the box has no point lights
        const RenderRate r = measureRender(scene, c, unlit, passes);
        const double ceilingRate = measureRandomRays(scene, RayQuery::Single, settings.threads,
                                                     quick ? 0.2 : 0.6, settings.seed).raysPerCpuSecond() * 1e-6;
        triangles.add({std::to_string(scene.summary().triangles), cell("%.3f", build),
                       cell("%.3f", r.mraysPerCpuSecond()), cell("%.3f", ceilingRate),
                       cell("%.1f%%", 100.0 * r.mraysPerCpuSecond() / ceilingRate)});
        triangleData += cell("%zu %.4f %.4f\n", scene.summary().triangles, r.mraysPerCpuSecond(), ceilingRate);
    }
    writeFile(settings.outDir / "throughput-triangles.csv", triangles.csv());
    writeFile(settings.outDir / "throughput-triangles.dat", triangleData);
    runGnuplot(settings.outDir, "throughput-triangles",
               "set terminal pngcairo noenhanced size 640,400 font ',10'\nset output 'throughput-triangles.png'\n"
               "set logscale x\nset grid\nset yrange [0:*]\nset key bottom left\n"
               "set xlabel 'triangles'\nset ylabel 'Mrays per CPU-second'\n"
               "set title 'Cost against triangle count (tessellated sphere in a box)'\n"
               "plot 'throughput-triangles.dat' using 1:2 with linespoints lw 2 title 'path tracer', "
               "'' using 1:3 with linespoints lw 2 title 'rtcIntersect1 random rays'\n");
    advance();

    // 6. Peak memory of a 1920x1080 render (depth 0: memory does not depend on depth).
    const long rss = peakRssOfFullHdRender(settings.scene, settings.outDir, maxThreads);
    advance();

    // 7. Sampler micro-benchmark (one thread).
    const uint64_t count = quick ? (1u << 21) : (1u << 24);
    const double nsPoint = nanosecondsPerSample(count, [](uint64_t i) { return randomPoint(i).x; });
    const double nsUniform = nanosecondsPerSample(
        count, [](uint64_t i) { return componentSum(sampleUniformHemisphere(randomPoint(i))); });
    const double nsStratum = nanosecondsPerSample(count, [](uint64_t i) {
        return componentSum(sampleStratum(static_cast<int>(i % kStrataCount), randomPoint(i)));
    });
    // A path's schedule built once, then asked for 5 bounces (each path hashing its pixel's and
    // pass's keys itself, which the path tracer shares among a pass's 24 paths).
    constexpr int kBounces = 5;
    const double nsScheduled = nanosecondsPerSample(
        count, [schedule = PathSchedule(0, 0, 0)](uint64_t i) mutable {
            const uint64_t path = i / kBounces;
            if (i % kBounces == 0) {
                schedule = PathSchedule(0x1234u + path / kStrataCount, static_cast<uint32_t>(path / 576),
                                        static_cast<int>(path % kStrataCount));
            }
            return componentSum(sampleStratum(schedule.stratum(static_cast<int>(i % kBounces)), randomPoint(i)));
        });
    Table sampler{{"operation (1 thread, includes the random point)", "ns/sample"}, {}};
    sampler.add({"random point in [0,1)^2 only", cell("%.2f", nsPoint)});
    sampler.add({"sampleUniformHemisphere", cell("%.2f", nsUniform)});
    sampler.add({"sampleStratum", cell("%.2f", nsStratum)});
    sampler.add({"PathSchedule (per 5-bounce path) + sampleStratum", cell("%.2f", nsScheduled)});
    writeFile(settings.outDir / "sampler-microbench.csv", sampler.csv());
    advance();
    progress.finish(stage, 0);

    summary += "### Path tracer throughput (" + name + ")\n\n" + rates.markdown() +
               cell("\nstrata24 / uniform render speed (paths per CPU-second): %.3f (within the "
                    "10%% target: %s)\n",
                    speedRatio, std::fabs(speedRatio - 1.0) <= 0.10 ? "yes" : "NO");
    summary += "\n### Embree ceiling: incoherent random rays on the same scene\n\n" + ceiling.markdown() +
               cell("\nPath tracer rays per CPU-second as a fraction of the rtcIntersect1 ceiling: "
                    "%.1f%% (target >= 85%%)\n",
                    100.0 * strata.mraysPerCpuSecond() / singleCeiling);
    summary += "\n### Thread scaling\n\n" + scaling.markdown();
    summary += "\n### Cost against resolution\n\n" + resolution.markdown();
    summary += "\n### Cost against triangle count\n\n" + triangles.markdown();
    summary += rss > 0 ? cell("\nPeak RSS of `strata render` at 1920x1080 (24 spp): %.1f MiB\n", rss / 1024.0)
                       : std::string("\nPeak RSS of a 1920x1080 render: the child render failed\n");
    summary += "\n### Sampler micro-benchmark\n\n" + sampler.markdown() +
               cell("\nNet of the random point: uniform %.2f ns, sampleStratum %.2f ns, with the "
                    "schedule %.2f ns.\n",
                    nsUniform - nsPoint, nsStratum - nsPoint, nsScheduled - nsPoint);
    return summary;
}

}  // namespace strata
