// strata: the command-line front end. Each subcommand lives in its own file; this one only parses
// and turns every failure into one line on stderr and a non-zero exit: 2 for a usage error (an
// unknown command or option, an option's value out of range), 1 for an input error (a missing or
// malformed file) or a failure while rendering.
#include <cstdio>
#include <malloc.h>
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
#include "usage.h"
#include "view_command.h"

int main(int argc, char** argv) {
    // A run allocates and frees large blocks more than once (a parser's growing arrays, images);
    // glibc maps each block over 128 KiB afresh and unmaps it when freed, so its pages fault in
    // again every time. Kept in the heap, freed blocks are reused (util/prefault.h on what a fault
    // costs; docs/performance.md on what this saves).
    mallopt(M_MMAP_THRESHOLD, 32 << 20);
    mallopt(M_TRIM_THRESHOLD, 1 << 30);
    // Named, so that usage lines say `strata` rather than the path it was started by.
    CLI::App app("Strata: a progressive path tracer with the 24-stratum hemisphere estimator", "strata");
    app.set_version_flag("--version", STRATA_VERSION_TEXT, "Print the version and exit");
    app.footer(std::string("With no scene, render and view show the bundled Cornell box.\n"
                           "`strata COMMAND --help` lists a command's options.\n") +
               strata::kExitStatusHelp);
    app.require_subcommand(1);
    strata::addBenchCommand(app);
    strata::addRenderCommand(app);
    strata::addSamplesCommand(app);
    strata::addViewCommand(app);
    std::vector<std::string> commands;
    for (CLI::App* command : app.get_subcommands([](CLI::App*) { return true; })) {
        commands.push_back(command->get_name());
        command->footer(strata::kExitStatusHelp);
    }
    // CLI11 reports a mistyped command only as "a subcommand is required"; name it instead.
    if (argc > 1 && argv[1][0] != '-') {
        try {
            app.get_subcommand(argv[1]);
        } catch (const CLI::OptionNotFound&) {
            const auto nearest = strata::nearestName(argv[1], commands);
            const std::string suggestion = nearest ? "; did you mean '" + *nearest + "'?" : "";
            std::fprintf(stderr, "strata: unknown command '%s'%s (see strata --help)\n", argv[1],
                         suggestion.c_str());
            return strata::kUsageExitStatus;
        }
    }
    try {
        app.parse(argc, argv);
    } catch (const CLI::Success& e) {  // --help, --version
        return app.exit(e);
    } catch (const CLI::ParseError& e) {
        std::fprintf(stderr, "strata: %s\n", strata::describeParseError(app, e).c_str());
        return strata::kUsageExitStatus;
    } catch (const strata::ErrorReportedByRankZero&) {
        return 0;  // an MPI rank other than 0: rank 0 prints the job's error and exits with its status
    } catch (const strata::UsageError& e) {
        std::fprintf(stderr, "strata: %s\n", e.what());
        return strata::kUsageExitStatus;
    } catch (const strata::Error& e) {
        std::fprintf(stderr, "strata: %s\n", e.what());
        return strata::kInputExitStatus;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "strata: unexpected failure: %s\n", e.what());
        return strata::kInputExitStatus;
    }
    return 0;
}
