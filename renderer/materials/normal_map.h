#pragma once
// Tangent-space normal mapping: a texel (x, y, z) * 0.5 + 0.5 gives the shading normal
// x T + y B + z N, with N the interpolated shading normal and T, B the directions of increasing
// u and v on the surface (dp/du, dp/dv from the triangle's positions and UVs), T made
// perpendicular to N and B = +-(N x T) keeping the UV's handedness. The constant texel
// (0.5, 0.5, 1) gives N itself.
#include <array>
#include <optional>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "textures/texture.h"

namespace strata {

// dp/du and dp/dv of a triangle; empty when its UVs are degenerate (no direction of u).
struct SurfaceTangents {
    glm::vec3 dpdu;
    glm::vec3 dpdv;
};
std::optional<SurfaceTangents> surfaceTangents(const std::array<glm::vec3, 3>& positions,
                                               const std::array<glm::vec2, 3>& uvs);

// The mapped shading normal (unit) at `uv`, x and y of the texel scaled by `scale`; `normal`
// itself when the texel or the tangents give no direction.
glm::vec3 mappedNormal(const Texture& map, float scale, glm::vec2 uv, const glm::vec3& normal,
                       const SurfaceTangents& tangents);

}  // namespace strata

namespace strata {

// Whether an image read as a bump map (MTL map_Bump/bump, which tools use for either) holds
// normals rather than heights: three or more channels, mean blue at least 0.6 and 0.1 above both
// mean red and mean green (the +z of flat-ish normals encodes as ~(0.5, 0.5, 1)), and the decoded
// vectors 2c - 1 of unit length on average within 0.2. A height map is grey (equal means).
bool looksLikeNormalMap(const Texture& image);

}  // namespace strata
