#pragma once
// Counter-based random numbers. Every random value in a render is a pure function of a key built
// from (seed, pixel, pass, path, bounce, dimension), so an image never depends on thread count or
// scheduling: there is no generator state to share or to advance in order.
#include <cstdint>

namespace strata {

// A strong 64-bit finaliser (Stafford's "Mix13" variant used by splitmix64): every input bit
// affects every output bit, so consecutive counters give unrelated outputs.
constexpr uint64_t mixBits(uint64_t v) {
    v ^= v >> 30;
    v *= 0xbf58476d1ce4e5b9ull;
    v ^= v >> 27;
    v *= 0x94d049bb133111ebull;
    v ^= v >> 31;
    return v;
}

// Folds one more field into a key. The odd constant separates fields so that (a, b) and (b, a)
// give different keys.
constexpr uint64_t hashCombine(uint64_t key, uint64_t field) {
    return mixBits(key ^ (field + 0x9e3779b97f4a7c15ull + (key << 6) + (key >> 2)));
}

// A float uniform on [0, 1): the top 24 bits, so the largest value is 1 - 2^-24 (never 1).
constexpr float uniformFloat(uint64_t bits) {
    return static_cast<float>(bits >> 40) * 0x1p-24f;
}

// An integer uniform on [0, n) from 64 random bits (Lemire's multiply-shift; the bias is below
// n / 2^64, far beneath any statistical test).
constexpr uint32_t uniformIndex(uint64_t bits, uint32_t n) {
    __extension__ using Wide = unsigned __int128;  // a GCC/Clang extension, hence the marker
    return static_cast<uint32_t>((static_cast<Wide>(bits) * n) >> 64);
}

}  // namespace strata
