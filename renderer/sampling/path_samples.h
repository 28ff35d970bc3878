#pragma once
// The random numbers of one path: step `step` (0..23) of pass `pass` at one pixel. Every value is
// a pure function of (seed, pixel, pass, step, bounce, dimension), which is what makes renders
// bit-identical for any thread count.
//
// The pixel jitter, the lens point, the light sample, the lobe sample and the roulette decision are stratified
// over the pixel's paths: the pixel's path number n = 24 pass + step indexes a low-discrepancy
// stream (sobol.h) of its own for each of these values at each bounce, Owen-scrambled with seeds
// from (seed, pixel, value, bounce), and index-shuffled too, so that two streams pair their points
// at random ("padding", as pbrt-v4's PaddedSobolSampler and Cycles' Sobol-Burley do; the jitter's
// stream alone keeps its own order, which the others' shuffles pair at random already). Each value
// alone is then stratified over the pixel's first n paths (a (0,2)-sequence in 2D), while the values
// stay independent of each other and of the direction's stratum. Every single value is uniform, so
// every path is unbiased. The direction samplers' own points (bouncePoint, stratumSequencePoint)
// keep their meanings: the paper's estimators are compared on the same pixel, light and roulette
// numbers.
#include <array>
#include <cstdint>
#include <optional>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "sampling/sobol.h"
#include "sampling/stratum_schedule.h"

namespace strata {

// The keys of one pixel's streams: hashes of (seed, pixel) with each value's tag folded in.
struct PixelKeys {
    PixelKeys(uint64_t seed, uint64_t pixel);
    uint64_t pixel, jitter, light, lobe, roulette, sequence;
    // The lens point's key, which only a camera with a lens asks for.
    uint64_t lens() const;
};

// The streams, the strata's shared point and the stratum schedule's keys that every path of one
// pixel in one pass shares, worked out once rather than at every path's bounce: they depend on
// (seed, pixel, pass, value, bounce), not on the path, and hashing keys into scramble seeds is a
// good part of a path vertex's own work. Each stream (and point) is worked out when a path first
// asks for it, so sharing costs no stream that no path uses; the schedule's keys (a hash per
// bounce) are worked out with the pixel, whether or not its sampler stratifies. Bounces
// 0..cachedBounces()-1 are held; a path going deeper works out its streams itself. Not
// thread-safe: one thread's paths share it.
class PixelStreams {
public:
    static constexpr int kMaxCachedBounces = PassSchedule::kMaxBounces;

    // For the paths of a render whose light samples, lobe choices, roulette and strata reach at
    // most bounce depth - 1 (a path of depth K scatters at bounces 0..K-1).
    PixelStreams(uint64_t seed, uint64_t pixel, uint32_t pass, int depth);

    const PixelKeys& keys() const { return keys_; }
    uint32_t pass() const { return schedule_.pass(); }
    const PassSchedule& schedule() const { return schedule_; }
    int cachedBounces() const { return cachedBounces_; }
    const SobolStream& jitter() const { return jitter_; }
    const SobolStream& lens() const {
        if (!lens_) lens_.emplace(keys_.lens());
        return *lens_;
    }
    // For bounce < cachedBounces().
    const SobolStream& light(int bounce) const { return stream(light_, keys_.light, bounce); }
    const SobolStream& lobe(int bounce) const { return stream(lobe_, keys_.lobe, bounce); }
    const SobolStream& roulette(int bounce) const { return stream(roulette_, keys_.roulette, bounce); }
    // The bounce's stratum stream (PathSamples::stratumSequencePoint): its key, from which each
    // stratum's shift comes, and its point for this pass, which every stratum shifts.
    struct StratumStreamPoint {
        uint64_t streamKey;
        glm::uvec2 point;
    };
    const StratumStreamPoint& stratumStreamPoint(int bounce) const;

    // The key of the stream at `bounce` of the value whose pixel key is `valueKey`.
    static uint64_t streamKey(uint64_t valueKey, int bounce);

private:
    // One quantity by bounce, each bounce's worked out by `make` on its first use.
    template <class T>
    class ByBounce {
    public:
        template <class Make>
        const T& at(int bounce, const Make& make) const {
            const uint32_t bit = 1u << bounce;
            if (!(ready_ & bit)) {
                values_[static_cast<size_t>(bounce)] = make();
                ready_ |= bit;
            }
            return values_[static_cast<size_t>(bounce)];
        }

    private:
        mutable std::array<T, kMaxCachedBounces> values_;
        mutable uint32_t ready_ = 0;
    };
    static const SobolStream& stream(const ByBounce<SobolStream>& streams, uint64_t valueKey, int bounce) {
        return streams.at(bounce, [&] { return SobolStream(streamKey(valueKey, bounce)); });
    }

