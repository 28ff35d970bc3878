#include <doctest/doctest.h>

#include <string>

#include "test_support.h"

// The program's answers to command lines it cannot run (app/usage.h).
using namespace strata;

TEST_CASE("usage: every command's help states the exit statuses") {
    for (const std::string command : {"", "render ", "view ", "bench ", "samples "}) {
        const auto help = test::runStrata(command + "--help");
        CAPTURE(command);
        REQUIRE(help.exitCode == 0);
        CHECK(help.out.find("Exit status: 0 done; 1 bad input") != std::string::npos);
        CHECK(help.out.find("2 bad usage") != std::string::npos);
    }
}

TEST_CASE("usage: unknown options get one line with the nearest known one, for every command, and exit 2") {
    const struct {
        std::string arguments;
        std::string expected;
    } cases[] = {
        {"render --sp 24", "unknown option '--sp'; did you mean '--spp'? (see strata render --help)"},
        {"render --spp=24 --thread 2", "unknown option '--thread'; did you mean '--threads'? (see strata render --help)"},
        // Two letters swapped count as one edit.
        {"render --widht 8", "unknown option '--widht'; did you mean '--width'? (see strata render --help)"},
        {"render --hieght 8", "unknown option '--hieght'; did you mean '--height'? (see strata render --help)"},
        {"render --sampel uniform", "unknown option '--sampel'; did you mean '--sampler'? (see strata render --help)"},
        // The only option the typed name begins.
        {"render --noise 0.1", "unknown option '--noise'; did you mean '--noise-threshold'? (see strata render --help)"},
        {"render --env-rot 90", "unknown option '--env-rot'; did you mean '--env-rotate'? (see strata render --help)"},
        // Near nothing, or the start of several: no guess.
        {"render --frobnicate", "unknown option '--frobnicate' (see strata render --help)"},
        {"render --e 1", "unknown option '--e' (see strata render --help)"},
        {"view --frame 3", "unknown option '--frame'; did you mean '--frames'? (see strata view --help)"},
        {"bench --quik", "unknown option '--quik'; did you mean '--quick'? (see strata bench --help)"},
        {"samples --pases 2", "unknown option '--pases'; did you mean '--passes'? (see strata samples --help)"},
        {"veiw", "unknown command 'veiw'; did you mean 'view'? (see strata --help)"},
        {"sample", "unknown command 'sample'; did you mean 'samples'? (see strata --help)"},
        {"paint", "unknown command 'paint' (see strata --help)"},
    };
    for (const auto& c : cases) {
        const auto result = test::runStrata(c.arguments);
        CAPTURE(c.arguments);
        CHECK(result.exitCode == 2);
        CHECK(result.err == "strata: " + c.expected + "\n");
    }
}
