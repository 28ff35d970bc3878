// This process's peak resident memory, and a child's as it reports it (process_memory.h).
#include <doctest/doctest.h>

#include <fstream>
#include <string>
#include <vector>

#include "bench/bench_process.h"
#include "bench/process_memory.h"
#include "test_support.h"

using namespace strata;

namespace {

// This process's resident set now (VmRSS), KiB. The peak so far may lie above it: in a suite run
// as one process, earlier tests may have held more than is resident now.
long residentKiB() {
    std::ifstream status("/proc/self/status");
    for (std::string line; std::getline(status, line);) {
        if (line.rfind("VmRSS:", 0) == 0) return std::stol(line.substr(6));
    }
    return 0;
}

}  // namespace

TEST_CASE("process memory: VmHWM follows this process's own pages, and a child reports its own, not its parent's") {
    REQUIRE(peakResidentKiB() > 0);
    const long before = residentKiB();
    REQUIRE(before > 0);
    // 256 MiB touched page by page: the resident set grows by that much, and the peak with it.
    std::vector<char> ballast(256u << 20);
    for (size_t i = 0; i < ballast.size(); i += 4096) ballast[i] = 1;
    CHECK(peakResidentKiB() >= before + (250L << 10));
    // A small render in a child: what it reports is far below the parent's 256 MiB, which the
    // rusage of a spawned child would include.
    const auto dir = test::scratchDir("process-memory");
    const ProcessTiming timing = runTimed({STRATA_BINARY, "render", "--width", "16", "--height", "16", "--spp", "24",
                                           "--depth", "1", "--threads", "1", "--json"}, dir / "render.log");
    REQUIRE(timing.ok());
    const long child = reportedPeakResidentKiB(dir / "render.log");
    CHECK(child > 0);
    CHECK(child < (160L << 10));
    CHECK(ballast[ballast.size() - 4096] == 1);
    // A log without a report reads as none.
    REQUIRE(runTimed({"sh", "-c", "echo no report"}, dir / "none.log").ok());
    CHECK(reportedPeakResidentKiB(dir / "none.log") == -1);
}
