#include "lights/light_sampler.h"

#include <algorithm>

namespace strata {

LightSampler::LightSampler(const std::vector<double>& powers) : probability_(powers.size(), 0.0f) {
    double total = 0.0;
    for (double p : powers) total += p;
    if (!(total > 0.0)) return;
    cdf_.reserve(powers.size());
    double running = 0.0;
    for (size_t i = 0; i < powers.size(); ++i) {
        running += powers[i];
        cdf_.push_back(running / total);
        probability_[i] = static_cast<float>(powers[i] / total);
    }
    cdf_.back() = 1.0;
}

LightChoice LightSampler::choose(float u) const {
    // The first light whose running fraction exceeds u; a zero-power light has an empty interval
    // and is never chosen.
    const auto k = static_cast<uint32_t>(std::min<size_t>(
        std::upper_bound(cdf_.begin(), cdf_.end(), static_cast<double>(u)) - cdf_.begin(),
        cdf_.size() - 1));
    return {k, probability_[k]};
}

}  // namespace strata
