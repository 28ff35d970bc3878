#pragma once
// Adaptive sampling: stop giving passes to pixels whose estimate is already good enough.
//
// A pixel is done once it has at least `minPasses` complete passes and its relative standard
// error, SE / max(mean luminance, floor), is at most the threshold. The standard error comes from
// the spread of the pixel's pass means (AccumulationBuffer::passStandardError), which is right for
// both samplers: the 24 paths of a strata24 pass are not independent, the passes are. A stopping
// rule driven by the data is not exactly unbiased (a pixel whose early passes happen to agree stops
// early); the threshold bounds that error, and the tests check it on scenes with known answers.
#include <cstdint>
#include <vector>

#include "film/accumulation_buffer.h"

namespace strata {

struct AdaptiveSettings {
    double threshold = 0.0;   // relative standard error at which a pixel is done; 0: off
    uint32_t minPasses = 4;   // never judge a pixel on fewer passes
    double luminanceFloor = 1e-3;  // keeps black pixels from dividing by zero

    bool enabled() const { return threshold > 0.0; }
};

class AdaptiveSampling {
public:
    AdaptiveSampling(const AdaptiveSettings& settings, size_t pixelCount);

    bool enabled() const { return settings_.enabled(); }
    // Re-evaluates every pixel not yet done; returns the number still active.
    size_t update(const AccumulationBuffer& buffer);
    // 1 for pixels that receive no more passes; indexable by pixel.
    const std::vector<uint8_t>& doneMask() const { return done_; }
    size_t activePixels() const { return active_; }

private:
    AdaptiveSettings settings_;
    std::vector<uint8_t> done_;
    size_t active_;
};

}  // namespace strata
