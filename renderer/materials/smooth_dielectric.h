#pragma once
// A smooth interface between two dielectrics (glass, water): a Dirac delta reflection and a Dirac
// delta refraction, chosen by the exact Fresnel reflectance for unpolarised light (fresnel.h),
// with total internal reflection where Snell's law has no solution. `eta` is the index of
// refraction below the normal (inside) over the one above it (outside); wo below the normal is
// light inside the object.
//
// Refraction into a denser medium compresses radiance by 1/eta^2 (Veach 1997, section 5.2), and a
// camera path carrying radiance is scaled by that ratio; importance is not. A closed object's
// transmission filter Tf (MTL Tf, glTF's transmission tint) is applied as sqrt(Tf) at every
// crossing, so that a passage in and out of the object passes Tf whatever the internal
// reflections, and the model stays symmetric (the eta^2 rule holds with the filter in it).
#include <optional>
#include <glm/vec3.hpp>

#include "materials/bsdf_sample.h"
#include "materials/delta_lobes.h"

namespace strata {

class SmoothDielectric : public DeltaLobes {
public:
    SmoothDielectric(float eta, const glm::vec3& transmittance);

    bool isBlack() const { return false; }
    BsdfFlags flags() const { return kReflection | kTransmission | kSpecular; }
    // Reflection with probability F(cos theta_o), refraction otherwise, chosen by
    // numbers.lobeChoice: the weight is then 1 for reflection and sqrt(Tf) / eta'^2 (radiance) or
    // sqrt(Tf) (importance) for refraction, eta' being the index crossed into over the one left.
    std::optional<BsdfSample> sample(const glm::vec3& wo, const BsdfNumbers& numbers,
                                     TransportMode mode = TransportMode::Radiance) const;

    float eta() const { return eta_; }

private:
    float eta_;
    glm::vec3 filter_;  // sqrt(Tf), per crossing
};

}  // namespace strata
