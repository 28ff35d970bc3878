#pragma once
// A surface that is partly a dielectric (glTF KHR_materials_transmission with a factor or texture
// below 1: a label on a bottle, a tinted pane with an opaque print): the mixture
//   f = (1 - t) f_opaque + t f_dielectric
// of the opaque layered model (two-sided, as every reflection is) and a dielectric (smooth, rough
// or thin), t being the transmission weight at the hit. Each part conserves energy, so the mixture
// does. Sampling chooses the dielectric with probability t by numbers.lobeChoice, rescaled so
// that the part chosen chooses among its own lobes with what is left.
#include <optional>
#include <glm/vec3.hpp>

#include "materials/bsdf_sample.h"
#include "materials/layered_bsdf.h"
#include "materials/rough_dielectric.h"
#include "materials/smooth_dielectric.h"
#include "materials/thin_dielectric.h"

namespace strata {

template <class Dielectric>
class TransmissionBlend {
public:
    TransmissionBlend(const LayeredBsdf& opaque, const Dielectric& dielectric, float transmission)
        : opaque_(opaque), dielectric_(dielectric), transmission_(transmission) {}

    bool isBlack() const { return false; }
    BsdfFlags flags() const { return static_cast<BsdfFlags>(opaque_.flags() | dielectric_.flags()); }
    glm::vec3 evaluate(const glm::vec3& wo, const glm::vec3& wi, TransportMode mode = TransportMode::Radiance) const;
    std::optional<BsdfSample> sample(const glm::vec3& wo, const BsdfNumbers& numbers,
                                     TransportMode mode = TransportMode::Radiance) const;
    float pdf(const glm::vec3& wo, const glm::vec3& wi, DiffuseWarp warp) const;

private:
    LayeredBsdf opaque_;
    Dielectric dielectric_;
    float transmission_;
};

extern template class TransmissionBlend<SmoothDielectric>;
extern template class TransmissionBlend<RoughDielectric>;
extern template class TransmissionBlend<ThinDielectric>;

}  // namespace strata
