// The rounding gap share (traversal_precision.h) and what it predicts: how many rays Embree's
// fast triangle test lets through the edges of a closed mesh, and which scenes take it.
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "render_support.h"
#include "scene/scene.h"
#include "scene/scene_loader.h"
#include "test_support.h"

using namespace strata;

namespace {

MeshData triangleMesh(const std::vector<glm::vec3>& corners) {
    MeshData mesh;
    mesh.materials = {{"grey", glm::vec3(0.5f), glm::vec3(0.0f)}};
    mesh.positions = corners;
    for (uint32_t i = 0; i + 2 < corners.size(); i += 3) {
        mesh.triangles.push_back({i, i + 1, i + 2});
        mesh.triangleMaterials.push_back(0);
    }
    return mesh;
}

// Of `rays` rays from points around the centre of the furnace's closed sphere (radius 1, centred
// on the origin, then moved by `offset`), in uniformly random directions, how many find no
// triangle: each of them slipped through an edge.
int escapedRays(const MeshData& sphere, const glm::dvec3& offset, Traversal traversal, int rays) {
    const Scene scene(test::transformMesh(sphere, 1.0, offset), traversal);
    std::mt19937_64 rng(20261202);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    int escaped = 0;
    for (int i = 0; i < rays; ++i) {
        const glm::dvec3 direction = test::uniformUnitVector(rng);
        // Starts spread over a cube of side 0.5, so that rays cross the edges at every angle.
        const glm::dvec3 start =
            offset + 0.5 * glm::dvec3(uniform(rng) - 0.5, uniform(rng) - 0.5, uniform(rng) - 0.5);
        const Ray ray{glm::vec3(start), glm::vec3(direction)};
        if (!scene.intersect(ray)) ++escaped;
    }
    return escaped;
}

}  // namespace

TEST_CASE("traversal precision: a triangle's share is u M P / A, the scene's its largest triangle's") {
    const double u = 0x1p-24;
    // The unit right triangle at the origin: M = 1, P = 2 + sqrt 2, A = 1/2.
    const MeshData unit = triangleMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    CHECK(roundingGapShare(unit) == doctest::Approx(u * (2.0 + std::sqrt(2.0)) / 0.5).epsilon(1e-12));
    // Scaled, it reads the same; moved to x = 1000, M = 1001.
    CHECK(roundingGapShare(test::transformMesh(unit, 1e3, glm::dvec3(0.0))) ==
          doctest::Approx(roundingGapShare(unit)).epsilon(1e-6));
    CHECK(roundingGapShare(test::transformMesh(unit, 1.0, glm::dvec3(1e3, 0.0, 0.0))) ==
          doctest::Approx(1001.0 * roundingGapShare(unit)).epsilon(1e-6));
    // A sliver beside it, 1000 long and 0.01 wide (P/A ~ 2000 / 5), decides the scene's share.
    const MeshData both = triangleMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1000, 0, 1}, {0, 0.01f, 1}});
    const double sliver = (1000.0 + std::hypot(1000.0, 0.01) + 0.01) / (0.5 * 1000.0 * 0.01);
    CHECK(roundingGapShare(both) == doctest::Approx(u * 1000.0 * sliver).epsilon(1e-6));
    // Triangles without area have no band to lose rays in.
    CHECK(roundingGapShare(triangleMesh({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}})) == 0.0);
}

TEST_CASE("traversal precision: the fast test lets fewer rays through a closed mesh than the share, the watertight none") {
    const LoadedScene furnace = loadScene(test::sourceDir() / "assets/furnace/furnace.obj");
    const MeshData& sphere = furnace.scene.mesh();
    struct Placement {
        glm::dvec3 offset;
        int rays;
    };
    // At the origin (share 3e-6) and 1e5 away (0.3), where the gaps are wide enough to lose
    // rays by the thousand: the count sees them, so it could see them nearer too.
    for (const Placement& placement : {Placement{glm::dvec3(0.0), 1000000}, Placement{glm::dvec3(1e5, -1e5, 1e5), 200000}}) {
        CAPTURE(placement.offset.x);
        const double share = roundingGapShare(test::transformMesh(sphere, 1.0, placement.offset));
        const int fast = escapedRays(sphere, placement.offset, Traversal::Fast, placement.rays);
        CAPTURE(share);
        CAPTURE(fast);
        CHECK(fast <= share * placement.rays);
        if (share > 0.1) CHECK(fast > 0);
        CHECK(escapedRays(sphere, placement.offset, Traversal::Watertight, placement.rays) == 0);
    }
}

TEST_CASE("traversal precision: scenes near the origin take the fast test, far or with slivers the watertight one") {
    const LoadedScene cornell = loadScene(test::cornellScene());
    const LoadedScene furnace = loadScene(test::sourceDir() / "assets/furnace/furnace.obj");
    CHECK_FALSE(cornell.scene.summary().watertight);
    CHECK_FALSE(furnace.scene.summary().watertight);
    CHECK(cornell.scene.summary().roundingGapShare < kTolerableGapShare);
    const Scene far(test::transformMesh(furnace.scene.mesh(), 1.0, glm::dvec3(1e5, -1e5, 1e5)));
    CHECK(far.summary().watertight);
    const Scene sliver(triangleMesh({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1000, 0, 1}, {0, 0.01f, 1}}));
    CHECK(sliver.summary().watertight);
    // Asked for, either test is taken whatever the share.
    CHECK(Scene(test::transformMesh(furnace.scene.mesh(), 1.0, glm::dvec3(1e5)), Traversal::Fast).summary().watertight == false);
    CHECK(Scene(furnace.scene.mesh(), Traversal::Watertight).summary().watertight);
}
