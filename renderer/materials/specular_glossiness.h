#pragma once
// glTF's specular-glossiness model (KHR_materials_pbrSpecularGlossiness, "Specular - Glossiness"
// and its reference BRDF) onto Strata's layered material (layered_bsdf.h), for the loader's
// constants and the per-hit values of textured materials:
//   diffuse   Kd = diffuse (1 - max(specular)): the light the specular colour reflects at normal
//             incidence is taken from the diffuse lobe, as the model's c_diff is;
//   specular  Ks = specular: the Fresnel reflectance at normal incidence (F0);
//   roughness Pr = 1 - glossiness: the model's GGX alpha is (1 - glossiness)^2, Strata's Pr^2.
#include <algorithm>
#include <glm/vec3.hpp>

#include "materials/metallic_roughness.h"

namespace strata {

inline LayeredReflectance fromSpecularGlossiness(const glm::vec3& diffuse, const glm::vec3& specular) {
    return {diffuse * (1.0f - std::max({specular.x, specular.y, specular.z})), specular};
}

}  // namespace strata
