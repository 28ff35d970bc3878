#include "bench/bench_convergence.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>

#include "bench/convergence.h"
#include "util/error.h"
#include "film/image_metrics.h"
#include "progress.h"
#include "integrator/render_session.h"
#include "bench/ray_throughput.h"
#include "bench/reference_cache.h"
#include "render_options.h"
#include "scene/scene_loader.h"
#include "io/output_file.h"

namespace strata {
namespace {

// The adaptive-sampling variant of the skips comparison stops pixels at 5% relative error.
constexpr double kBenchNoiseThreshold = 0.05;
// Russian roulette is on in the plain runs; this variant measures it by switching it off.
constexpr const char* kNoRouletteVariant = "no-roulette";

// The reference must not share the bench's random numbers, or its error would correlate with
// theirs.
constexpr uint64_t kReferenceSeedOffset = 0x5eed5eed5eed5eedull;

// Runs `session` to `budget`, each pass it completes reported to `progress`.
void renderWithProgress(RenderSession& session, const RenderBudget& budget, ProgressReporter& progress) {
    session.run(budget, [&](const PassReport& report) {
        progress.update(report.passes, session.counters().paths);
    });
}

// The reference's two halves, each of half the passes (rounded up) and its own seed.
std::pair<Image, Image> renderReferenceHalves(const LoadedScene& loaded, const Camera& camera, RenderOptions options,
                                              const ConvergenceSettings& settings) {
    const uint32_t passes = (settings.referencePasses + 1) / 2;
    ProgressReporter progress("reference " + sceneName(loaded.scenePath()), 2 * passes, kPathsPerPass);
    std::array<Image, 2> halves;
    uint64_t pathsBefore = 0;
    for (uint32_t half = 0; half < 2; ++half) {
        options.seed = settings.seed + kReferenceSeedOffset + half;
        RenderSession session(loaded.scene, camera, options.renderSettings(loaded.scene), {0, passes});
        session.run({}, [&](const PassReport& report) {
            progress.update(half * passes + report.passes, pathsBefore + session.counters().paths);
        });
        pathsBefore += session.counters().paths;
        halves[half] = session.buffer().meanImage();
    }
    progress.finish(2 * passes, pathsBefore);
    return {std::move(halves[0]), std::move(halves[1])};
}

Image meanOf(const Image& a, const Image& b) {
    Image mean = a;
    for (size_t i = 0; i < mean.pixels.size(); ++i) mean.pixels[i] = 0.5f * (a.pixels[i] + b.pixels[i]);
    return mean;
}

// Checkpoints at 1, 2, 4, ... passes and at the last; the run ends at the first checkpoint past
// maxSeconds, or where adaptive sampling (options.noiseThreshold > 0) finished every pixel.
ConvergenceRun runOne(const std::string& label, const LoadedScene& loaded, const Camera& camera,
                      const RenderOptions& options, const Reference& reference,
                      const ConvergenceSettings& settings, const std::string& variant = "") {
    RenderSession session(loaded.scene, camera, options.renderSettings(loaded.scene),
                          {0, settings.maxPasses});
    const RenderSettings& render = session.settings();
    ConvergenceRun run{label,
                       loaded.scenePath().string(),
                       std::string(samplerName(render.integrator.sampler)),
                       variant,
                       render.integrator.depth,
                       render.integrator.nextEventEstimation,
                       session.threadCount(),
                       reference.kind,
                       {}};
    ProgressReporter progress(run.scene + "/" + run.sampler + (variant.empty() ? "" : "/" + variant) +
                                  "/d" + std::to_string(run.depth),
                              settings.maxPasses, kPathsPerPass);
    double cpuSeconds = 0.0;
    for (uint32_t passes = 1; !session.finished({}); passes *= 2) {
        const double cpuStart = processCpuSeconds();
        renderWithProgress(session, {passes * kPathsPerPass}, progress);
        cpuSeconds += processCpuSeconds() - cpuStart;
        // Measured outside the render time.
        const ImageError error = measure(session.buffer().meanImage(), reference);
        const RenderCounters counters = session.counters();
        const double seconds = session.renderSeconds();
        run.checkpoints.push_back(Checkpoint{seconds, cpuSeconds, session.spp(), counters.paths,
                                             counters.rays, error.mse, error.rmse, error.relMse,
                                             efficiency(error.relMse, seconds),
                                             session.buffer().droppedSamples()});
        if (seconds >= settings.maxSeconds) break;
    }
    progress.finish(session.completedPasses(), session.counters().paths);
    return run;
}

void writeRunCsv(const std::filesystem::path& dir, const ConvergenceRun& run) {
    Table table{{"scene", "sampler", "depth", "nee", "reference", "seconds", "cpu_seconds", "spp",
                 "paths", "rays",
                 "mse", "rmse", "relmse", "efficiency", "nonfinite"},
                {}};
    for (const Checkpoint& c : run.checkpoints) {
        table.add({run.scene, run.sampler, std::to_string(run.depth), run.nee ? "1" : "0",
                   run.reference, cell("%.6g", c.seconds), cell("%.6g", c.cpuSeconds),
                   std::to_string(c.spp),
                   std::to_string(c.paths), std::to_string(c.rays), cell("%.6g", c.mse),
                   cell("%.6g", c.rmse), cell("%.6g", c.relMse), cell("%.6g", c.efficiency),
                   std::to_string(c.nonFinite)});
    }
    writeFile(dir / ("convergence-" + run.scene + "-" + run.sampler +
                     (run.variant.empty() ? "" : "-" + run.variant) + "-d" + std::to_string(run.depth) + ".csv"),
              table.csv());
}

void plotErrorAgainstTime(const std::filesystem::path& dir, const std::vector<ConvergenceRun>& runs) {
    if (runs.empty()) return;
    const std::string stem = runs.front().scene + "-d" + std::to_string(runs.front().depth);
    std::string script =
        "set terminal pngcairo noenhanced size 640,440 font ',10'\n"
        "set output 'error-vs-time-" + stem + ".png'\n"
        "set datafile separator ','\n"
        "set logscale xy\nset format y '%g'\nset grid\nset key top right\n"
        "set xlabel 'render CPU seconds (" + threadsText(runs.front().threads) + ")'\n"
        "set ylabel 'RMSE against the reference'\n"
        "set title '" + runs.front().scene + ", depth " + std::to_string(runs.front().depth) +
        " (" + runs.front().reference + " reference)'\n"
        "plot ";
    for (size_t i = 0; i < runs.size(); ++i) {
        script += (i ? ", " : "") + std::string("'convergence-") + runs[i].scene + "-" +
                  runs[i].sampler + "-d" + std::to_string(runs[i].depth) +
                  ".csv' using 'cpu_seconds':'rmse' with linespoints lw 2 title '" + runs[i].sampler + "'";
    }
    runGnuplot(dir, "error-vs-time-" + stem, script + "\n");
}

template <typename Get>
std::vector<double> column(const ConvergenceRun& run, Get get) {
    std::vector<double> values;
    for (const Checkpoint& c : run.checkpoints) values.push_back(get(c));
    return values;
}

std::string slopeVerdict(const PowerLawFit& fit) {
    // Monte Carlo's rate is spp^-1/2; the paper claims a faster one (notes section 4 (ii)).
    const double tolerance = std::max(0.1, 3.0 * fit.slopeStandardError);
    if (std::fabs(fit.slope + 0.5) <= tolerance) return "~ -1/2 (plain Monte Carlo rate)";
    if (std::fabs(fit.slope + 1.0) <= tolerance) return "~ -1 (the paper's claimed rate)";
    return fit.slope > -0.5 ? "slower than -1/2 (bias or reference noise floor?)"
                            : "between -1/2 and -1";
}

}  // namespace

std::optional<Reference> findReference(const LoadedScene& loaded, const Camera& camera,
                                       const RenderOptions& options, const ConvergenceSettings& settings) {
    const PathIntegratorSettings integrator = options.renderSettings(loaded.scene).integrator;
    if (auto exact = furnaceRadiance(loaded.scene, camera.pose(), integrator)) {
        return Reference{exact, {}, "analytic", {}};
    }
    if (settings.referenceFile) {
        Image image = readExr(*settings.referenceFile);
        if (image.width != camera.width() || image.height != camera.height()) {
            throw Error("--reference " + settings.referenceFile->string() + ": " +
                        std::to_string(image.width) + "x" + std::to_string(image.height) +
                        ", but the bench renders " + std::to_string(camera.width()) + "x" +
                        std::to_string(camera.height()) + " (use --width)");
        }
        return Reference{std::nullopt, std::move(image), "file", {}};
    }
    const auto path = referencePath(settings.outDir / "references", loaded, camera, integrator);
    auto halfPath = path;
    halfPath.replace_extension().concat("-half.exr");
    if (std::filesystem::is_regular_file(path) && std::filesystem::is_regular_file(halfPath)) {
        return renderedReference(readExr(path), readExr(halfPath), "cache");
    }
    if (!settings.makeReference) {
        std::fprintf(stderr, "note: no reference %s for %s; run with --make-reference (skipped)\n",
                     path.string().c_str(), loaded.scenePath().string().c_str());
        return std::nullopt;
    }
    std::filesystem::create_directories(path.parent_path());
    const auto [first, second] = renderReferenceHalves(loaded, camera, options, settings);
    Image image = meanOf(first, second);
    writeImage(halfPath, first);
    writeImage(path, image);
    std::fprintf(stderr, "wrote reference %s and its first half\n", path.string().c_str());
    return renderedReference(std::move(image), first, "made");
}

std::vector<ConvergenceRun> runConvergence(const ConvergenceSettings& settings) {
    std::vector<ConvergenceRun> runs;
    std::map<std::string, int> uses;  // two scenes may share a name (assets/cornell, shared cornell)
    for (const auto& scenePath : settings.scenes) {
        const LoadedScene loaded = loadScene(scenePath, std::nullopt, settings.files);
        std::string label = sceneName(loaded.scenePath());
        if (const int n = ++uses[label]; n > 1) label.append("-").append(std::to_string(n));
        std::fprintf(stderr, "bench scene %s: %s\n", label.c_str(), scenePath.string().c_str());
        const int height = std::max(1, static_cast<int>(std::lround(
            static_cast<double>(settings.width) * loaded.settings.height / loaded.settings.width)));
        const Camera camera(loaded.settings.pose, settings.width, height);
        for (int depth : settings.depths) {
            // The programs' defaults: next-event estimation and Russian roulette on.
            RenderOptions options;
            options.depth = depth;
            options.seed = settings.seed;
            options.threads = settings.threads;
            const auto reference = findReference(loaded, camera, options, settings);
            if (!reference) continue;
            std::vector<ConvergenceRun> group;
            for (const auto& name : settings.samplers) {
                options.sampler = name;
                group.push_back(runOne(label, loaded, camera, options, *reference, settings));
                writeRunCsv(settings.outDir, group.back());
            }
            plotErrorAgainstTime(settings.outDir, group);
            runs.insert(runs.end(), group.begin(), group.end());
            if (!settings.skips) continue;
            options.sampler = "strata24";
            RenderOptions noRoulette = options;
            noRoulette.rouletteDepth = -1;
            RenderOptions adaptive = options;
            adaptive.noiseThreshold = kBenchNoiseThreshold;
            for (const auto& [variant, variantOptions] : {std::pair{kNoRouletteVariant, noRoulette},
                                                          std::pair{"adaptive-5pct", adaptive}}) {
                runs.push_back(runOne(label, loaded, camera, variantOptions, *reference, settings, variant));
                writeRunCsv(settings.outDir, runs.back());
            }
        }
    }
    return runs;
}

// A run whose error is exactly zero at some checkpoint: a zero-variance estimator on an analytic
// scene (cosine or BSDF sampling of the furnace). No power law or ratio is defined for it.
bool exact(const ConvergenceRun& run) {
    return std::any_of(run.checkpoints.begin(), run.checkpoints.end(),
                       [](const Checkpoint& c) { return !(c.rmse > 0.0); });
}

std::string skipsSummary(const std::vector<ConvergenceRun>& runs) {
    Table table{{"scene", "depth", "skip", "with: MSE", "with: CPU-s", "without: MSE", "without: CPU-s",
                 "time to the same error, with / without"},
                {}};
    for (const auto& run : runs) {
        if (run.variant.empty() || run.checkpoints.empty()) continue;
        const auto plain = std::find_if(runs.begin(), runs.end(), [&](const ConvergenceRun& r) {
            return r.scene == run.scene && r.depth == run.depth && r.sampler == run.sampler &&
                   r.variant.empty() && !r.checkpoints.empty();
        });
        if (plain == runs.end()) continue;
        // The plain run has roulette and the variant not; adaptive sampling the other way round.
        const bool rouletteOff = run.variant == kNoRouletteVariant;
        const Checkpoint& with = rouletteOff ? plain->checkpoints.back() : run.checkpoints.back();
        const Checkpoint& without = rouletteOff ? run.checkpoints.back() : plain->checkpoints.back();
        const std::string skip =
            rouletteOff ? "Russian roulette from bounce " + std::to_string(kRouletteDepthDefault)
                        : std::string("adaptive sampling, threshold 5%");
        const bool exactBoth = !(with.mse > 0.0) || !(without.mse > 0.0);
        table.add({run.scene, std::to_string(run.depth), skip, cell("%.4g", with.mse),
                   cell("%.3f", with.cpuSeconds), cell("%.4g", without.mse), cell("%.3f", without.cpuSeconds),
                   exactBoth ? "- (zero error)"
                             : cell("%.3f", (with.mse * with.cpuSeconds) / (without.mse * without.cpuSeconds))});
    }
    return "### What each skip gains (strata24)\n\n" + table.markdown() +
           "\nBelow 1: the skip reaches the same error sooner (Monte Carlo's error^2 ~ 1/time, "
           "taken at the last checkpoint). The black early out applies only to a scene no light "
           "reaches, which none of these is: such a scene takes no time instead of a full render.\n";
}

std::string convergenceSummary(const std::vector<ConvergenceRun>& runs) {
    Table finals{{"scene", "depth", "sampler", "reference", "spp", "seconds", "CPU-s", "Mpaths/CPU-s",
                  "Mrays/CPU-s",
                  "RMSE", "relMSE", "efficiency 1/(relMSE s)", "RMSE slope vs spp", "verdict"},
                 {}};
    // Group the runs of one (scene, depth) to compare samplers.
    std::map<std::pair<std::string, int>, std::vector<const ConvergenceRun*>> groups;
    for (const auto& run : runs) {
        if (!run.variant.empty()) continue;  // skipsSummary's
        groups[{run.scene, run.depth}].push_back(&run);
        if (run.checkpoints.empty()) continue;
        const Checkpoint& last = run.checkpoints.back();
        std::string slope = "-", verdict = "-";
        if (exact(run)) {
            slope = "exact";
            verdict = "zero error: a zero-variance estimator here";
        } else if (run.checkpoints.size() >= 3) {
            const PowerLawFit fit = fitPowerLaw(column(run, [](auto& c) { return double(c.spp); }),
                                                column(run, [](auto& c) { return c.rmse; }));
            slope = cell("%.3f +- %.3f", fit.slope, fit.slopeStandardError);
            verdict = slopeVerdict(fit);
        }
        finals.add({run.scene, std::to_string(run.depth), run.sampler, run.reference,
                    std::to_string(last.spp), cell("%.3f", last.seconds), cell("%.3f", last.cpuSeconds),
                    cell("%.3f", last.paths / last.cpuSeconds * 1e-6),
                    cell("%.3f", last.rays / last.cpuSeconds * 1e-6), cell("%.4g", last.rmse),
                    cell("%.4g", last.relMse), cell("%.4g", last.efficiency), slope, verdict});
    }

    Table ratios{{"scene", "depth", "sampler / uniform", "measured Var ratio (equal spp)",
                  "paper sec. 3: 1/24", "paper sec. 4: (N-1)/(23N) at last N", "verdict",
                  "RMSE ratio at equal time", "time ratio at equal RMSE"},
                 {}};
    for (const auto& [key, group] : groups) {
        const auto uniform = std::find_if(group.begin(), group.end(),
                                          [](auto* r) { return r->sampler == "uniform"; });
        if (uniform == group.end()) continue;
        const ConvergenceRun& base = **uniform;
        for (const ConvergenceRun* run : group) {
            if (run == &base) continue;
            const size_t n = std::min(run->checkpoints.size(), base.checkpoints.size());
            if (n == 0) continue;
            if (exact(*run) || exact(base)) {
                ratios.add({key.first, std::to_string(key.second), run->sampler,
                            exact(*run) ? "0 (exact)" : "inf (uniform exact)",
                            cell("%.4f", kPaperSection3Ratio), "-", "zero error: no ratio to fit", "-", "-"});
                continue;
            }
            std::vector<double> a, b;
            for (size_t i = 0; i < n; ++i) {
                a.push_back(run->checkpoints[i].mse);
                b.push_back(base.checkpoints[i].mse);
            }
            const double ratio = varianceRatio(a, b);
            const double lastN = run->checkpoints[n - 1].spp;
            const double claim4 = paperSection4Ratio(lastN);
            std::string verdict = ratio < 1.0 ? cell("lower variance, by x%.2f; ", 1.0 / ratio)
                                              : std::string("no variance reduction; ");
            verdict += ratio > 2.0 * kPaperSection3Ratio
                           ? cell("the paper's 1/24 is contradicted (%.1fx larger)", ratio * 24.0)
                           : std::string("consistent with the paper's 1/24");
            // Equal time: both curves at the shorter run's end; equal error: the larger final error.
            const auto ts = column(*run, [](auto& c) { return c.cpuSeconds; });
            const auto tu = column(base, [](auto& c) { return c.cpuSeconds; });
            const auto es = column(*run, [](auto& c) { return c.rmse; });
            const auto eu = column(base, [](auto& c) { return c.rmse; });
            const double commonTime = std::min(ts.back(), tu.back());
            const auto errorS = interpolateLogLog(ts, es, commonTime);
            const auto errorU = interpolateLogLog(tu, eu, commonTime);
            const double commonError = std::max(es.back(), eu.back());
            const auto timeS = firstReach(ts, es, commonError);
            const auto timeU = firstReach(tu, eu, commonError);
            ratios.add({key.first, std::to_string(key.second), run->sampler, cell("%.3f", ratio),
                        cell("%.4f", kPaperSection3Ratio), cell("%.4f", claim4), verdict,
                        errorS && errorU ? cell("%.3f at %.2f CPU-s", *errorS / *errorU, commonTime) : "-",
                        timeS && timeU ? cell("%.3f at RMSE %.3g", *timeS / *timeU, commonError) : "-"});
        }
    }
    Table files{{"scene", "file", "reference"}, {}};
    for (const auto& [key, group] : groups) {
        if (key.second == groups.begin()->first.second) {
            files.add({key.first, group.front()->sceneFile, group.front()->reference});
        }
    }
    return "### Scenes\n\n" + files.markdown() +
           "\n### Error against time (last checkpoint per run)\n\n" + finals.markdown() +
           "\nSlopes are least-squares fits of log RMSE on log spp over all checkpoints (+- one "
           "standard error). The MSE includes the reference's own noise (references: 16x or more "
           "the bench's largest spp, analytic where exact), which flattens the last checkpoints a "
           "little.\n\n### Variance ratio against the paper's claims, equal time, equal error\n\n" +
           ratios.markdown() +
           "\nRatios below 1 favour the sampler over uniform. The variance ratio is the geometric "
           "mean of MSE ratios over checkpoints at equal spp. Equal time and equal error use CPU "
           "seconds: the machine is shared, and wall time moves with other people's load.\n";
}

}  // namespace strata
