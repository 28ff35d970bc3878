#include "stratum_schedule.h"

#include "random.h"
#include "strata24.h"

namespace strata {
namespace {

// Distinct tags keep the permutation streams apart from each other and from the point streams.
constexpr uint64_t kDeliveryOrderTag = 0x6f72646572ull;   // "order"
constexpr uint64_t kBouncePermutationTag = 0x7065726dull;  // "perm"

// Offset d_b(p) of bounce b in pass p (header): d_0 = 0, d_b = a_b + 5 d_{b-1}.
uint32_t productOffset(uint32_t pass, int bounce) {
    uint32_t offset = 0;
    for (int b = 1; b <= bounce; ++b) {
        const uint32_t digit = pass % kStrataCount;
        pass /= kStrataCount;
        offset = (digit + 5 * offset) % kStrataCount;
    }
    return offset;
}

}  // namespace

int permuteStratum(int index, uint64_t key) {
    const uint32_t k = static_cast<uint32_t>(key);
    uint32_t i = static_cast<uint32_t>(index);
    // Each line is a bijection of [0, 32); walking the cycle until the value falls below 24 gives a
    // bijection of [0, 24) (every cycle through [24, 32) is at most 8 steps long).
    do {
        i ^= k & 31u;
        i = (i * 0x1du) & 31u;
        i ^= i >> 3;
        i = (i + (k >> 5)) & 31u;
        i = (i * (((k >> 10) & 30u) | 1u)) & 31u;
        i ^= i >> 2;
        i ^= (k >> 15) & 31u;
        i = (i * 0x13u) & 31u;
        i ^= i >> 4;
    } while (i >= static_cast<uint32_t>(kStrataCount));
    // The walk uses the key's low 20 bits; the rotation takes its top bits (multiply-shift), which
    // a hash output leaves independent of them, so no second hash is needed.
    const uint32_t rotation = uniformIndex(key, kStrataCount);
    return static_cast<int>((i + rotation) % kStrataCount);
}

PathSchedule::PathSchedule(uint64_t pixelKey, uint32_t pass, int step)
    : permutationKey_(hashCombine(pixelKey, kBouncePermutationTag)),
      pass_(pass),
      canonical_(permuteStratum(step, hashCombine(hashCombine(pixelKey, kDeliveryOrderTag), pass))) {}

int PathSchedule::stratum(int bounce) const {
    const uint64_t bounceKey = hashCombine(permutationKey_, static_cast<uint64_t>(bounce));
    if (bounce < kProductStratifiedBounces) {
        const int t = static_cast<int>((canonical_ + productOffset(pass_, bounce)) % kStrataCount);
        return permuteStratum(t, bounceKey);
    }
    return permuteStratum(canonical_, hashCombine(bounceKey, pass_));
}

int scheduledStratum(uint64_t pixelKey, uint32_t pass, int step, int bounce) {
    return PathSchedule(pixelKey, pass, step).stratum(bounce);
}

}  // namespace strata
