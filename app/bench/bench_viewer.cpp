#include "bench/bench_viewer.h"

#include <nlohmann/json.hpp>
#include <tbb/info.h>
#include <vector>

#include "bench/bench_output.h"
#include "bench/bench_process.h"
#include "bench/bench_race.h"
#include "bench/strata_child.h"
#include "io/output_file.h"

namespace strata {
namespace {

const std::string kViewerTitle = "\n### The viewer: throughput against `strata render`, UI frame times\n\n";

// What the `strata view --json` runs reported, one entry per run.
struct ViewReports {
    std::vector<double> p50, p95;
    std::string context;

    // Reads the run's report from its log; false when there is none.
    bool read(const std::filesystem::path& log) {
        const nlohmann::json report = lastJsonReport(log);
        if (!report.is_object()) return false;
        p50.push_back(report.value("frame_ms_p50", 0.0));
        p95.push_back(report.value("frame_ms_p95", 0.0));
        context = report.value("context", "");
        return true;
    }
};

}  // namespace

std::string runViewerComparison(const ViewerBenchSettings& settings) {
    const int threads = settings.threads > 0 ? settings.threads : tbb::info::default_concurrency();
    RenderOptions options;
    options.scene = settings.scene.string();
    options.depth = settings.depth;
    options.threads = threads;
    RenderOptions batch = options;
    batch.width = settings.width;
    batch.height = settings.height;
    const std::string spp = std::to_string(settings.spp);
    // One frame, then on to the target: the viewer draws its panel at its own frame rate meanwhile.
    // --width/--height give the viewer's image the batch render's size (its window is the panel
    // wider): the same paths.
    const auto view = strataCommandLine(
        "view", options,
        {"--headless", "--no-split", "--target-spp", spp, "--width", std::to_string(settings.width), "--height",
         std::to_string(settings.height), "--frames", "1", "--json"});
    // The default split view: uniform | strata24, both at the options' depth.
    const auto splitView = strataCommandLine(
        "view", options,
        {"--headless", "--window", std::to_string(settings.uiWidth), std::to_string(settings.uiHeight),
         "--frames", std::to_string(settings.uiFrames), "--json"});
    const auto log = settings.outDir / "viewer.log";

    ViewReports viewReports, splitReports;
    std::vector<Entrant> entrants = {
        {"strata render", renderCommandLine(batch, settings.spp), {}, {}, {}},
        {"strata view --headless", view, [&](const auto& log) { return viewReports.read(log); }, {}, {}},
        {"strata view --headless (split view)", splitView,
         [&](const auto& log) { return splitReports.read(log); }, {}, {}}};
    if (const auto failed = race(entrants, settings.repeats, log, "viewer")) {
        return kViewerTitle + "Skipped: `" + *failed + "` failed (see " + log.string() + ").\n";
    }

    const double paths = double(settings.width) * settings.height * settings.spp;
    const double renderSeconds = entrants[0].medianWall(), viewSeconds = entrants[1].medianWall();
    const std::string repeats = std::to_string(settings.repeats);
    Table table{{"program", "wall s (median of " + repeats + ")", "Mpaths/s", "UI frame p50 ms",
                 "UI frame p95 ms"}, {}};
    table.add({"strata render", cell("%.3f", renderSeconds), cell("%.3f", paths / renderSeconds * 1e-6), "-", "-"});
    table.add({"strata view with its panel (" + viewReports.context + ")", cell("%.3f", viewSeconds),
               cell("%.3f", paths / viewSeconds * 1e-6), cell("%.1f", median(viewReports.p50)),
               cell("%.1f", median(viewReports.p95))});
    writeFile(settings.outDir / "viewer.csv", table.csv());
    return kViewerTitle +
           cell("%s, %dx%d, %d spp, depth %d, the default sampler (%s) and transport, %s; whole "
                "processes including start-up and loading, runs alternated.\n\n",
                settings.scene.filename().string().c_str(), settings.width, settings.height, settings.spp,
                settings.depth, options.sampler.c_str(), threadsText(threads).c_str()) +
           table.markdown() +
           cell("\nViewer throughput / `strata render` throughput: **%.3f** (target at least 0.9).\n",
                renderSeconds / viewSeconds) +
           cell("\nUI frame times while rendering the split view (uniform | strata24) at %dx%d, offscreen "
                "(%s), %d frames, median of %d run(s): p50 %.1f ms, **p95 %.1f ms** (target under 33 ms).\n",
                settings.uiWidth, settings.uiHeight, splitReports.context.c_str(), settings.uiFrames,
                settings.repeats, median(splitReports.p50), median(splitReports.p95));
}

}  // namespace strata
