#pragma once
// Whole programs timed against each other on a shared machine. Each runs `repeats` times, round
// by round, the order rotating every round so that none always runs first (on a machine that the
// previous run left cool, or warm); the figures are medians over the rounds, which one run
// slowed by another tenant moves little.
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace strata {

struct Entrant {
    std::string name;  // names it in tables and in the note when it fails
    std::vector<std::string> argv;
    // After each run that exited 0, given its log: reads what the program reported (the viewer's
    // JSON); false counts the run as failed.
    std::function<bool(const std::filesystem::path& log)> readLog;
    std::vector<double> wall, cpu;  // seconds, one per run

    double medianWall() const;
    double medianCpu() const;
};

// Runs every entrant `repeats` times as above, their output into `log`, showing progress under
// `label`. Returns the name of the first entrant whose run failed (the race stops there), else
// nullopt.
std::optional<std::string> race(std::vector<Entrant>& entrants, int repeats,
                                const std::filesystem::path& log, const std::string& label);

// The middle value (the upper one of the middle two for an even count); `values` not empty.
double median(std::vector<double> values);

}  // namespace strata
