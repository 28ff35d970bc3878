#pragma once
// A scene as loaders give it: geometry, materials and the lights that are not emitting triangles
// (what a scene format's loader produces, scene_format.h, and what tests build by hand), and what
// rays leaving it see.
#include <array>
#include <cstdint>
#include <string>
#include <vector>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "lights/directional_light.h"
#include "lights/environment.h"
#include "lights/point_light.h"
#include "materials/material.h"

namespace strata {

inline constexpr std::array<uint32_t, 3> kNoNormals{UINT32_MAX, UINT32_MAX, UINT32_MAX};
inline constexpr std::array<uint32_t, 3> kNoUvs = kNoNormals;

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
    // Texture coordinates (textures/texture.h's convention: origin lower-left, v up), likewise:
    // three indices into `uvs` per triangle, or kNoUvs for a triangle without (its texture
    // lookups all read uv (0, 0)). Empty: no triangle has any.
    std::vector<glm::vec2> uvs;
    std::vector<std::array<uint32_t, 3>> triangleUvs;
    std::vector<Material> materials;
    std::vector<PointLight> pointLights;
    std::vector<DirectionalLight> directionalLights;
    Environment environment;
};

// The texture coordinates of a triangle's corners, (0, 0) for one without.
inline std::array<glm::vec2, 3> cornerUvs(const MeshData& mesh, size_t triangle) {
    if (mesh.triangleUvs.empty() || mesh.triangleUvs[triangle] == kNoUvs) return {};
    const auto& c = mesh.triangleUvs[triangle];
    return {mesh.uvs[c[0]], mesh.uvs[c[1]], mesh.uvs[c[2]]};
}

}  // namespace strata
