// strata: the command-line front end. Each subcommand lives in its own file; this one only parses
// and turns every failure into one line on stderr and a non-zero exit: 2 for a usage error (an
// unknown command or option, an option's value out of range), 1 for an input error (a missing or
// malformed file) or a failure while rendering.
#include <cstdio>
#include <string>
#include <vector>
#include <CLI/App.hpp>
#include <CLI/Config.hpp>
#include <CLI/Formatter.hpp>

#include "bench/bench_command.h"
#include "util/error.h"
#include "render_command.h"
#include "render_job.h"
#include "samples_command.h"
#include "unknown_option.h"
#include "view_command.h"

int main(int argc, char** argv) {
    // Named, so that usage lines say `strata` rather than the path it was started by.
    CLI::App app("Strata: a progressive path tracer with the 24-stratum hemisphere estimator", "strata");
    app.set_version_flag("--version", STRATA_VERSION_TEXT, "Print the version and exit");
    app.footer("With no scene, render and view show the bundled Cornell box.\n"
               "`strata COMMAND --help` lists a command's options.\n"
               "Exit status: 0 done, 1 an input error (a missing or malformed file) or a failed render,\n"
               "2 a usage error (an unknown command or option, a value out of range).");
    app.require_subcommand(1);
    strata::addBenchCommand(app);
    strata::addRenderCommand(app);
    strata::addSamplesCommand(app);
    strata::addViewCommand(app);
    // CLI11 reports a mistyped command only as "a subcommand is required", and a mistyped option
    // as the words it did not expect; name them instead, with the option meant.
    if (argc > 1 && argv[1][0] != '-') {
        const CLI::App* command = nullptr;
        try {
            command = app.get_subcommand(argv[1]);
        } catch (const CLI::OptionNotFound&) {
            std::fprintf(stderr, "strata: unknown command '%s' (see --help)\n", argv[1]);
            return 2;
        }
        const std::vector<std::string> arguments(argv + 2, argv + argc);
        if (const auto message = strata::unknownOptionMessage(*command, arguments)) {
            std::fprintf(stderr, "strata: %s: %s (see strata %s --help)\n", argv[1], message->c_str(), argv[1]);
            return 2;
        }
    }
    try {
        app.parse(argc, argv);
    } catch (const CLI::Success& e) {  // --help, --version
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::fprintf(stderr, "strata: %s (see --help)\n", e.what());
        return 2;
    } catch (const strata::UsageError& e) {
        std::fprintf(stderr, "strata: %s (see --help)\n", e.what());
        return 2;
    } catch (const strata::ErrorReportedByRankZero&) {
        return 1;  // an MPI rank other than 0: rank 0 printed the job's error
    } catch (const strata::Error& e) {
        std::fprintf(stderr, "strata: %s\n", e.what());
        return 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "strata: unexpected failure: %s\n", e.what());
        return 1;
    }
    return 0;
}
