#pragma once
// A scene as loaders give it: geometry, materials and the lights that are not emitting triangles
// (what a scene format's loader produces, scene_format.h, and what tests build by hand), and what
// rays leaving it see.
#include <array>
#include <cstdint>
#include <string>
#include <vector>
#include <glm/vec3.hpp>

#include "lights/directional_light.h"
#include "lights/environment.h"
#include "lights/point_light.h"
#include "materials/material.h"

namespace strata {

inline constexpr std::array<uint32_t, 3> kNoNormals{UINT32_MAX, UINT32_MAX, UINT32_MAX};

struct MeshData {
    std::vector<glm::vec3> positions;
    // Vertex indices, counter-clockwise seen from the front.
    std::vector<std::array<uint32_t, 3>> triangles;
    std::vector<uint32_t> triangleMaterials;  // one index into `materials` per triangle
    // Shading normals (unit), interpolated across each triangle from its corners: per triangle,
    // three indices into `normals` in the order of its vertices, or kNoNormals for a flat
    // triangle. Empty: every triangle is flat (its geometric normal).
    std::vector<glm::vec3> normals;
    std::vector<std::array<uint32_t, 3>> triangleNormals;
    std::vector<Material> materials;
    std::vector<PointLight> pointLights;
    std::vector<DirectionalLight> directionalLights;
    Environment environment;
};

}  // namespace strata
