#pragma once
// Progress of a long render, or of a bench section's runs, on stderr: a redrawn bar when stderr is
// a terminal, plain lines every few seconds otherwise (logs, CI).
#include <chrono>
#include <cstdint>
#include <string>

namespace strata {

class ProgressReporter {
public:
    // A render's passes of `pathsPerPass` paths each: its spp and paths per second besides.
    ProgressReporter(std::string label, uint64_t totalPasses, int pathsPerPass);
    // Steps that are not passes (a race's runs, a section's stages), each called `step`: counted
    // alone.
    ProgressReporter(std::string label, uint64_t totalSteps, std::string step);
    // Called after each pass or step, with the paths traced so far (0 for steps); prints when it
    // is time to.
    void update(uint64_t done, uint64_t paths);
    void finish(uint64_t done, uint64_t paths);
    double elapsedSeconds() const;

private:
    ProgressReporter(std::string label, uint64_t total, std::string step, int pathsPerPass);
    void print(uint64_t done, uint64_t paths, bool final);

    std::string label_;
    uint64_t total_;
    std::string step_;
    int pathsPerPass_;  // 0 for steps
    bool terminal_;
    std::chrono::steady_clock::time_point start_;
    std::chrono::steady_clock::time_point lastPrint_;
};

}  // namespace strata
