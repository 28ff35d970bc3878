#include "path_samples.h"

#include "random.h"

namespace strata {
namespace {
constexpr uint64_t kPixelJitterDimension = 0;
constexpr uint64_t kFirstBounceDimension = 1;
}  // namespace

PathSamples::PathSamples(uint64_t seed, uint64_t pixel, uint32_t pass, int step)
    : pixelKey_(hashCombine(mixBits(seed), pixel)),
      pathKey_(hashCombine(hashCombine(pixelKey_, pass), static_cast<uint64_t>(step))),
      pass_(pass),
      step_(step) {}

glm::vec2 PathSamples::point(uint64_t dimension) const {
    const uint64_t bits = hashCombine(pathKey_, dimension);
    // Two 24-bit coordinates from one 64-bit hash: bits 40..63 and bits 16..39.
    return {uniformFloat(bits), uniformFloat(bits << 24)};
}

glm::vec2 PathSamples::pixelJitter() const { return point(kPixelJitterDimension); }

glm::vec2 PathSamples::bouncePoint(int bounce) const {
    return point(kFirstBounceDimension + static_cast<uint64_t>(bounce));
}

int PathSamples::stratum(int bounce) const {
    if (!schedule_) schedule_.emplace(pixelKey_, pass_, step_);
    return schedule_->stratum(bounce);
}

}  // namespace strata
