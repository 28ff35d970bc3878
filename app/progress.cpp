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
    : label_(std::move(label)),
      totalPasses_(totalPasses),
      pathsPerPass_(pathsPerPass),
      terminal_(isatty(STDERR_FILENO) != 0),
      start_(Clock::now()),
      lastPrint_(start_) {}

double ProgressReporter::elapsedSeconds() const {
    return std::chrono::duration<double>(Clock::now() - start_).count();
}

void ProgressReporter::update(uint64_t passesDone, uint64_t paths) {
    const auto now = Clock::now();
    if (now - lastPrint_ < (terminal_ ? kTerminalInterval : kLogInterval)) return;
    lastPrint_ = now;
    print(passesDone, paths, false);
}

void ProgressReporter::finish(uint64_t passesDone, uint64_t paths) { print(passesDone, paths, true); }

void ProgressReporter::print(uint64_t passesDone, uint64_t paths, bool final) {
    const double elapsed = elapsedSeconds();
    const double fraction = totalPasses_ ? static_cast<double>(passesDone) / totalPasses_ : 1.0;
    const double eta = fraction > 0.0 ? elapsed * (1.0 - fraction) / fraction : 0.0;
    const double rate = elapsed > 0.0 ? static_cast<double>(paths) / elapsed * 1e-6 : 0.0;
    const unsigned long long spp = passesDone * static_cast<uint64_t>(pathsPerPass_);
    if (terminal_) {
        constexpr int kWidth = 30;
        const int filled = static_cast<int>(fraction * kWidth);
        std::string bar(filled, '#');
        bar.resize(kWidth, '.');
        std::fprintf(stderr, "\r%s [%s] pass %llu/%llu  %llu spp  %.1fs  ETA %.1fs  %.2f Msamples/s%s",
                     label_.c_str(), bar.c_str(), static_cast<unsigned long long>(passesDone),
                     static_cast<unsigned long long>(totalPasses_), spp, elapsed, eta, rate,
                     final ? "\n" : "  ");
    } else {
        std::fprintf(stderr, "%s: pass %llu/%llu, %llu spp, %.1fs elapsed, ETA %.1fs, %.2f Msamples/s\n",
                     label_.c_str(), static_cast<unsigned long long>(passesDone),
                     static_cast<unsigned long long>(totalPasses_), spp, elapsed, eta, rate);
    }
    std::fflush(stderr);
}

}  // namespace strata
