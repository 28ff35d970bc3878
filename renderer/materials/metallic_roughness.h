#pragma once
// glTF 2.0's metallic-roughness model ("Materials", "Appendix B: BRDF Implementation") onto
// Strata's layered material (layered_bsdf.h), in one place for the loader's constants and the
// per-hit values of textured materials:
//   diffuse   Kd = baseColor (1 - metallic): a metal has no diffuse lobe;
//   specular  Ks = lerp(F0, baseColor, metallic): the Fresnel reflectance at normal incidence,
//             F0 for a dielectric: ((ior - 1) / (ior + 1))^2 = 0.04 at glTF's default index 1.5,
//             times KHR_materials_specular's colour and factor where it is given.
// Roughness needs no mapping: glTF's GGX alpha is roughness^2, as Strata's is Pr^2.
#include <glm/common.hpp>
#include <glm/vec3.hpp>

namespace strata {

struct LayeredReflectance {
    glm::vec3 diffuse;
    glm::vec3 specular;
};

inline LayeredReflectance fromMetallicRoughness(const glm::vec3& baseColor, float metallic,
                                                const glm::vec3& dielectricF0 = glm::vec3(0.04f)) {
    return {baseColor * (1.0f - metallic), glm::mix(dielectricF0, baseColor, metallic)};
}

}  // namespace strata
