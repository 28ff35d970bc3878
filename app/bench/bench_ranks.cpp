#include "bench/bench_ranks.h"

#include <algorithm>
#include <cstdlib>
#include <tbb/info.h>
#include <vector>

#include "bench/bench_output.h"
#include "bench/bench_race.h"
#include "bench/strata_child.h"
#include "io/output_file.h"

namespace strata {

std::string runRankComparison([[maybe_unused]] const RankSettings& settings) {
    const std::string title = "\n### MPI on one machine: one process against 1 and 2 ranks\n\n";
#if !STRATA_WITH_MPI
    return title + "Skipped: this strata was built without MPI.\n";
#else
    const int threads = settings.threads > 0 ? settings.threads : tbb::info::default_concurrency();
    const auto render = [&](int threadsPerRank, const std::string& image) {
        RenderOptions options;
        options.scene = settings.scene.string();
        options.sampler = "strata24";
        options.depth = settings.depth;
        options.width = settings.width;
        options.height = settings.height;
        options.threads = threadsPerRank;
        return renderCommandLine(options, settings.spp, settings.outDir / image);
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
    std::vector<Entrant> variants = {
        {"strata render, " + threadsText(threads), render(threads, "ranks-single.exr"), {}, {}, {}},
        {"mpiexec -np 1, " + threadsText(threads), ranks(1, render(threads, "ranks-1.exr")), {}, {}, {}},
        {"mpiexec -np 2, " + threadsText(half) + " each", ranks(2, render(half, "ranks-2.exr")), {}, {}, {}}};
    const auto log = settings.outDir / "ranks.log";
    if (const auto failed = race(variants, settings.repeats, log, "mpi ranks")) {
        return title + "Skipped: `" + *failed + "` failed (see " + log.string() + ").\n";
    }
    const double paths = double(settings.width) * settings.height * settings.spp;
    const double single = variants[0].medianWall();
    Table table{{"run", "wall s (median of " + std::to_string(settings.repeats) + ")", "Mpaths/s",
                 "CPU s (median)", "wall time / one process"}, {}};
    for (const Entrant& v : variants) {
        const double wall = v.medianWall();
        table.add({v.name, cell("%.3f", wall), cell("%.3f", paths / wall * 1e-6), cell("%.3f", v.medianCpu()),
                   cell("%.3f", wall / single)});
    }
    writeFile(settings.outDir / "ranks.csv", table.csv());
    return title +
           cell("%s, %dx%d, %d spp, depth %d, strata24; whole processes including start-up, "
                "loading, BVH build, reduction and writing.\n\n",
                settings.scene.filename().string().c_str(), settings.width, settings.height, settings.spp,
                settings.depth) +
           table.markdown();
#endif
}

}  // namespace strata
