#pragma once
// The random numbers of one path: step `step` (0..23) of pass `pass` at one pixel. Every value is
// a hash of (seed, pixel, pass, step, bounce, dimension) (see random.h), which is what makes
// renders bit-identical for any thread count.
#include <cstdint>
#include <optional>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "sampling/stratum_schedule.h"

namespace strata {

class PathSamples {
public:
    PathSamples(uint64_t seed, uint64_t pixel, uint32_t pass, int step);

    // Sub-pixel position of the camera ray, uniform on [0,1)^2.
    glm::vec2 pixelJitter() const;
    // The point in [0,1)^2 that the direction sampler maps onto the hemisphere (or onto a stratum)
    // at `bounce`. Uniform random, as in the paper; other point sets plug in here.
    glm::vec2 bouncePoint(int bounce) const;
    // The point in [0,1)^2 of the path's stratum at `bounce` from that stratum's own
    // Owen-scrambled Sobol' stream (sobol.h): one stream per (pixel, bounce, stratum), indexed by
    // the pass. Every pass uses each stratum once per bounce, so the first 2^m passes put a
    // (0,m,2)-net in every stratum: each stratum is stratified ever more finely (strata24-qmc).
    glm::vec2 stratumSequencePoint(int bounce) const;
    // The stratum this path takes at `bounce` (stratum_schedule.h).
    int stratum(int bounce) const;
    // Uniform on [0,1): which lobe of a layered material sample() takes at `bounce`.
    float lobeChoice(int bounce) const;
    // Uniform on [0,1): whether Russian roulette lets the path go on after `bounce`.
    float roulette(int bounce) const;
    // Next-event estimation at `bounce`: x picks the emitting triangle, (y, z) the point on it.
    glm::vec3 lightSample(int bounce) const;

    uint64_t pixelKey() const { return pixelKey_; }
    uint32_t pass() const { return pass_; }
    int step() const { return step_; }

private:
    glm::vec2 point(uint64_t dimension) const;

    uint64_t pixelKey_;
    uint64_t pathKey_;
    uint32_t pass_;
    int step_;
    // The path's strata, worked out on the first stratum() call rather than at every bounce
    // (and never for samplers that do not stratify).
    mutable std::optional<PathSchedule> schedule_;
};

}  // namespace strata
