#pragma once
// `strata bench`, part 1: run time against error. For each scene, sampler and depth, render
// progressively, checkpoint at spp = 24, 48, 96, ... and measure the error against a reference
// (reference_cache.h), then read the curves: slopes, variance ratios against the paper's claims,
// equal-time and equal-error comparisons.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "bench/bench_output.h"
#include "bench/reference_cache.h"
#include "io/image_io.h"
#include "render_options.h"

namespace strata {

struct ConvergenceSettings {
    std::vector<std::filesystem::path> scenes;
    SceneReadOptions files;  // what reading them may read (--allow-outside-files)
    std::vector<std::string> samplers;  // names from direction_sampler.h
    std::vector<int> depths;
    int width = 128;            // image width; the height keeps the scene's aspect
    uint32_t maxPasses = 32;    // last checkpoint: 24 * maxPasses spp
    double maxSeconds = 60.0;   // per run: stops at the first checkpoint past it
    uint32_t referencePasses = 512;
    bool makeReference = false;
    std::optional<std::filesystem::path> referenceFile;
    uint64_t seed = 0;
    int threads = 0;
    std::filesystem::path outDir;
    // Also run strata24 with each of the renderer's skips (docs/design.md, "Skip what a scene
    // does not need") switched the other way: Russian roulette off, adaptive sampling on.
    // skipsSummary compares each with the plain strata24 run (the programs' defaults).
    bool skips = false;
};

struct Checkpoint {
    double seconds = 0.0;     // wall render time only (error measurement excluded)
    double cpuSeconds = 0.0;  // the same in process CPU time, robust on a shared machine
    uint32_t spp = 0;
    uint64_t paths = 0;
    uint64_t rays = 0;
    double mse = 0.0;
    double rmse = 0.0;
    double relMse = 0.0;
    double efficiency = 0.0;
    uint64_t nonFinite = 0;
};

struct ConvergenceRun {
    std::string scene;      // a unique label: the scene's name, "-2" etc. when names repeat
    std::string sceneFile;  // the OBJ
    std::string sampler;
    std::string variant;  // empty for the plain run, else which skip was switched (see skips)
    int depth = 0;
    bool nee = false;
    int threads = 0;        // the render threads it ran on
    std::string reference;  // "analytic", "cache", "file" or "made"
    std::vector<Checkpoint> checkpoints;
};

// The reference for `loaded` seen by `camera` at `options`' depth and next-event flag: analytic
// for a furnace (reference_cache.h), else settings.referenceFile, else the cached render in
// OUT/references, else (settings.makeReference) a render of settings.referencePasses passes with
// `options`' sampler stored there; nullopt, with a note, when there is none. Throws strata::Error
// for a --reference file of the wrong size. A render is made as two halves of independent seeds
// (renderedReference), the first stored beside the mean as NAME-dK-KEY-half.exr.
std::optional<Reference> findReference(const LoadedScene& loaded, const Camera& camera,
                                       const RenderOptions& options, const ConvergenceSettings& settings);

// Runs every (scene, depth, sampler), writing convergence-SCENE-SAMPLER-dK.csv per run and one
// error-against-time plot per (scene, depth). Scenes without a reference are skipped with a note.
std::vector<ConvergenceRun> runConvergence(const ConvergenceSettings& settings);

// The analysis tables (markdown) for the summary: per-run final figures, slopes and variance
// ratios against the paper, equal-time and equal-error comparisons.
std::string convergenceSummary(const std::vector<ConvergenceRun>& runs);

// Each skip's gain: time to the same error with the skip against without it, taken as the ratio
// of MSE x CPU seconds at the last checkpoint (Monte Carlo's error^2 ~ 1/time).
std::string skipsSummary(const std::vector<ConvergenceRun>& runs);

}  // namespace strata
