#include "progress.h"

#include <cstdio>
#include <string>
#include <unistd.h>

namespace strata {
namespace {
using Clock = std::chrono::steady_clock;
constexpr auto kTerminalInterval = std::chrono::milliseconds(100);
constexpr auto kLogInterval = std::chrono::seconds(5);
}  // namespace

ProgressReporter::ProgressReporter(std::string label, uint64_t totalPasses, int pathsPerPass)
    : ProgressReporter(std::move(label), totalPasses, "pass", pathsPerPass) {}

ProgressReporter::ProgressReporter(std::string label, uint64_t totalSteps, std::string step)
    : ProgressReporter(std::move(label), totalSteps, std::move(step), 0) {}

ProgressReporter::ProgressReporter(std::string label, uint64_t total, std::string step, int pathsPerPass)
    : label_(std::move(label)),
      total_(total),
      step_(std::move(step)),
      pathsPerPass_(pathsPerPass),
      terminal_(isatty(STDERR_FILENO) != 0),
      start_(Clock::now()),
      lastPrint_(start_) {}

double ProgressReporter::elapsedSeconds() const {
    return std::chrono::duration<double>(Clock::now() - start_).count();
}

void ProgressReporter::update(uint64_t done, uint64_t paths) {
    const auto now = Clock::now();
    if (now - lastPrint_ < (terminal_ ? kTerminalInterval : kLogInterval)) return;
    lastPrint_ = now;
    print(done, paths, false);
}

void ProgressReporter::finish(uint64_t done, uint64_t paths) { print(done, paths, true); }

void ProgressReporter::print(uint64_t done, uint64_t paths, bool final) {
    const double elapsed = elapsedSeconds();
    const double fraction = total_ ? static_cast<double>(done) / total_ : 1.0;
    const double eta = fraction > 0.0 ? elapsed * (1.0 - fraction) / fraction : 0.0;
    // The same fields either way: set apart by two spaces after a redrawn bar, by commas in a log.
    const char* separator = terminal_ ? "  " : ", ";
    char field[96];
    std::snprintf(field, sizeof field, "%s %llu/%llu", step_.c_str(), static_cast<unsigned long long>(done),
                  static_cast<unsigned long long>(total_));
    std::string line = field;
    const auto add = [&] { (line += separator) += field; };
    // A pass's figures: its spp so far and the paths per second.
    if (pathsPerPass_ > 0) {
        std::snprintf(field, sizeof field, "%llu spp", static_cast<unsigned long long>(done * pathsPerPass_));
        add();
    }
    std::snprintf(field, sizeof field, terminal_ ? "%.1fs" : "%.1fs elapsed", elapsed);
    add();
    std::snprintf(field, sizeof field, "ETA %.1fs", eta);
    add();
    if (pathsPerPass_ > 0) {
        const double rate = elapsed > 0.0 ? static_cast<double>(paths) / elapsed * 1e-6 : 0.0;
        std::snprintf(field, sizeof field, "%.2f Msamples/s", rate);
        add();
    }
    if (terminal_) {
        constexpr int kWidth = 30;
        std::string bar(static_cast<size_t>(fraction * kWidth), '#');
        bar.resize(kWidth, '.');
        std::fprintf(stderr, "\r%s [%s] %s%s", label_.c_str(), bar.c_str(), line.c_str(), final ? "\n" : "  ");
    } else {
        std::fprintf(stderr, "%s: %s\n", label_.c_str(), line.c_str());
    }
    std::fflush(stderr);
}

}  // namespace strata
