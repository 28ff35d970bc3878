#pragma once
// The peak resident memory of this very process (Linux's VmHWM), which `strata render --json` and
// `strata view --json` report so that the bench can quote each child's own figure. The rusage a
// parent gets for its child cannot give it: a child started by posix_spawn (or fork) runs in the
// parent's address space until it executes the new program, and the kernel carries that space's
// high-water mark over into the child's ru_maxrss, so every child would read at least the bench's
// own resident set.
#include <filesystem>

namespace strata {

// KiB; 0 where /proc/self/status cannot be read.
long peakResidentKiB();

// The peak a `strata` child reported in its JSON (the last line of `log` that is a JSON object,
// its "peak_rss_mib"), in KiB; -1 when the log holds no such report.
long reportedPeakResidentKiB(const std::filesystem::path& log);

}  // namespace strata
