#include "sampling/sobol.h"

#include "sampling/random.h"

namespace strata {
namespace {

uint32_t reverseBits(uint32_t v) {
    v = ((v >> 1) & 0x55555555u) | ((v & 0x55555555u) << 1);
    v = ((v >> 2) & 0x33333333u) | ((v & 0x33333333u) << 2);
    v = ((v >> 4) & 0x0f0f0f0fu) | ((v & 0x0f0f0f0fu) << 4);
    v = ((v >> 8) & 0x00ff00ffu) | ((v & 0x00ff00ffu) << 8);
    return (v >> 16) | (v << 16);
}

// A seeded bijection of 32-bit words in which every bit depends only on itself and the bits
// below it: adding a constant carries upward only, and x ^= x * (even constant) flips bit k by a
// function of bits 0..k-1 (an even multiplier never moves a bit onto itself). Applied to the
// bit-reversed value, "below" becomes "more significant": a nested uniform scramble. The
// multipliers are Burley 2020's, which make each bit's flips close to independent.
uint32_t scrambleUpward(uint32_t x, uint32_t seed) {
    x += seed;
    x ^= x * 0x6c50b47cu;
    x ^= x * 0xb82f1e52u;
    x ^= x * 0xc7afe638u;
    x ^= x * 0x8d22f6e6u;
    return x;
}

// 24 significant bits to a float in [0, 1): never rounds up to 1.
float toUnitFloat(uint32_t fixedPoint) { return static_cast<float>(fixedPoint >> 8) * 0x1p-24f; }

}  // namespace

uint32_t sobolFirstCoordinate(uint32_t index) { return reverseBits(index); }

uint32_t sobolSecondCoordinate(uint32_t index) {
    // Column j of the generator matrix is row j of Pascal's triangle mod 2, read from the top
    // bit down: it starts at 1 << 31 and the next is v ^ (v >> 1).
    uint32_t result = 0;
    for (uint32_t v = 1u << 31; index != 0; index >>= 1, v ^= v >> 1) {
        if (index & 1u) result ^= v;
    }
    return result;
}

uint32_t sobolThirdCoordinate(uint32_t index) {
    // Bratley & Fox's recurrence for a degree-2 polynomial with a_1 = 1:
    // v_k = v_{k-1} ^ v_{k-2} ^ (v_{k-2} >> 2), from v_1 = 1/2 and v_2 = 3/4 (m = 1, 3).
    uint32_t result = 0;
    uint32_t older = 1u << 31;
    uint32_t newer = 3u << 30;
    if (index & 1u) result ^= older;
    for (index >>= 1; index != 0; index >>= 1) {
        if (index & 1u) result ^= newer;
        const uint32_t next = newer ^ older ^ (older >> 2);
        older = newer;
        newer = next;
    }
    return result;
}

uint32_t owenScramble(uint32_t value, uint32_t seed) {
    return reverseBits(scrambleUpward(reverseBits(value), seed));
}

// Owen-scrambling the index maps each aligned block of 2^m indices onto an aligned block of 2^m
// (its high bits depend only on high bits), and every aligned block of a (t,s)-sequence is a
// (t,m,s)-net: the shuffled prefixes stay nets. The stream's seeds: the index scramble in the low
// 32 bits of the first hash, the first coordinate's in its high bits, the others' in the next.
glm::vec2 scrambledSobolPoint(uint32_t index, uint64_t streamKey) {
    const uint64_t seeds = mixBits(streamKey);
    const uint64_t moreSeeds = mixBits(seeds);
    const uint32_t shuffled = owenScramble(index, static_cast<uint32_t>(seeds));
    return {toUnitFloat(owenScramble(sobolFirstCoordinate(shuffled), static_cast<uint32_t>(seeds >> 32))),
            toUnitFloat(owenScramble(sobolSecondCoordinate(shuffled), static_cast<uint32_t>(moreSeeds)))};
}

float scrambledSobolValue(uint32_t index, uint64_t streamKey) {
    const uint64_t seeds = mixBits(streamKey);
    const uint32_t shuffled = owenScramble(index, static_cast<uint32_t>(seeds));
    return toUnitFloat(owenScramble(sobolFirstCoordinate(shuffled), static_cast<uint32_t>(seeds >> 32)));
}

glm::vec3 scrambledSobolPoint3(uint32_t index, uint64_t streamKey) {
    const glm::vec2 firstTwo = scrambledSobolPoint(index, streamKey);
    const uint64_t seeds = mixBits(streamKey);
    const uint32_t shuffled = owenScramble(index, static_cast<uint32_t>(seeds));
    const auto thirdSeed = static_cast<uint32_t>(mixBits(seeds) >> 32);
    return {firstTwo, toUnitFloat(owenScramble(sobolThirdCoordinate(shuffled), thirdSeed))};
}

}  // namespace strata