    PixelKeys keys_;
    PassSchedule schedule_;
    int cachedBounces_;
    SobolStream jitter_;
    mutable std::optional<SobolStream> lens_;  // for a camera with a lens only
    ByBounce<SobolStream> light_, lobe_, roulette_;
    ByBounce<StratumStreamPoint> stratumStreamPoints_;
};

class PathSamples {
public:
    PathSamples(uint64_t seed, uint64_t pixel, uint32_t pass, int step);
    // The same numbers, bit for bit, from the streams of the pixel's pass; `shared` outlives this.
    PathSamples(const PixelStreams& shared, int step);

    // Sub-pixel position of the camera ray, uniform on [0,1)^2; a (0,2)-sequence over the pixel.
    glm::vec2 pixelJitter() const;
    // The camera ray's point on the lens (camera.h), uniform on [0,1)^2; likewise, its stream
    // shuffled, so that it pairs with the jitter at random.
    glm::vec2 lensPoint() const;
    // The point in [0,1)^2 that the direction sampler maps onto the hemisphere (or onto a stratum)
    // at `bounce`. Uniform random, as in the paper; other point sets plug in here.
    glm::vec2 bouncePoint(int bounce) const;
    // The path's stratum at `bounce` (stratum()) and a point in [0,1)^2 for it from that
    // stratum's own low-discrepancy sequence, indexed by the pass: point `pass` of an
    // Owen-scrambled Sobol' stream (sobol.h) of the pixel and bounce, XORed with random bits of
    // the stratum's own (a random digital shift). A digital shift maps every dyadic box onto
    // another, so each stratum's sequence is still a (0,2)-sequence and the first 2^m passes put
    // a (0,m,2)-net in every stratum: each stratum is stratified ever more finely (strata24-qmc).
    // A shifted Owen-scrambled sequence is distributed as an Owen-scrambled one, and the strata's
    // shifts are independent and uniform, so two strata's sequences are uncorrelated: the
    // estimate's variance is that of one independently scrambled stream per stratum, while the
    // pass's 24 paths share one scrambled point. The stratum comes with its point, so a bounce
    // works it out once.
    struct StratumPoint {
        int stratum;
        glm::vec2 point;
    };
    StratumPoint stratumSequencePoint(int bounce) const;
    // The stratum this path takes at `bounce` (stratum_schedule.h).
    int stratum(int bounce) const;
    // A lobe sample at `bounce`: x which lobe of a layered material sample() takes, (y, z) the
    // point in [0,1)^2 that a lobe other than the diffuse one (GGX visible normals, a
    // dielectric's microfacet) maps to its direction. Laid out as the light sample is: the point
    // the stream's (0,2)-sequence pair, the choice its third coordinate, so that the point is
    // stratified over the pixel's paths and, jointly a (1,3)-sequence, within each lobe's share
    // of the choices.
    glm::vec3 lobeSample(int bounce) const;
    // Uniform on [0,1): whether Russian roulette lets the path go on after `bounce`; likewise.
    float roulette(int bounce) const;
    // Next-event estimation at `bounce`: x picks the emitting triangle, (y, z) the point on it;
    // jointly the first three Sobol' dimensions over the pixel.
    glm::vec3 lightSample(int bounce) const;
    // lightSample's (y, z) alone, bit for bit, without the choice's dimension: what a scene with
    // a single light needs.
    glm::vec2 lightPoint(int bounce) const;

    uint64_t pixelKey() const { return keys_.pixel; }
    uint32_t pass() const { return pass_; }
    int step() const { return step_; }

private:
    PathSamples(const PixelKeys& keys, const PixelStreams* streams, uint32_t pass, int step);
    // A uniform random point of the path: a hash of the path's key and `dimension`.
    glm::vec2 point(uint64_t dimension) const;
    bool cached(int bounce) const { return streams_ && bounce < streams_->cachedBounces(); }
    SobolStream lightStream(int bounce) const;
    SobolStream lobeStream(int bounce) const;

    PixelKeys keys_;
    const PixelStreams* streams_;  // the pixel's shared streams, or none
    // The path's key for its hashed points, worked out on the first bouncePoint() call: the
    // samplers that stratify by sequence never ask for it.
    mutable std::optional<uint64_t> pathKey_;
    uint32_t pixelIndex_;  // the path's number n = 24 pass + step within the pixel's streams
    uint32_t pass_;
    int step_;
    // The path's strata, worked out on the first stratum() call rather than at every bounce
    // (and never for samplers that do not stratify).
    mutable std::optional<PathSchedule> schedule_;
};

}  // namespace strata
