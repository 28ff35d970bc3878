#pragma once
// `strata bench`, part 2: speed. The path tracer's Mrays/s and Mpaths/s against Embree's own
// ceiling for incoherent rays on the same scene (ray_throughput.h); thread scaling; cost against
// resolution and triangle count; peak memory of a 1920x1080 render; the samplers' cost
// (ns/sample, and strata24 against uniform render speed).
#include <cstdint>
#include <filesystem>
#include <string>

namespace strata {

struct ThroughputSettings {
    std::filesystem::path scene;
    int depth = 5;
    int threads = 0;  // 0: all cores
    bool quick = false;
    uint64_t seed = 0;
    std::filesystem::path outDir;
};

// Runs every measurement, writes throughput CSVs and plots to outDir and returns the markdown
// section for the summary.
std::string runThroughput(const ThroughputSettings& settings);

}  // namespace strata
