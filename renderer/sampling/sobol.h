#pragma once
// Owen-scrambled Sobol' sequences in base 2: the (0,2)-sequence that stratifies each of the 24
// strata progressively (`strata24-qmc`, the paper's future work: uniform separation combined with
// low-discrepancy points), and the 1D, 2D and 3D streams that stratify a path's other numbers over
// its pixel (path_samples.h).
//
// The first two Sobol' dimensions form a (0,2)-sequence: for every m, each aligned block of 2^m
// consecutive points is a (0,m,2)-net, i.e. every dyadic box of area 2^-m holds exactly one
// point. Owen's nested uniform scrambling (Owen 1995, "Randomly permuted (t,m,s)-nets and
// (t,s)-sequences") permutes the binary digits of each coordinate, every digit's flip depending
// on the digits above it; it keeps the net property and makes each point uniform on [0,1)^2, so
// every point alone is an unbiased sample. The scramble here is the hash-based one of Burley 2020
// ("Practical Hash-based Owen Scrambling", JCGT 9(4)), which also shuffles the order of the
// points by Owen-scrambling the index: that decorrelates streams that share an index (one per
// pixel and bounce for the strata, indexed by the pass; one per pixel, value and bounce, indexed
// by the path number) while each aligned block of 2^m consecutive indices still maps to
// a (0,m,2)-net.
#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace strata {

// The unscrambled sequence as 32-bit fixed-point coordinates (x = value / 2^32): the first
// coordinate is the base-2 radical inverse (van der Corput); the second uses the generator
// matrix of Sobol's second dimension (Pascal's triangle mod 2).
uint32_t sobolFirstCoordinate(uint32_t index);
uint32_t sobolSecondCoordinate(uint32_t index);
// Sobol's third dimension (primitive polynomial x^2 + x + 1, direction numbers m = 1, 3, as in
// Joe & Kuo's table). With the first two it makes a (1,3)-sequence: every aligned block of 2^m
// points is a (1,m,3)-net.
uint32_t sobolThirdCoordinate(uint32_t index);

// Nested uniform (Owen) scrambling of the binary digits of `value`, most significant first,
// chosen by `seed`: a bijection of 32-bit values in which bit k of the result depends only on
// bit k and the bits above it.
uint32_t owenScramble(uint32_t value, uint32_t seed);

// A point's fixed-point coordinates as floats in [0,1)^2: their top 24 bits, never rounded up to 1.
glm::vec2 unitPoint(glm::uvec2 fixedPoint);

// One scrambled, shuffled sequence, chosen by its key: the index shuffle's and each coordinate's
// scramble seeds are hashes of the key, worked out once, so that a caller drawing many points of
// one stream (a pixel's paths share theirs, path_samples.h) hashes the key once.
class SobolStream {
public:
    SobolStream() = default;  // the stream of zero seeds, to be assigned
    explicit SobolStream(uint64_t streamKey);

    // Point `index` in [0,1)^2.
    glm::vec2 point(uint32_t index) const;
    // The same point as 32-bit fixed-point coordinates (x = value / 2^32), for callers that shift
    // it digitally (XOR) before it becomes a float; unitPoint(pointBits(i)) == point(i).
    glm::uvec2 pointBits(uint32_t index) const;
    // Point `index` without the index shuffle: the scrambled sequence in its own order, so every
    // aligned block of 2^m indices is still a (0,m,2)-net and every point is still uniform. Two
    // bit reversals and a hash cheaper than point(); for a stream whose index no other unshuffled
    // stream shares, since the shuffle is what pairs two streams' points at random.
    glm::vec2 orderedPoint(uint32_t index) const;
    // The same for the first Sobol' dimension alone (a scrambled, shuffled van der Corput
    // sequence: every aligned block of 2^m values has one value in each interval
    // [k 2^-m, (k+1) 2^-m)), and for the first three, shuffled by one index scramble so that the
    // three stay jointly a net. A stream's 3D point starts with its 2D point, which starts with
    // its value.
    float value(uint32_t index) const;
    glm::vec3 point3(uint32_t index) const;

private:
    uint32_t shuffled(uint32_t index) const;
    // The scrambled 2D point at `sequenceIndex` of the unscrambled sequence, as fixed point.
    glm::uvec2 scrambledBits(uint32_t sequenceIndex) const;

    uint32_t indexSeed_ = 0;
    uint32_t coordinateSeeds_[3] = {0, 0, 0};
};

}  // namespace strata
