#pragma once
// Alpha cut-outs and opacities (MTL map_d and d, glTF alphaMode MASK and BLEND) inside Embree's
// traversal: the scene's cut-out triangles form an Embree geometry of their own, and its
// intersection and occlusion filter rejects every hit where the material's coverage at the hit's UV
// is below its cutoff, so that camera, bounce and shadow rays alike go on through the cut-out part
// to whatever lies behind. A blended coverage is an opacity: the filter rejects the hit with
// probability 1 - opacity, by a number hashed from the ray and the triangle, so that in expectation
// a pixel, a path's reflection and a shadow ray's visibility all see the surface blended over what
// lies behind it (pbrt-v4's stochastic alpha test, each layer apart). Opaque triangles are in
// another geometry without a filter and pay nothing for it. The test reads only the ray and the
// hit, so tracing stays deterministic.
#include <array>
#include <vector>
#include <embree3/rtcore.h>
#include <glm/vec2.hpp>

#include "materials/material.h"

namespace strata {

// What the filter reads, per triangle of the cut-out geometry (by its primID there).
struct CutoutTriangles {
    std::vector<std::array<glm::vec2, 3>> uvs;
    std::vector<const Material*> materials;  // outlive the filter
};

// Makes `geometry` reject the hits that `triangles` say are cut out; `triangles` outlives it.
void attachCutoutFilter(RTCGeometry geometry, const CutoutTriangles& triangles);

}  // namespace strata
