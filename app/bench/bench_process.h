#pragma once
// Timing another program from start to exit, for the bench's comparisons between whole processes
// (Embree's tutorial path tracer, `strata render` under mpiexec).
#include <filesystem>
#include <string>
#include <vector>

namespace strata {

struct ProcessTiming {
    double wall = -1.0;  // seconds; negative: the program could not start or exited non-zero
    double cpu = 0.0;    // user + system CPU seconds of the child and its children
};

// Runs argv (found on PATH when argv[0] has no slash), its stdout and stderr into `log`.
ProcessTiming runTimed(std::vector<std::string> argv, const std::filesystem::path& log);

double median(std::vector<double> values);

}  // namespace strata
