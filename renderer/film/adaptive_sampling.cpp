#include "film/adaptive_sampling.h"

#include <algorithm>
#include <cmath>

namespace strata {

AdaptiveSampling::AdaptiveSampling(const AdaptiveSettings& settings, size_t pixelCount)
    : settings_(settings), done_(pixelCount, 0), active_(pixelCount) {}

size_t AdaptiveSampling::update(const AccumulationBuffer& buffer) {
    if (!enabled()) return active_;
    for (size_t pixel = 0; pixel < done_.size(); ++pixel) {
        if (done_[pixel] || buffer.completedPasses(pixel) < settings_.minPasses) continue;
        const double mean = std::abs(luminance(buffer.mean(pixel)));
        const double relative = buffer.passStandardError(pixel) / std::max(mean, settings_.luminanceFloor);
        if (relative <= settings_.threshold) {
            done_[pixel] = 1;
            --active_;
        }
    }
    return active_;
}

}  // namespace strata
