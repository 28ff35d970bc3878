#pragma once
// Running another program from start to exit, for the bench's comparisons between whole
// processes (Embree's tutorial path tracer, `strata render` under mpiexec, `strata view`) and its
// memory probe.
#include <filesystem>
#include <string>
#include <vector>

namespace strata {

struct ProcessTiming {
    double wall = -1.0;     // seconds; negative: the program could not start or exited non-zero
    double cpu = 0.0;       // user + system CPU seconds of the child and its children
    long peakRssKiB = 0;    // the largest resident set of the child and its children
    bool ok() const { return wall >= 0.0; }
};

// Runs argv (found on PATH when argv[0] has no slash), its stdout and stderr into `log`.
ProcessTiming runTimed(std::vector<std::string> argv, const std::filesystem::path& log);

}  // namespace strata
