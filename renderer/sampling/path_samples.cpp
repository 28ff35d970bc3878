#include "sampling/path_samples.h"

#include "sampling/random.h"
#include "sampling/sobol.h"
#include "sampling/strata24.h"

namespace strata {
namespace {
// Dimensions of the plain hashed points: 1 + bounce for the bounce points.
constexpr uint64_t kFirstBounceDimension = 1;
// Tags of the pixel's low-discrepancy streams (and of strata24-qmc's per-stratum streams): each
// value, folded in with the bounce, keys a stream of its own.
constexpr uint64_t kPixelJitterTag = 0x6a6974746572ull;  // "jitter"
constexpr uint64_t kLightTag = 0x6c69676874ull;          // "light"
constexpr uint64_t kLobeTag = 0x6c6f6265ull;             // "lobe"
constexpr uint64_t kRouletteTag = 0x726f756c6574ull;     // "roulet"
constexpr uint64_t kSequenceTag = 0x736f626f6cull;       // "sobol"
}  // namespace

PathSamples::PathSamples(uint64_t seed, uint64_t pixel, uint32_t pass, int step)
    : pixelKey_(hashCombine(mixBits(seed), pixel)),
      pathKey_(hashCombine(hashCombine(pixelKey_, pass), static_cast<uint64_t>(step))),
      lightKey_(hashCombine(pixelKey_, kLightTag)),
      lobeKey_(hashCombine(pixelKey_, kLobeTag)),
      rouletteKey_(hashCombine(pixelKey_, kRouletteTag)),
      sequenceKey_(hashCombine(pixelKey_, kSequenceTag)),
      pixelIndex_(pass * static_cast<uint32_t>(kStrataCount) + static_cast<uint32_t>(step)),
      pass_(pass),
      step_(step) {}

glm::vec2 PathSamples::point(uint64_t dimension) const {
    const uint64_t bits = hashCombine(pathKey_, dimension);
    // Two 24-bit coordinates from one 64-bit hash: bits 40..63 and bits 16..39.
    return {uniformFloat(bits), uniformFloat(bits << 24)};
}

uint64_t PathSamples::streamKey(uint64_t tagKey, int bounce) {
    return hashCombine(tagKey, static_cast<uint64_t>(bounce));
}

glm::vec2 PathSamples::pixelJitter() const {
    return scrambledSobolPoint(pixelIndex_, hashCombine(pixelKey_, kPixelJitterTag));
}

glm::vec2 PathSamples::bouncePoint(int bounce) const {
    return point(kFirstBounceDimension + static_cast<uint64_t>(bounce));
}

int PathSamples::stratum(int bounce) const {
    if (!schedule_) schedule_.emplace(pixelKey_, pass_, step_);
    return schedule_->stratum(bounce);
}

PathSamples::StratumPoint PathSamples::stratumSequencePoint(int bounce) const {
    const int id = stratum(bounce);
    const uint64_t stream = hashCombine(streamKey(sequenceKey_, bounce), static_cast<uint64_t>(id));
    return {id, scrambledSobolPoint(pass_, stream)};
}

float PathSamples::lobeChoice(int bounce) const {
    return scrambledSobolValue(pixelIndex_, streamKey(lobeKey_, bounce));
}

float PathSamples::roulette(int bounce) const {
    return scrambledSobolValue(pixelIndex_, streamKey(rouletteKey_, bounce));
}

glm::vec3 PathSamples::lightSample(int bounce) const {
    // The point on the emitter takes the (0,2)-sequence pair, the emitter choice the third
    // coordinate: jointly a (1,3)-sequence, so the choice and the point are stratified together.
    const glm::vec3 p = scrambledSobolPoint3(pixelIndex_, streamKey(lightKey_, bounce));
    return {p.z, p.x, p.y};
}

glm::vec2 PathSamples::lightPoint(int bounce) const {
    // The 3D stream's first two coordinates are its 2D stream's (sobol.h).
    return scrambledSobolPoint(pixelIndex_, streamKey(lightKey_, bounce));
}

}  // namespace strata
