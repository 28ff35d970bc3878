#pragma once
// A thin dielectric sheet (a window pane; glTF's thin-walled transmission): two parallel smooth
// interfaces so close that the light between them is not resolved. Light is reflected with the
// sheet's total reflectance R = R0 + T0^2 R0 / (1 - R0^2) (every internal bounce summed, R0 the
// single interface's Fresnel reflectance and T0 = 1 - R0) and passes straight through otherwise:
// the two refractions undo each other, so the direction is -wo and no 1/eta^2 applies. The
// transmission filter Tf colours the light that passes. Both sides are alike.
#include <optional>
#include <glm/vec3.hpp>

#include "materials/bsdf_sample.h"
#include "materials/delta_lobes.h"

namespace strata {

class ThinDielectric : public DeltaLobes {
public:
    ThinDielectric(float eta, const glm::vec3& transmittance) : eta_(eta), transmittance_(transmittance) {}

    bool isBlack() const { return false; }
    BsdfFlags flags() const { return kReflection | kTransmission | kSpecular; }
    // Reflection with probability R (above), transmission with 1 - R, by numbers.lobeChoice.
    std::optional<BsdfSample> sample(const glm::vec3& wo, const BsdfNumbers& numbers,
                                     TransportMode = TransportMode::Radiance) const;
    // R at cos(theta_o) = |wo.z|.
    float reflectance(float cosThetaO) const;

private:
    float eta_;
    glm::vec3 transmittance_;
};

}  // namespace strata
