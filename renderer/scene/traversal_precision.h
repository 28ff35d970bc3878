#pragma once
// Which of Embree's two triangle tests a scene needs.
//
// Embree's robust mode (RTC_SCENE_FLAG_ROBUST) tests triangles with Pluecker coordinates, whose
// edge terms are the same numbers for the two triangles that share an edge (watertight), and
// traverses with conservative boxes. Its fast mode tests them by Moeller-Trumbore, which works
// from vertex minus ray origin: each difference is rounded to within u M (u = 2^-24, M the largest
// coordinate magnitude of the scene), and the two triangles on an edge round differently, so a ray
// can pass between them inside a band about u M wide along the edge. The share of a triangle's
// area inside that band is about
//   u M P / A,  P its perimeter and A its area,
// which grows with the scene's distance from the origin against the triangle's size, not with
// the scene's scale. A scene's rounding gap share is its largest triangle's; the Cornell box near
// the origin reads 2e-6, the bundled furnace 3e-6, the same furnace moved 1e5 away 0.3.
//
// What fast mode costs, measured (tests/scene/test_traversal_precision.cpp and
// test_scene_robustness.cpp): rays from inside the closed furnace escape through its edges at
// 0.001-0.034 of the share (none in 10^6 at the origin, 9% at 10^6 away); rays spawned from hits
// on wild single triangles (coordinates 1e-8..1e8) found their own triangle again from a share of
// 3e-5 on, never below 1e-5 in 196,000. A wider sweep (docs/design.md, "The triangle test"), of
// slivers too, found none under 3.2e-6 and 1.7e-4 of the spawned rays between 3.2e-6 and 1e-5,
// rising to percents above it. Up to kTolerableGapShare, then, fast mode changes no estimate
// measurably, and traces the Cornell box's paths in 0.90 of the time (cornell_point, 96 spp, 5
// alternated renders); above it a scene takes the watertight test.
//
// Bounce and shadow rays start on the surfaces, inside M; a camera far outside the scene's
// bounds widens the bands for its own rays (not for the paths after them).
//
// A shared mesh's triangles (mesh.h) count as their placements make them in the world: M is the
// world's, and a placement's linear map L raises P / A by sigma_1^2 / |det L| at most (exactly,
// for a similarity). Embree tests them in the shared mesh's coordinates, after moving the ray
// there; the two triangles on an edge are both tested with that one moved ray, so their band is
// the one above, measured in those coordinates, which is the world's divided by the scale.
#include "scene/mesh.h"

namespace strata {

enum class Traversal {
    Automatic,   // watertight when the scene's rounding gap share is above kTolerableGapShare
    Watertight,  // always Embree's robust mode
    Fast,        // always Embree's fast mode
};

inline constexpr double kTolerableGapShare = 1e-5;

// The largest u M P / A over the mesh's triangles of nonzero area, in the world (above); 0 when
// there is none.
double roundingGapShare(const MeshData& mesh);

// Whether a scene whose rounding gap share is `gapShare` is traced with the watertight test:
// `requested`, with Automatic resolved by the share.
bool usesWatertightTest(Traversal requested, double gapShare);

}  // namespace strata
