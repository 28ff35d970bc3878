#pragma once
// A perfect mirror: a Dirac delta reflection about the normal with Schlick's Fresnel, F0 = Ks
// (MTL illum 3/5 with Pr 0, glTF metallic 1 at roughness 0, and the GGX layer's limit at
// roughness 0, where its lobe would have no width). No light sample can find its direction, so
// evaluate and pdf are 0 and only sample() scatters.
#include <optional>
#include <glm/vec3.hpp>

#include "materials/bsdf_sample.h"
#include "materials/delta_lobes.h"

namespace strata {

class SmoothConductor : public DeltaLobes {
public:
    explicit SmoothConductor(const glm::vec3& f0) : f0_(f0) {}

    bool isBlack() const { return f0_.x == 0.0f && f0_.y == 0.0f && f0_.z == 0.0f; }
    BsdfFlags flags() const { return kReflection | kSpecular; }
    // The mirror direction, weighted by F(cos theta_o); reads no numbers.
    std::optional<BsdfSample> sample(const glm::vec3& wo, const BsdfNumbers& numbers,
                                     TransportMode = TransportMode::Radiance) const;
    // F(cos theta_o): the share of the light it reflects toward wo.
    glm::vec3 albedo(const glm::vec3& wo) const;

private:
    glm::vec3 f0_;
};

}  // namespace strata
