#pragma once
// Vertex normals for faces that a file marks smooth without giving their normals: an OBJ face in
// a smoothing group (`s 1`) and without `vn`. Faces of one group that share a vertex share its
// normal there, so the group shades as one curved surface; where two groups meet, or a group
// meets a face outside any, the edge stays sharp (the OBJ format's meaning of the groups, and
// that of the tools that write them).
//
// A vertex's normal is the sum of its faces' unit normals, each weighted by the face's angle at
// the vertex (Thürmer & Wüthrich 1998): unlike weights by area or none, it does not depend on
// how the faces around the vertex were split into triangles.
#include <array>
#include <cstdint>
#include <span>
#include <vector>
#include <glm/vec3.hpp>

namespace strata {

struct SmoothTriangle {
    std::array<uint32_t, 3> vertices;  // indices into the positions
    uint32_t group;                    // the smoothing group, nonzero
};

struct GroupNormals {
    std::vector<glm::vec3> normals;  // unit
    // Per triangle given, three indices into `normals` in the order of its vertices; UINT32_MAX
    // in all three for a triangle with a corner whose faces' normals cancel (a sheet folded back
    // onto itself), which is then shaded flat.
    std::vector<std::array<uint32_t, 3>> corners;
};

// The normals of the triangles' corners, one per (vertex, group) that the triangles use. The
// triangles must have finite corners and nonzero area (the loaders drop the others).
GroupNormals smoothingGroupNormals(std::span<const glm::vec3> positions, std::span<const SmoothTriangle> triangles);

}  // namespace strata
