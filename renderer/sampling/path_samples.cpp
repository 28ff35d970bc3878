#include "sampling/path_samples.h"

#include "sampling/random.h"
#include "sampling/sobol.h"

namespace strata {
namespace {
// Dimensions: 0 the pixel jitter, 1 + bounce the bounce points; the other per-bounce values live
// at bounce + tag with tags above any depth the CLI allows, so no two dimensions coincide.
constexpr uint64_t kPixelJitterDimension = 0;
constexpr uint64_t kFirstBounceDimension = 1;
constexpr uint64_t kLobeDimension = 1ull << 40;
constexpr uint64_t kLightDimension = 2ull << 40;
constexpr uint64_t kLightPointDimension = 3ull << 40;
constexpr uint64_t kRouletteDimension = 4ull << 40;
constexpr uint64_t kSequenceTag = 0x736f626f6cull;  // "sobol"
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

glm::vec2 PathSamples::stratumSequencePoint(int bounce) const {
    const uint64_t stream = hashCombine(
        hashCombine(hashCombine(pixelKey_, kSequenceTag), static_cast<uint64_t>(bounce)),
        static_cast<uint64_t>(stratum(bounce)));
    return scrambledSobolPoint(pass_, stream);
}

float PathSamples::lobeChoice(int bounce) const {
    return point(kLobeDimension + static_cast<uint64_t>(bounce)).x;
}

float PathSamples::roulette(int bounce) const {
    return point(kRouletteDimension + static_cast<uint64_t>(bounce)).x;
}

glm::vec3 PathSamples::lightSample(int bounce) const {
    const glm::vec2 choice = point(kLightDimension + static_cast<uint64_t>(bounce));
    const glm::vec2 position = point(kLightPointDimension + static_cast<uint64_t>(bounce));
    return {choice.x, position.x, position.y};
}

}  // namespace strata
