#pragma once
// A clear coat over another model (glTF KHR_materials_clearcoat; a smooth varnish over a diffuse
// base): a dielectric interface of weight w (the coat's factor), Fresnel reflectance F0 (0.04 for
// the coat's index 1.5) and roughness (0: a Dirac delta, else GGX at alpha = roughness^2), which
// reflects its share of the light and lets the rest through to the base and back:
//   f = w f_coat + (1 - w E_c(mu_o)) (1 - w E_c(mu_i)) f_base,
// E_c being the coat's directional albedo (Schlick's F for the smooth coat, the GGX tables of
// microfacet.h for the rough one). The attenuation is symmetric in the two directions, as the
// layered model's coupling is (layered_bsdf.h), so f is reciprocal, and the albedo is
// w E_c + (1 - w E_c) A_base' <= 1 wherever the base's is (A_base' being the base's albedo under
// the attenuation of the coat on the way out). What the coat's interior would scatter between
// the two layers is not modelled (a little energy is lost there, not created).
//
// Sampling chooses the coat with probability by its albedo at wo against the base's, with
// numbers.lobeChoice, rescaled so that the base chooses among its own lobes with what is left.
//
// The coat may have a normal of its own (tilt): glTF's coat takes its own normal map, or none
// where the base has one. Its lobe and its albedos E_c are then those of the coat's frame, and the
// coat's reflection is projected on the coat's normal as a lobe of its own frame would be,
// f_coat cos_coat(wi) / cos(wi), so that it still reflects at most w E_c (the albedo stays <= 1)
// and a direction the coat sees from below is one it does not reflect. The coat's term is then
// reciprocal in its own frame, not in the surface's, as with any shading normal.
#include <optional>
#include <utility>
#include <glm/vec3.hpp>

#include "geometry/frame.h"
#include "materials/bsdf_sample.h"
#include "materials/layered_bsdf.h"
#include "materials/sheen.h"
#include "materials/smooth_conductor.h"

namespace strata {

struct CoatLayer {
    float weight = 0.0f;
    glm::vec3 f0{0.04f};
    const SpecularLobe* lobe = nullptr;  // the rough coat's GGX lobe; null: smooth

    // w E_c(mu), per channel; a direction at or below the coat's plane counts as grazing (mu 0).
    glm::vec3 albedo(float mu) const;
};

template <class Base>
class Coated {
public:
    Coated(const CoatLayer& coat, const Base& base) : coat_(coat), base_(base) {}

    bool isBlack() const { return false; }
    BsdfFlags flags() const {
        return static_cast<BsdfFlags>(base_.flags() | kReflection | (coat_.lobe ? kGlossy : kSpecular));
    }
    glm::vec3 evaluate(const glm::vec3& wo, const glm::vec3& wi, TransportMode mode = TransportMode::Radiance) const;
    std::optional<BsdfSample> sample(const glm::vec3& wo, const BsdfNumbers& numbers,
                                     TransportMode mode = TransportMode::Radiance) const;
    float pdf(const glm::vec3& wo, const glm::vec3& wi, DiffuseWarp warp) const;
    glm::vec3 albedo(const glm::vec3& wo) const;

    const Base& base() const { return base_; }
    // Turns the coat's normal to `axis` (unit, in the local frame, above the surface).
    void tilt(const glm::vec3& axis) { axis_ = axis; }

private:
    bool tilted() const { return axis_ != glm::vec3(0.0f, 0.0f, 1.0f); }
    // wo and wi in the coat's frame: the local frame itself unless the coat is tilted.
    std::pair<glm::vec3, glm::vec3> inCoatFrame(const glm::vec3& wo, const glm::vec3& wi) const;
    // The probability of sampling the coat, `coatCosine` being wo's cosine to the coat's normal
    // (0 where that is not positive).
    float coatProbability(const glm::vec3& wo, float coatCosine) const;
    // The coat's GGX reflection alone, of directions in the coat's frame (0 for the smooth coat,
    // whose delta evaluate() leaves out).
    glm::vec3 roughCoat(const glm::vec3& wo, const glm::vec3& wi) const;

    CoatLayer coat_;
    Base base_;
    glm::vec3 axis_{0.0f, 0.0f, 1.0f};  // the coat's normal in the local frame
};

extern template class Coated<LayeredBsdf>;
extern template class Coated<SmoothConductor>;
extern template class Coated<Sheened>;

}  // namespace strata
