#include "sampling/stratum_schedule.h"

#include <algorithm>
#include <array>
#include <utility>

#include "sampling/random.h"
#include "sampling/strata24.h"

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

// 256 random permutations of 0..23, shuffled (Fisher-Yates) at compile time from a fixed
// counter-based stream: 6 KiB, small enough to stay in the L1 cache while Embree traverses.
using StratumPermutation = std::array<uint8_t, kStrataCount>;
constexpr std::array<StratumPermutation, 256> makePermutationTable() {
    std::array<StratumPermutation, 256> table{};
    uint64_t counter = 0;
    for (StratumPermutation& permutation : table) {
        for (int i = 0; i < kStrataCount; ++i) permutation[i] = static_cast<uint8_t>(i);
        for (int i = kStrataCount - 1; i > 0; --i) {
            const uint32_t j = uniformIndex(mixBits(++counter), static_cast<uint32_t>(i + 1));
            std::swap(permutation[i], permutation[j]);
        }
    }
    return table;
}
constexpr std::array<StratumPermutation, 256> kPermutationTable = makePermutationTable();

}  // namespace

int permuteStratum(int index, uint64_t key) {
    const StratumPermutation& first = kPermutationTable[key & 0xffu];
    const StratumPermutation& second = kPermutationTable[(key >> 8) & 0xffu];
    // The lookups use the key's low 16 bits; the rotation takes its top bits (multiply-shift),
    // which a hash output leaves independent of them, so no second hash is needed.
    const uint32_t rotated = second[first[index]] + uniformIndex(key, kStrataCount);
    return static_cast<int>(rotated >= kStrataCount ? rotated - kStrataCount : rotated);
}

uint64_t PassSchedule::makeDeliveryKey(uint64_t pixelKey, uint32_t pass) {
    return hashCombine(hashCombine(pixelKey, kDeliveryOrderTag), pass);
}

uint64_t PassSchedule::makePermutationKey(uint64_t pixelKey) { return hashCombine(pixelKey, kBouncePermutationTag); }

// sigma_b's key: the pixel's own for the product-stratified bounces, a fresh one every pass from
// kProductStratifiedBounces on (header).
uint64_t PassSchedule::makeStratumKey(uint64_t permutationKey, uint32_t pass, int bounce) {
    const uint64_t bounceKey = hashCombine(permutationKey, static_cast<uint64_t>(bounce));
    return bounce < kProductStratifiedBounces ? bounceKey : hashCombine(bounceKey, pass);
}

PassSchedule::PassSchedule(uint64_t pixelKey, uint32_t pass, int bounces)
    : deliveryKey_(makeDeliveryKey(pixelKey, pass)),
      permutationKey_(makePermutationKey(pixelKey)),
      pass_(pass),
      bounces_(std::clamp(bounces, 0, kMaxBounces)),
      stratumKeys_{} {
    for (int bounce = 0; bounce < bounces_; ++bounce) {
        stratumKeys_[static_cast<size_t>(bounce)] = makeStratumKey(permutationKey_, pass, bounce);
    }
}

PathSchedule::PathSchedule(uint64_t pixelKey, uint32_t pass, int step)
    : permutationKey_(PassSchedule::makePermutationKey(pixelKey)),
      pass_(pass),
      canonical_(permuteStratum(step, PassSchedule::makeDeliveryKey(pixelKey, pass))) {}

PathSchedule::PathSchedule(const PassSchedule& shared, int step)
    : shared_(&shared),
      permutationKey_(shared.permutationKey()),
      pass_(shared.pass()),
      canonical_(permuteStratum(step, shared.deliveryKey())) {}

int PathSchedule::stratum(int bounce) const {
    const uint64_t key = shared_ && bounce < shared_->bounces()
                             ? shared_->stratumKey(bounce)
                             : PassSchedule::makeStratumKey(permutationKey_, pass_, bounce);
    if (bounce < kProductStratifiedBounces) {
        const int t = static_cast<int>((canonical_ + productOffset(pass_, bounce)) % kStrataCount);
        return permuteStratum(t, key);
    }
    return permuteStratum(canonical_, key);
}

int scheduledStratum(uint64_t pixelKey, uint32_t pass, int step, int bounce) {
    return PathSchedule(pixelKey, pass, step).stratum(bounce);
}

}  // namespace strata
