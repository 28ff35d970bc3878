#pragma once
// Which light next-event estimation samples at a vertex: light i with probability proportional to
// the power its samples draw (the mean of its RGB sampled power, light.h), so that brighter and
// larger lights get more of the shadow rays. The choice does not depend on the receiving point;
// every light of positive sampled power can be chosen, and what the others send (a uniform sky)
// the BSDF's samples reach, so with MIS the estimate stays unbiased whatever the scene.
#include <cstdint>
#include <vector>

namespace strata {

struct LightChoice {
    uint32_t light;
    float probability;
};

class LightSampler {
public:
    // One weight (power) per light, each >= 0.
    explicit LightSampler(const std::vector<double>& powers);

    bool empty() const { return cdf_.empty(); }
    // `u` uniform in [0,1). Not to be called when empty.
    LightChoice choose(float u) const;
    float probability(uint32_t light) const { return probability_[light]; }

private:
    std::vector<double> cdf_;         // running power fractions, last = 1; empty: nothing to sample
    std::vector<float> probability_;  // per light
};

}  // namespace strata
