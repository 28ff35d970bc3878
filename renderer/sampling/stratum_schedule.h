#pragma once
// Which of the 24 strata each path of a pixel takes at each bounce: the paper's stratified
// estimator xi*_N (section 3) with the product stratification across bounces of section 4.
//
// A pass gives a pixel 24 paths, delivered in steps 0..23. For pass p, step i, bounce b:
//   c   = order_p(i)                       per-pixel, per-pass random permutation: the delivery
//                                          order, so any prefix of a pass is an unbiased estimate;
//   t_b = (c + d_b(p)) mod 24              d_0 = 0, d_1 = a_1, d_2 = a_2 + 5 a_1, with the base-24
//                                          digits a_1 = p mod 24, a_2 = (p / 24) mod 24;
//   s_b = sigma_b(t_b)                     per-pixel random permutation of the ids, fixed for the
//                                          pixel, one per bounce (randomises the pattern).
// Properties (tests/sampling/test_stratum_schedule.cpp checks them):
//   (a) in every pass, each bounce uses each stratum exactly once (i -> s_b is a permutation);
//   (b) over any 24^(k-1) consecutive passes the 24^k cells of bounces 0..k-1 are each used once,
//       for k <= kProductStratifiedBounces: (a_1, a_2) -> (d_1, d_2) is a bijection of Z_24^2,
//       and the multiplier 5 (a unit mod 24) also makes bounces 0 and 2 cover all 576 pairs in
//       every aligned run of 24 passes instead of only every 576;
//   (c) each step's first-bounce stratum is uniform over the 24, and every path's stratum tuple is
//       uniform over the product cells (each sigma_b ends in an independent random rotation), so
//       every path, hence every partial pass, is unbiased.
// Bounces from kProductStratifiedBounces on are stratified per pass only ("padded", notes
// section 4 (iii)): s_b = sigma_{p,b}(c) with a fresh permutation every pass. Product
// stratification of bounce 3 would need 24^3 = 13824 passes per cycle, and until a cycle completes
// a deep bounce's stratum would stay tied to the first bounce's, a per-pixel error that does not
// shrink with more passes.
#include <array>
#include <cstddef>
#include <cstdint>

namespace strata {

inline constexpr int kProductStratifiedBounces = 3;

// A random permutation of 0..23 applied to `index`, chosen by `key`: two permutations picked by
// the key's low 16 bits from a table of 256 made at compile time, composed, then rotated by a
// uniform random offset taken from the key's top bits, so that the image of any index is exactly
// uniform over the keys. Table lookups rather than a keyed hash cycle-walked into [0, 24): the
// walk's data-dependent loop exit was mispredicted often enough to cost the path tracer ~4%.
int permuteStratum(int index, uint64_t key);

// The stratum id (0..23) for step `step` (0..23) of pass `pass` at `bounce`, for the pixel whose
// random key is `pixelKey` (PathSamples::pixelKey).
int scheduledStratum(uint64_t pixelKey, uint32_t pass, int step, int bounce);

// What the schedule of one pixel in one pass hashes, which the pass's 24 paths share: the
// delivery order's key and each bounce's permutation key, for bounces 0..bounces()-1.
class PassSchedule {
public:
    static constexpr int kMaxBounces = 16;

    PassSchedule(uint64_t pixelKey, uint32_t pass, int bounces);

    uint32_t pass() const { return pass_; }
    int bounces() const { return bounces_; }
    uint64_t deliveryKey() const { return deliveryKey_; }
    uint64_t permutationKey() const { return permutationKey_; }
    uint64_t stratumKey(int bounce) const { return stratumKeys_[static_cast<size_t>(bounce)]; }

    // The keys themselves, for a schedule that works them out alone.
    static uint64_t makeDeliveryKey(uint64_t pixelKey, uint32_t pass);
    static uint64_t makePermutationKey(uint64_t pixelKey);
    static uint64_t makeStratumKey(uint64_t permutationKey, uint32_t pass, int bounce);

private:
    uint64_t deliveryKey_;
    uint64_t permutationKey_;
    uint32_t pass_;
    int bounces_;
    std::array<uint64_t, kMaxBounces> stratumKeys_;
};

// The same schedule with the work that depends only on the path (c = order_p(i) and the pixel's
// permutation key) done once per path rather than at every bounce: a path tracer asks for every
// bounce of a path in turn. PathSchedule(k, p, i).stratum(b) == scheduledStratum(k, p, i, b), and
// so is the stratum of a path whose pass's keys are shared (`shared` outlives it).
class PathSchedule {
public:
    PathSchedule(uint64_t pixelKey, uint32_t pass, int step);
    PathSchedule(const PassSchedule& shared, int step);
    int stratum(int bounce) const;

private:
    const PassSchedule* shared_ = nullptr;
    uint64_t permutationKey_;  // the pixel's key for its per-bounce permutations sigma_b
    uint32_t pass_;
    int canonical_;            // c = order_p(i)
};

}  // namespace strata
