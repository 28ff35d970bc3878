#include "bench/bench_ranks.h"

#include <algorithm>
#include <cstdlib>
#include <tbb/info.h>
#include <vector>

#include "bench/bench_output.h"
#include "bench/bench_process.h"
#include "progress.h"

namespace strata {

std::string runRankComparison([[maybe_unused]] const RankSettings& settings) {
    const std::string title = "\n### MPI on one machine: one process against 1 and 2 ranks\n\n";
#if !STRATA_WITH_MPI
    return title + "Skipped: this strata was built without MPI.\n";
#else
    const int threads = settings.threads > 0 ? settings.threads : tbb::info::default_concurrency();
    const std::string exe = std::filesystem::read_symlink("/proc/self/exe").string();
    const auto render = [&](int threadsPerRank, const std::string& image) {
        return std::vector<std::string>{
            exe, "render", settings.scene.string(), "--sampler", "strata24",
            "--depth", std::to_string(settings.depth), "--spp", std::to_string(settings.spp),
            "--width", std::to_string(settings.width), "--height", std::to_string(settings.height),
            "--threads", std::to_string(threadsPerRank), "--out", (settings.outDir / image).string()};
    };
    const auto ranks = [](int count, std::vector<std::string> args) {
        // --bind-to none: mpiexec would otherwise pin each of 2 ranks to one core.
        const std::vector<std::string> launcher = {STRATA_MPIEXEC, "--allow-run-as-root", "--oversubscribe",
                                                   "--bind-to", "none", "-np", std::to_string(count)};
        args.insert(args.begin(), launcher.begin(), launcher.end());
        return args;
    };
    // Containers often forbid the cross-memory attach Open MPI's shared-memory transport uses by
    // default; copying through the shared segment works everywhere. A setting the user made wins.
    setenv("OMPI_MCA_btl_vader_single_copy_mechanism", "none", 0);
    const int half = std::max(1, threads / 2);
    struct Variant {
        std::string name;
        std::vector<std::string> args;
        std::vector<double> wall, cpu;
    };
    std::vector<Variant> variants = {
        {"strata render, " + std::to_string(threads) + " threads", render(threads, "ranks-single.exr"), {}, {}},
        {"mpiexec -np 1, " + std::to_string(threads) + " threads", ranks(1, render(threads, "ranks-1.exr")), {}, {}},
        {"mpiexec -np 2, " + std::to_string(half) + (half == 1 ? " thread each" : " threads each"), ranks(2, render(half, "ranks-2.exr")), {}, {}}};
    const auto log = settings.outDir / "ranks.log";
    const int runs = settings.repeats * static_cast<int>(variants.size());
    ProgressReporter progress("mpi ranks", static_cast<uint64_t>(runs), 1);
    for (int run = 0; run < runs; ++run) {
        // Rotate the order so that no variant always runs first on a cool machine.
        const int count = static_cast<int>(variants.size());
        Variant& variant = variants[static_cast<size_t>((run + run / count) % count)];
        const ProcessTiming t = runTimed(variant.args, log);
        if (t.wall < 0.0) return title + "Skipped: `" + variant.name + "` failed (see " + log.string() + ").\n";
        variant.wall.push_back(t.wall);
        variant.cpu.push_back(t.cpu);
        progress.update(static_cast<uint64_t>(run + 1), 0);
    }
    progress.finish(static_cast<uint64_t>(runs), 0);
    const double paths = double(settings.width) * settings.height * settings.spp;
    const double single = median(variants[0].wall);
    Table table{{"run", "wall s (median of " + std::to_string(settings.repeats) + ")", "Mpaths/s",
                 "CPU s (median)", "wall time / one process"}, {}};
    for (const Variant& v : variants) {
        const double wall = median(v.wall);
        table.add({v.name, cell("%.3f", wall), cell("%.3f", paths / wall * 1e-6), cell("%.3f", median(v.cpu)),
                   cell("%.3f", wall / single)});
    }
    writeTextFile(settings.outDir / "ranks.csv", table.csv());
    return title +
           cell("%s, %dx%d, %d spp, depth %d, strata24; whole processes including start-up, "
                "loading, BVH build, reduction and writing.\n\n",
                settings.scene.filename().string().c_str(), settings.width, settings.height, settings.spp,
                settings.depth) +
           table.markdown();
#endif
}

}  // namespace strata
