#pragma once
// Splits a polygon face into triangles, for file formats whose faces may have any number of
// corners (OBJ). A fan from the first corner is right only for a convex polygon: on a concave one
// (an L, a C, a ring cut open by a slit, as CAD and modelling tools export them) its triangles
// overlap and cover the notches. Ear clipping (Meisters 1975) cuts off, one at a time, a convex
// corner whose triangle holds no other corner, which every simple polygon has two of; the
// triangles then tile the polygon exactly.
#include <array>
#include <cstdint>
#include <span>
#include <vector>
#include <glm/vec3.hpp>

namespace strata {

// Corner visits that ear clipping may still spend, shared by all faces of one file: a polygon
// drawn to make each cut look far for its ear costs n^3 visits, and a file of them must not hold
// the loader for minutes. A face found with the budget spent is split as a fan.
struct TriangulationBudget {
    uint64_t visits;
};

// The loaders' budget: about a quarter of a second of ear clipping per file.
inline constexpr uint64_t kTriangulationVisits = uint64_t(1) << 27;

// Appends the polygon's n - 2 triangles to `triangles`, as indices into `corners` and turning
// the way the corners do (so the face's front stays its front). The polygon may lie in any plane
// and need not be exactly planar; it is split in its projection along the largest component of
// its Newell normal. A convex quad is split along its shorter diagonal, as tinyobjloader does;
// any other convex polygon as a fan from corner 0. A polygon with no area or a non-finite corner
// gets a fan too (the loader drops its triangles without area or with a non-finite corner); one
// that crosses itself gets triangles that cover it, not a tiling. Returns false when the budget
// ran out before the polygon was clipped, its remaining corners then split as a fan.
bool triangulatePolygon(std::span<const glm::vec3> corners, TriangulationBudget& budget,
                        std::vector<std::array<uint32_t, 3>>& triangles);

}  // namespace strata
