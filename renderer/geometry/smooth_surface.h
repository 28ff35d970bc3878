#pragma once
// The smooth surface that a flat triangle's vertex normals describe, for shadow rays near the
// shadow terminator. A coarse mesh with interpolated normals is shaded as if it were curved, but
// its shadow rays leave the flat facets: where the light grazes a facet, or lies below its plane
// although above the interpolated normal's horizon, the facet's own plane or its neighbours
// block light that the curved surface would receive, and the terminator shows the facets as
// dark, hard-edged patches. Hanika ("Hacking the Shadow Terminator", Ray Tracing Gems II, ch. 4,
// 2021) moves the shadow ray's origin onto a curved surface through the triangle's vertices:
// the hit point projected onto the tangent plane of each vertex (the plane through the vertex
// normal to its normal), where it lies below that plane, and the three projections averaged by
// the hit's barycentrics. The surface meets the triangle at its vertices, bulges out where the
// normals spread apart, and is the triangle itself where they agree.
//
// Only shadow rays leave from it: the hit point, the shading and the directions sampled stay the
// triangle's. It changes what the scene's geometry is taken to be, so it is off unless asked for.
#include <array>
#include <glm/vec3.hpp>

namespace strata {

// The displacement from the point with barycentrics `barycentrics` of the triangle `corners` to
// the curved surface above, on the side its (unit or not) vertex `normals` face: zero where no
// tangent plane lies above the point.
glm::vec3 smoothSurfaceLift(const std::array<glm::vec3, 3>& corners, const std::array<glm::vec3, 3>& normals,
                            const glm::vec3& barycentrics);

// How much of that lift a shadow ray toward a light `geometricCosine` above the facet's plane
// takes (the cosine with the geometric normal, negative below the plane): all of it at and below
// the plane, none from `cutoff` up, linearly between; none when `cutoff` is 0 (off).
float terminatorLiftShare(float geometricCosine, float cutoff);

}  // namespace strata
