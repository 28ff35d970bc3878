#pragma once
// A scene as loaders give it: geometry, materials and the lights that are not emitting triangles
// (what a scene format's loader produces, scene_format.h, and what tests build by hand), and what
// rays leaving it see.
//
// Geometry that a scene places more than once (glTF nodes sharing a primitive) is stored once, as
// a shared mesh: a range of the triangles in coordinates of its own, placed in the world by each
// of its placements (Embree instances, scene.h). Every other triangle is in world coordinates,
// every triangle of a flat scene (an OBJ, a glTF file whose primitives are each used once).
#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "lights/directional_light.h"
#include "lights/environment.h"
#include "lights/point_light.h"
#include "lights/spot_light.h"
#include "materials/material.h"

namespace strata {

inline constexpr std::array<uint32_t, 3> kNoNormals{UINT32_MAX, UINT32_MAX, UINT32_MAX};
inline constexpr std::array<uint32_t, 3> kNoUvs = kNoNormals;
inline constexpr std::array<uint32_t, 3> kNoColours = kNoNormals;

// Triangles [firstTriangle, firstTriangle + triangleCount) of a mesh, in their own coordinates,
// drawn at each placement: an affine object-to-world transform (the last row 0 0 0 1) of nonzero
// determinant. Normals go by the inverse transpose; a mirroring placement (negative determinant)
// keeps the front side where it is, so the world front is where the transformed normals point.
struct SharedMesh {
    uint32_t firstTriangle = 0;
    uint32_t triangleCount = 0;
    std::vector<glm::mat4> placements;
};

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
    // Vertex colours in [0, 1] (OBJ `v x y z r g b`, glTF COLOR_0), interpolated across each
    // triangle and multiplying its material's diffuse or base colour, likewise: three indices into
    // `colours` per triangle, or kNoColours for a triangle without (white). Empty: none has any.
    std::vector<glm::vec3> colours;
    std::vector<std::array<uint32_t, 3>> triangleColours;
    std::vector<Material> materials;
    // Disjoint ranges of the triangles, in increasing order, each with vertices of its own.
    std::vector<SharedMesh> sharedMeshes;
    std::vector<PointLight> pointLights;
    std::vector<SpotLight> spotLights;
    std::vector<DirectionalLight> directionalLights;
    Environment environment;
};

// The texture coordinates of a triangle's corners, (0, 0) for one without.
inline std::array<glm::vec2, 3> cornerUvs(const MeshData& mesh, size_t triangle) {
    if (mesh.triangleUvs.empty() || mesh.triangleUvs[triangle] == kNoUvs) return {};
    const auto& c = mesh.triangleUvs[triangle];
    return {mesh.uvs[c[0]], mesh.uvs[c[1]], mesh.uvs[c[2]]};
}

// The world bounding box of the mesh, {lower, upper} corner by corner: of all its vertices for a
// flat mesh; with shared meshes, of the vertices the world's triangles use (a shared mesh's other
// vertices are in its own coordinates) and of each placement of each shared mesh's box (a box
// about the placed vertices, tight under translation, scale and mirroring). {+inf, -inf} for no
// vertices.
std::pair<glm::vec3, glm::vec3> worldBounds(const MeshData& mesh);

// The triangles of the mesh's world: those not shared, and each shared mesh's times its placements.
uint64_t placedTriangles(const MeshData& mesh);

// The area of the mesh's world: its world triangles', and each shared mesh's at each placement,
// scaled by the placement's |determinant|^(2/3). That is exact for a placement that scales
// uniformly (with any rotation, mirroring and translation) and an estimate for one that does not,
// which would take every placed triangle: it costs the stored triangles and the placements only.
double worldArea(const MeshData& mesh);

}  // namespace strata
