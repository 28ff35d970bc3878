#pragma once
// glTF 2.0's metallic-roughness model ("Materials", "Appendix B: BRDF Implementation") onto
// Strata's layered material (layered_bsdf.h), in one place for the loader's constants and the
// per-hit values of textured materials:
//   diffuse   Kd = baseColor (1 - metallic): a metal has no diffuse lobe;
//   specular  Ks = lerp(0.04, baseColor, metallic): the Fresnel reflectance at normal incidence,
//             0.04 for a dielectric.
// Roughness needs no mapping: glTF's GGX alpha is roughness^2, as Strata's is Pr^2.
#include <glm/common.hpp>
#include <glm/vec3.hpp>

namespace strata {

struct LayeredReflectance {
    glm::vec3 diffuse;
    glm::vec3 specular;
};

inline LayeredReflectance fromMetallicRoughness(const glm::vec3& baseColor, float metallic) {
    return {baseColor * (1.0f - metallic), glm::mix(glm::vec3(0.04f), baseColor, metallic)};
}

}  // namespace strata
