#pragma once
// A scene as loaders give it: geometry, materials and the lights that are not emitting triangles
// (what the OBJ loader produces and what tests build by hand), and what rays leaving it see.
#include <array>
#include <cstdint>
#include <string>
#include <vector>
#include <glm/vec3.hpp>

#include "lights/environment.h"
#include "lights/point_light.h"
#include "materials/material.h"

namespace strata {

struct MeshData {
    std::vector<glm::vec3> positions;
    // Vertex indices, counter-clockwise seen from the front.
    std::vector<std::array<uint32_t, 3>> triangles;
    std::vector<uint32_t> triangleMaterials;  // one index into `materials` per triangle
    std::vector<Material> materials;
    std::vector<PointLight> pointLights;
    Environment environment;
};

}  // namespace strata
