#include "bench/bench_viewer.h"

#include <fstream>
#include <nlohmann/json.hpp>
#include <tbb/info.h>
#include <vector>

#include "bench/bench_output.h"
#include "bench/bench_process.h"
#include "progress.h"

namespace strata {
namespace {

const std::string kTitle = "\n### The viewer: throughput against `strata render`, UI frame times\n\n";

// The report `strata view --json` printed: the last line of the log that is a JSON object.
nlohmann::json viewReport(const std::filesystem::path& log) {
    std::ifstream in(log);
    std::string report;
    for (std::string line; std::getline(in, line);) {
        if (!line.empty() && line.front() == '{') report = line;
    }
    return nlohmann::json::parse(report, nullptr, false);  // discarded (not an object) if none
}

struct ViewRuns {
    std::vector<double> wall, p50, p95;
    std::string context;
};

// Runs `args` (a `strata view --json`), adding its figures to `runs`; false when it failed.
bool runView(const std::vector<std::string>& args, const std::filesystem::path& log, ViewRuns& runs) {
    const ProcessTiming t = runTimed(args, log);
    const nlohmann::json report = viewReport(log);
    if (t.wall < 0.0 || !report.is_object()) return false;
    runs.wall.push_back(t.wall);
    runs.p50.push_back(report.value("frame_ms_p50", 0.0));
    runs.p95.push_back(report.value("frame_ms_p95", 0.0));
    runs.context = report.value("context", "");
    return true;
}

}  // namespace

std::string runViewerComparison(const ViewerBenchSettings& settings) {
    const int threads = settings.threads > 0 ? settings.threads : tbb::info::default_concurrency();
    const std::string exe = std::filesystem::read_symlink("/proc/self/exe").string();
    const std::string depth = std::to_string(settings.depth);
    const std::string spp = std::to_string(settings.spp);
    const std::vector<std::string> render = {
        exe, "render", settings.scene.string(), "--sampler", "strata24", "--depth", depth, "--spp", spp,
        "--width", std::to_string(settings.width), "--height", std::to_string(settings.height),
        "--threads", std::to_string(threads)};
    // One frame, then on to the target: the viewer draws its panel at its own frame rate meanwhile.
    const std::vector<std::string> view = {
        exe, "view", settings.scene.string(), "--headless", "--no-split", "--sampler", "strata24",
        "--depth", depth, "--target-spp", spp, "--window", std::to_string(settings.width),
        std::to_string(settings.height), "--threads", std::to_string(threads), "--frames", "1", "--json"};
    const std::vector<std::string> splitView = {
        exe, "view", settings.scene.string(), "--headless", "--depth", depth, "--window",
        std::to_string(settings.uiWidth), std::to_string(settings.uiHeight), "--threads",
        std::to_string(threads), "--frames", std::to_string(settings.uiFrames), "--json"};
    const auto log = settings.outDir / "viewer.log";

    std::vector<double> renderWall;
    ViewRuns viewRuns, splitRuns;
    const int runs = 3 * settings.repeats;
    ProgressReporter progress("viewer", static_cast<uint64_t>(runs), 1);
    for (int r = 0; r < settings.repeats; ++r) {
        // Alternate which goes first so that neither always runs on a warmer machine.
        for (int k = 0; k < 2; ++k) {
            if ((r + k) % 2 == 0) {
                const ProcessTiming t = runTimed(render, log);
                if (t.wall < 0.0) return kTitle + "Skipped: `strata render` failed (see " + log.string() + ").\n";
                renderWall.push_back(t.wall);
            } else if (!runView(view, log, viewRuns)) {
                return kTitle + "Skipped: `strata view --headless` failed (see " + log.string() + ").\n";
            }
        }
        if (!runView(splitView, log, splitRuns)) {
            return kTitle + "Skipped: `strata view --headless` failed (see " + log.string() + ").\n";
        }
        progress.update(static_cast<uint64_t>(3 * (r + 1)), 0);
    }
    progress.finish(static_cast<uint64_t>(runs), 0);

    const double paths = double(settings.width) * settings.height * settings.spp;
    const double renderSeconds = median(renderWall), viewSeconds = median(viewRuns.wall);
    const std::string repeats = std::to_string(settings.repeats);
    Table table{{"program", "wall s (median of " + repeats + ")", "Mpaths/s", "UI frame p50 ms",
                 "UI frame p95 ms"}, {}};
    table.add({"strata render", cell("%.3f", renderSeconds), cell("%.3f", paths / renderSeconds * 1e-6), "-", "-"});
    table.add({"strata view with its panel (" + viewRuns.context + ")", cell("%.3f", viewSeconds),
               cell("%.3f", paths / viewSeconds * 1e-6), cell("%.1f", median(viewRuns.p50)),
               cell("%.1f", median(viewRuns.p95))});
    writeTextFile(settings.outDir / "viewer.csv", table.csv());
    return kTitle +
           cell("%s, %dx%d, %d spp, depth %d, strata24, %d threads; whole processes including start-up "
                "and loading, runs alternated.\n\n",
                settings.scene.filename().string().c_str(), settings.width, settings.height, settings.spp,
                settings.depth, threads) +
           table.markdown() +
           cell("\nViewer throughput / `strata render` throughput: **%.3f** (target at least 0.9).\n",
                renderSeconds / viewSeconds) +
           cell("\nUI frame times while rendering the split view (uniform | strata24) at %dx%d, offscreen "
                "(%s), %d frames, median of %d run(s): p50 %.1f ms, **p95 %.1f ms** (target under 33 ms).\n",
                settings.uiWidth, settings.uiHeight, splitRuns.context.c_str(), settings.uiFrames,
                settings.repeats, median(splitRuns.p50), median(splitRuns.p95));
}

}  // namespace strata
