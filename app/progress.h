#pragma once
// Progress of a long render on stderr: a redrawn bar when stderr is a terminal, plain lines every
// few seconds otherwise (logs, CI).
#include <chrono>
#include <cstdint>
#include <string>

namespace strata {

class ProgressReporter {
public:
    ProgressReporter(std::string label, uint64_t totalPasses, int pathsPerPass);
    // Called after each pass; prints when it is time to.
    void update(uint64_t passesDone, uint64_t paths);
    void finish(uint64_t passesDone, uint64_t paths);
    double elapsedSeconds() const;

private:
    void print(uint64_t passesDone, uint64_t paths, bool final);

    std::string label_;
    uint64_t totalPasses_;
    int pathsPerPass_;
    bool terminal_;
    std::chrono::steady_clock::time_point start_;
    std::chrono::steady_clock::time_point lastPrint_;
};

}  // namespace strata
