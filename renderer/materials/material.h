#pragma once
// A surface's material as scene files give it (MTL today): plain data, turned into a BSDF at each
// hit by MaterialTable (material_table.h).
#include <string>
#include <glm/vec3.hpp>

namespace strata {

struct Material {
    std::string name;
    glm::vec3 diffuse{0.0f};   // Kd: Lambertian albedo
    glm::vec3 emission{0.0f};  // Ke: radiance emitted on the counter-clockwise (front) side
    glm::vec3 specular{0.0f};  // Ks: Fresnel reflectance at normal incidence of the GGX layer
    float roughness = 1.0f;    // Pr (or converted from Ns): GGX alpha = Pr^2 (microfacet.h)
};

}  // namespace strata
