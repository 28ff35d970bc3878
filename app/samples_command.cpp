#include "samples_command.h"

#include <CLI/App.hpp>
#include <cstdio>
#include <memory>

#include "sampling/direction_sampler.h"
#include "usage.h"
#include "util/error.h"
#include "integrator/progressive_renderer.h"

namespace strata {
namespace {

struct SamplesCommand {
    std::string sampler = "strata24";
    uint32_t passes = 1;
    uint64_t seed = 0;
    int depth = 1;
    uint64_t pixel = 0;

    void run() const {
        const auto kind = parseSamplerKind(sampler);
        if (!kind) throw UsageError("--sampler: unknown sampler '" + sampler + "' (use " + samplerNames() + ")");
        if (passes < 1 || passes > 1000000) throw UsageError("--passes: must be in 1..1000000");
        if (depth < 1 || depth > 64) throw UsageError("--depth: must be in 1..64 (bounces to list)");
        std::printf("pass,path,bounce,stratum,x,y,z\n");
        for (uint32_t pass = 0; pass < passes; ++pass) {
            for (int path = 0; path < kPathsPerPass; ++path) {
                const PathSamples samples(seed, pixel, pass, path);
                for (int bounce = 0; bounce < depth; ++bounce) {
                    const SampledDirection d = sampleDirection(*kind, samples, bounce);
                    std::printf("%u,%d,%d,%d,%.9g,%.9g,%.9g\n", pass, path, bounce, d.stratum,
                                d.local.x, d.local.y, d.local.z);
                }
            }
        }
    }
};

}  // namespace

void addSamplesCommand(CLI::App& app) {
    auto command = std::make_shared<SamplesCommand>();
    CLI::App* sub = app.add_subcommand(
        "samples", "Print a pixel's sampled directions as CSV");
    sub->add_option("--sampler", command->sampler, "Sampler: " + samplerNames())->capture_default_str();
    sub->add_option("--passes", command->passes, "Passes of 24 paths")->capture_default_str();
    acceptUnsigned64(*sub->add_option("--seed", command->seed, "Random seed")->capture_default_str());
    sub->add_option("--depth", command->depth, "Bounces per path to list")->capture_default_str();
    sub->add_option("--pixel", command->pixel, "Pixel index (y * width + x)")->capture_default_str();
    sub->callback([command] { command->run(); });
}

}  // namespace strata
