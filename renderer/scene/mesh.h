#pragma once
// Geometry and materials as plain data: what a scene format's loader produces (scene_format.h) and
// what tests build by hand.
#include <array>
#include <cstdint>
#include <string>
#include <vector>
#include <glm/vec3.hpp>

namespace strata {

struct Material {
    std::string name;
    glm::vec3 diffuse{0.0f};   // Kd: Lambertian albedo
    glm::vec3 emission{0.0f};  // Ke: radiance emitted on the counter-clockwise (front) side
    glm::vec3 specular{0.0f};  // Ks: Fresnel reflectance at normal incidence of the GGX layer
    float roughness = 1.0f;    // Pr (or converted from Ns): GGX alpha = Pr^2 (material.h)
};

struct PointLight {
    glm::vec3 position;
    glm::vec3 intensity;  // W/sr; reached only by next-event estimation (a delta light)
};

struct MeshData {
    std::vector<glm::vec3> positions;
    // Vertex indices, counter-clockwise seen from the front.
    std::vector<std::array<uint32_t, 3>> triangles;
    std::vector<uint32_t> triangleMaterials;  // one index into `materials` per triangle
    std::vector<Material> materials;
    std::vector<PointLight> pointLights;
};

}  // namespace strata
