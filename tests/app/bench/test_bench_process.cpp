#include <doctest/doctest.h>

#include <fstream>
#include <string>
#include <unistd.h>

#include "bench/bench_process.h"
#include "test_support.h"

using namespace strata;

TEST_CASE("bench process: a child's log is written through an exclusive temporary, never a planted symlink") {
    const auto dir = test::scratchDir("bench-process-log");
    std::ofstream(dir / "victim") << "precious";
    const auto log = dir / "child.log";
    const std::string pid = std::to_string(getpid());
    for (const std::string& suffix : {".tmp-" + pid, ".tmp" + pid, ".tmp-" + pid + "-0", ".tmp-" + pid + "-1"}) {
        std::filesystem::create_symlink(dir / "victim", dir / ("child.log" + suffix));
    }
    // A symlink at the log's own name is replaced, not written through.
    std::filesystem::create_symlink(dir / "victim", log);
    const ProcessTiming timing = runTimed({"sh", "-c", "echo out; echo err >&2"}, log);
    CHECK(timing.ok());
    CHECK(test::fileBytes(dir / "victim") == "precious");
    CHECK(!std::filesystem::is_symlink(log));
    CHECK(test::fileBytes(log) == "out\nerr\n");
    // A program that cannot start leaves an empty log, as the notes that name the log expect.
    CHECK(!runTimed({"strata-test-no-such-program"}, dir / "missing.log").ok());
    CHECK(test::fileBytes(dir / "missing.log").empty());
    CHECK(std::filesystem::exists(dir / "missing.log"));
}
