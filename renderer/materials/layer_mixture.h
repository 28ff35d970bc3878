#pragma once
// What a layer over a base (clear_coat.h, sheen.h) does alike when it samples: it takes its own
// lobe with some probability p, else hands the base numbers whose lobe choice is rescaled to
// [0, 1) so that the base chooses among its own lobes with what is left; and whichever drew the
// direction, the sample's f and density are the whole model's, so that its weight is the
// mixture's f cos / pdf.
#include <algorithm>
#include <optional>

#include "materials/bsdf_sample.h"

namespace strata {

// The numbers for the base, once lobeChoice >= p has passed over the layer.
inline BsdfNumbers baseNumbers(const BsdfNumbers& numbers, float p) {
    BsdfNumbers inner = numbers;
    inner.lobeChoice = std::min((numbers.lobeChoice - p) / (1.0f - p), 0x1.fffffep-1f);
    return inner;
}

// The sample of `model` along wi, which its lobe `lobe` drew (`stratum`: the diffuse lobe's, or
// -1); empty where the model's density there is 0.
template <class Model>
std::optional<BsdfSample> mixtureSample(const Model& model, const glm::vec3& wo, const glm::vec3& wi, BsdfFlags lobe,
                                        int stratum, DiffuseWarp warp, TransportMode mode) {
    const float density = model.pdf(wo, wi, warp);
    if (!(density > 0.0f)) return std::nullopt;
    const glm::vec3 f = model.evaluate(wo, wi, mode);
    return BsdfSample{wi, f, density, f * (wi.z / density), lobe, 1.0f, stratum};
}

}  // namespace strata
