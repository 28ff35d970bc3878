#include "sampling/path_samples.h"

#include <algorithm>

#include "sampling/random.h"
#include "sampling/strata24.h"

namespace strata {
namespace {
// Dimensions of the plain hashed points: 1 + bounce for the bounce points.
constexpr uint64_t kFirstBounceDimension = 1;
// Tags of the pixel's low-discrepancy streams (and of strata24-qmc's per-stratum streams): each
// value, folded in with the bounce, keys a stream of its own.
constexpr uint64_t kPixelJitterTag = 0x6a6974746572ull;  // "jitter"
constexpr uint64_t kLensTag = 0x6c656e73ull;             // "lens"
constexpr uint64_t kLightTag = 0x6c69676874ull;          // "light"
constexpr uint64_t kLobeTag = 0x6c6f6265ull;             // "lobe"
constexpr uint64_t kRouletteTag = 0x726f756c6574ull;     // "roulet"
constexpr uint64_t kSequenceTag = 0x736f626f6cull;       // "sobol"
}  // namespace

PixelKeys::PixelKeys(uint64_t seed, uint64_t pixelIndex)
    : pixel(hashCombine(mixBits(seed), pixelIndex)),
      jitter(hashCombine(pixel, kPixelJitterTag)),
      light(hashCombine(pixel, kLightTag)),
      lobe(hashCombine(pixel, kLobeTag)),
      roulette(hashCombine(pixel, kRouletteTag)),
      sequence(hashCombine(pixel, kSequenceTag)) {}

uint64_t PixelKeys::lens() const { return hashCombine(pixel, kLensTag); }

uint64_t PixelStreams::streamKey(uint64_t valueKey, int bounce) {
    return hashCombine(valueKey, static_cast<uint64_t>(bounce));
}

PixelStreams::PixelStreams(uint64_t seed, uint64_t pixel, uint32_t pass, int depth)
    : keys_(seed, pixel),
      schedule_(keys_.pixel, pass, depth),
      cachedBounces_(std::clamp(depth, 0, kMaxCachedBounces)),
      jitter_(keys_.jitter) {}

namespace {

PixelStreams::StratumStreamPoint stratumStreamPointOf(uint64_t sequenceKey, int bounce, uint32_t pass) {
    const uint64_t streamKey = PixelStreams::streamKey(sequenceKey, bounce);
    return {streamKey, SobolStream(streamKey).pointBits(pass)};
}

}  // namespace

const PixelStreams::StratumStreamPoint& PixelStreams::stratumStreamPoint(int bounce) const {
    return stratumStreamPoints_.at(bounce, [&] { return stratumStreamPointOf(keys_.sequence, bounce, pass()); });
}

PathSamples::PathSamples(const PixelKeys& keys, const PixelStreams* streams, uint32_t pass, int step)
    : keys_(keys),
      streams_(streams),
      pixelIndex_(pass * static_cast<uint32_t>(kStrataCount) + static_cast<uint32_t>(step)),
      pass_(pass),
      step_(step) {}

PathSamples::PathSamples(uint64_t seed, uint64_t pixel, uint32_t pass, int step)
    : PathSamples(PixelKeys(seed, pixel), nullptr, pass, step) {}

PathSamples::PathSamples(const PixelStreams& shared, int step)
    : PathSamples(shared.keys(), &shared, shared.pass(), step) {}

glm::vec2 PathSamples::point(uint64_t dimension) const {
    if (!pathKey_) pathKey_ = hashCombine(hashCombine(keys_.pixel, pass_), static_cast<uint64_t>(step_));
    const uint64_t bits = hashCombine(*pathKey_, dimension);
    // Two 24-bit coordinates from one 64-bit hash: bits 40..63 and bits 16..39.
    return {uniformFloat(bits), uniformFloat(bits << 24)};
}

glm::vec2 PathSamples::pixelJitter() const {
    // In the stream's own order: every other value's stream is shuffled, which pairs it with the
    // jitter at random (sobol.h); a shuffle here too would pair nothing more, and the jitter is
    // drawn for every path, however short.
    return (streams_ ? streams_->jitter() : SobolStream(keys_.jitter)).orderedPoint(pixelIndex_);
}

glm::vec2 PathSamples::lensPoint() const {
    return (streams_ ? streams_->lens() : SobolStream(keys_.lens())).point(pixelIndex_);
}

glm::vec2 PathSamples::bouncePoint(int bounce) const {
    return point(kFirstBounceDimension + static_cast<uint64_t>(bounce));
}

int PathSamples::stratum(int bounce) const {
    if (!schedule_) {
        if (streams_) {
            schedule_.emplace(streams_->schedule(), step_);
        } else {
            schedule_.emplace(keys_.pixel, pass_, step_);
        }
    }
    return schedule_->stratum(bounce);
}

PathSamples::StratumPoint PathSamples::stratumSequencePoint(int bounce) const {
    const int id = stratum(bounce);
    const PixelStreams::StratumStreamPoint shared =
        cached(bounce) ? streams_->stratumStreamPoint(bounce) : stratumStreamPointOf(keys_.sequence, bounce, pass_);
    const uint64_t shift = hashCombine(shared.streamKey, static_cast<uint64_t>(id));
    return {id, unitPoint(shared.point ^ glm::uvec2(static_cast<uint32_t>(shift), static_cast<uint32_t>(shift >> 32)))};
}

SobolStream PathSamples::lobeStream(int bounce) const {
    return cached(bounce) ? streams_->lobe(bounce) : SobolStream(PixelStreams::streamKey(keys_.lobe, bounce));
}

glm::vec3 PathSamples::lobeSample(int bounce) const {
    const glm::vec3 p = lobeStream(bounce).point3(pixelIndex_);
    return {p.z, p.x, p.y};
}

float PathSamples::roulette(int bounce) const {
    return (cached(bounce) ? streams_->roulette(bounce)
                           : SobolStream(PixelStreams::streamKey(keys_.roulette, bounce)))
        .value(pixelIndex_);
}

SobolStream PathSamples::lightStream(int bounce) const {
    return cached(bounce) ? streams_->light(bounce) : SobolStream(PixelStreams::streamKey(keys_.light, bounce));
}

glm::vec3 PathSamples::lightSample(int bounce) const {
    // The point on the emitter takes the (0,2)-sequence pair, the emitter choice the third
    // coordinate: jointly a (1,3)-sequence, so the choice and the point are stratified together.
    const glm::vec3 p = lightStream(bounce).point3(pixelIndex_);
    return {p.z, p.x, p.y};
}

glm::vec2 PathSamples::lightPoint(int bounce) const {
    // The 3D stream's first two coordinates are its 2D stream's (sobol.h).
    return lightStream(bounce).point(pixelIndex_);
}

}  // namespace strata
