#include "materials/transmission_blend.h"

#include <algorithm>
#include <cmath>

namespace strata {
namespace {
// The opaque part's directions on the side above the normal, where the layered model reflects.
glm::vec3 upper(const glm::vec3& wo, const glm::vec3& w) { return wo.z < 0.0f ? glm::vec3(w.x, w.y, -w.z) : w; }
}  // namespace

template <class Dielectric>
glm::vec3 TransmissionBlend<Dielectric>::evaluate(const glm::vec3& wo, const glm::vec3& wi, TransportMode mode) const {
    return (1.0f - transmission_) * opaque_.evaluate(upper(wo, wo), upper(wo, wi), mode) +
           transmission_ * dielectric_.evaluate(wo, wi, mode);
}

template <class Dielectric>
float TransmissionBlend<Dielectric>::pdf(const glm::vec3& wo, const glm::vec3& wi, DiffuseWarp warp) const {
    return (1.0f - transmission_) * opaque_.pdf(upper(wo, wo), upper(wo, wi), warp) +
           transmission_ * dielectric_.pdf(wo, wi, warp);
}

template <class Dielectric>
std::optional<BsdfSample> TransmissionBlend<Dielectric>::sample(const glm::vec3& wo, const BsdfNumbers& numbers,
                                                                TransportMode mode) const {
    const float t = transmission_;
    BsdfNumbers inner = numbers;
    std::optional<BsdfSample> s;
    if (numbers.lobeChoice < t) {
        inner.lobeChoice = std::min(numbers.lobeChoice / t, 0x1.fffffep-1f);
        s = dielectric_.sample(wo, inner, mode);
        if (s && isSpecular(s->flags)) {
            // A delta of the dielectric: t f / (t p) is its own weight.
            s->f *= t;
            s->pdf *= t;
            return s;
        }
    } else {
        inner.lobeChoice = std::min((numbers.lobeChoice - t) / (1.0f - t), 0x1.fffffep-1f);
        s = opaque_.sample(upper(wo, wo), inner, mode);
        if (s) s->wi = upper(wo, s->wi);
    }
    if (!s) return std::nullopt;
    const float density = pdf(wo, s->wi, numbers.diffuse.warp);
    if (!(density > 0.0f)) return std::nullopt;
    const glm::vec3 f = evaluate(wo, s->wi, mode);
    return BsdfSample{s->wi, f, density, f * (std::abs(s->wi.z) / density), s->flags, s->eta, s->stratum};
}

template class TransmissionBlend<SmoothDielectric>;
template class TransmissionBlend<RoughDielectric>;
template class TransmissionBlend<ThinDielectric>;

}  // namespace strata
