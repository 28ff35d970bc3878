#include "progress.h"

#include <cstdio>
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
    const auto count = static_cast<unsigned long long>(done);
    const auto total = static_cast<unsigned long long>(total_);
    // A pass's figures: its spp so far and the paths per second.
    const unsigned long long spp = done * static_cast<uint64_t>(pathsPerPass_);
    const double rate = elapsed > 0.0 ? static_cast<double>(paths) / elapsed * 1e-6 : 0.0;
    if (terminal_) {
        constexpr int kWidth = 30;
        const int filled = static_cast<int>(fraction * kWidth);
        std::string bar(filled, '#');
        bar.resize(kWidth, '.');
        std::fprintf(stderr, "\r%s [%s] %s %llu/%llu", label_.c_str(), bar.c_str(), step_.c_str(), count, total);
        if (pathsPerPass_ > 0) std::fprintf(stderr, "  %llu spp", spp);
        std::fprintf(stderr, "  %.1fs  ETA %.1fs", elapsed, eta);
        if (pathsPerPass_ > 0) std::fprintf(stderr, "  %.2f Msamples/s", rate);
        std::fputs(final ? "\n" : "  ", stderr);
    } else {
        std::fprintf(stderr, "%s: %s %llu/%llu", label_.c_str(), step_.c_str(), count, total);
        if (pathsPerPass_ > 0) std::fprintf(stderr, ", %llu spp", spp);
        std::fprintf(stderr, ", %.1fs elapsed, ETA %.1fs", elapsed, eta);
        if (pathsPerPass_ > 0) std::fprintf(stderr, ", %.2f Msamples/s", rate);
        std::fputc('\n', stderr);
    }
    std::fflush(stderr);
}

}  // namespace strata
