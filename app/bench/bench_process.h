#pragma once
// Running another program from start to exit: every child of the bench goes through here (the
// whole-process comparisons with Embree's tutorial path tracer, `strata render` under mpiexec and
// `strata view`, the memory probe, gnuplot).
#include <filesystem>
#include <string>
#include <vector>
#include <nlohmann/json_fwd.hpp>

namespace strata {

// Memory is not among the figures: the child's rusage counts the bench's own resident set
// (process_memory.h says why); a `strata` child reports its own.
struct ProcessTiming {
    double wall = -1.0;     // seconds; negative: the program could not start or exited non-zero
    double cpu = 0.0;       // user + system CPU seconds of the child and its children
    bool ok() const { return wall >= 0.0; }
};

// Runs argv (found on PATH when argv[0] has no slash) in `directory` (empty: this process's),
// its stdout and stderr into `log` (written through an OutputFile: throws strata::Error when it
// cannot be).
ProcessTiming runTimed(std::vector<std::string> argv, const std::filesystem::path& log,
                       const std::filesystem::path& directory = {});

// What a child that reports in JSON (`strata render --json`, `strata view --json`) printed: the
// last line of its log that is a JSON object; a discarded value (not an object) when none is.
nlohmann::json lastJsonReport(const std::filesystem::path& log);

// Whether `program` (a name without a slash) is an executable file in a folder of PATH.
bool onPath(const std::string& program);

}  // namespace strata
