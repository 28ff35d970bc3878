#include <doctest/doctest.h>

#include <cmath>
#include <vector>
#include <glm/geometric.hpp>

#include "geometry/smoothing_groups.h"

using namespace strata;

namespace {

constexpr std::array<uint32_t, 3> kFlat{UINT32_MAX, UINT32_MAX, UINT32_MAX};

// The normal that `result` gives `vertex` of triangle t.
glm::vec3 normalAt(const GroupNormals& result, const std::vector<SmoothTriangle>& triangles, size_t t, uint32_t vertex) {
    for (size_t k = 0; k < 3; ++k) {
        if (triangles[t].vertices[k] == vertex) return result.normals.at(result.corners[t][k]);
    }
    FAIL("the triangle does not use the vertex");
    return {};
}

void checkDirection(const glm::vec3& normal, const glm::vec3& expected) {
    CAPTURE(normal);
    CAPTURE(expected);
    CHECK(glm::length(normal) == doctest::Approx(1.0).epsilon(1e-6));
    CHECK(glm::dot(normal, glm::normalize(expected)) == doctest::Approx(1.0).epsilon(1e-6));
}

// The square pyramid with apex (0, 0, 1) over the base corners (+-1, +-1, 0), its four sides
// counter-clockwise seen from outside; with `splitOneSide`, the side over the edge y = -1 is
// split at the edge's midpoint (vertex 5) into two triangles.
std::vector<SmoothTriangle> pyramid(bool splitOneSide) {
    std::vector<SmoothTriangle> sides{{{0, 1, 2}, 1}, {{0, 2, 3}, 1}, {{0, 3, 4}, 1}};
    if (splitOneSide) {
        sides.push_back({{0, 4, 5}, 1});
        sides.push_back({{0, 5, 1}, 1});
    } else {
        sides.push_back({{0, 4, 1}, 1});
    }
    return sides;
}
const std::vector<glm::vec3> kPyramid{{0, 0, 1}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, {-1, -1, 0}, {0, -1, 0}};

}  // namespace

TEST_CASE("smoothing groups: each vertex of a regular octahedron gets its direction from the centre") {
    const std::vector<glm::vec3> positions{{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    std::vector<SmoothTriangle> faces;
    for (uint32_t x : {0u, 1u}) {
        for (uint32_t y : {2u, 3u}) {
            for (uint32_t z : {4u, 5u}) {
                // Counter-clockwise seen from outside: the corners' triple product is positive.
                const bool outward = glm::dot(positions[x], glm::cross(positions[y], positions[z])) > 0.0f;
                faces.push_back({outward ? std::array<uint32_t, 3>{x, y, z} : std::array<uint32_t, 3>{x, z, y}, 7});
            }
        }
    }
    const GroupNormals result = smoothingGroupNormals(positions, faces);
    CHECK(result.normals.size() == 6);
    for (size_t t = 0; t < faces.size(); ++t) {
        for (uint32_t v : faces[t].vertices) checkDirection(normalAt(result, faces, t, v), positions[v]);
    }
}

TEST_CASE("smoothing groups: the normal weighs faces by their angle, so splitting a face leaves it unchanged") {
    for (bool split : {false, true}) {
        CAPTURE(split);
        const std::vector<SmoothTriangle> faces = pyramid(split);
        const GroupNormals result = smoothingGroupNormals(kPyramid, faces);
        // By symmetry the apex's normal is +z. Weighted by area or not at all, the split side
        // would count twice and tilt it toward -y.
        checkDirection(normalAt(result, faces, 0, 0), {0, 0, 1});
        // A base corner is shared by two sides of normals (1, 0, 1) and (0, -1, 1) over equal
        // angles: between them.
        checkDirection(normalAt(result, faces, 0, 1), {1, -1, 2});
        // The split edge's midpoint is on one side only: that side's normal.
        if (split) checkDirection(normalAt(result, faces, 3, 5), {0, -1, 1});
    }
}

TEST_CASE("smoothing groups: faces of different groups that share a vertex keep an edge between them") {
    // The pyramid's sides in two groups: {y = -1 side, x = 1 side} and the other two.
    std::vector<SmoothTriangle> faces = pyramid(false);
    faces[0].group = 2;  // the x = 1 side
    faces[3].group = 2;  // the y = -1 side
    const GroupNormals result = smoothingGroupNormals(kPyramid, faces);
    // The apex is shared by both groups: two normals, each the mean of its group's sides.
    checkDirection(normalAt(result, faces, 0, 0), {1, -1, 2});
    checkDirection(normalAt(result, faces, 1, 0), {-1, 1, 2});
    // Corner (1, 1, 0) joins the x = 1 side (group 2) and the y = 1 side (group 1): each keeps its own.
    checkDirection(normalAt(result, faces, 0, 2), {1, 0, 1});
    checkDirection(normalAt(result, faces, 1, 2), {0, 1, 1});
    // A normal per vertex and group: the apex and the corners at a group's border two each.
    CHECK(result.normals.size() == 2 + 1 + 2 + 1 + 2);
}

TEST_CASE("smoothing groups: a sheet folded back onto itself, and a triangle without area, are shaded flat") {
    const std::vector<glm::vec3> positions{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 0, 0}, {5, 5, 5}};
    const std::vector<SmoothTriangle> faces{
        {{0, 1, 2}, 1}, {{0, 2, 1}, 1},  // one triangle, both windings: its normals cancel
        {{0, 1, 3}, 4},                  // collinear corners
        {{1, 2, 4}, 4},                  // an ordinary triangle, whose vertex 1 it shares with the collinear one
    };
    const GroupNormals result = smoothingGroupNormals(positions, faces);
    REQUIRE(result.corners.size() == 4);
    CHECK(result.corners[0] == kFlat);
    CHECK(result.corners[1] == kFlat);
    CHECK(result.corners[2] == kFlat);
    REQUIRE(result.corners[3] != kFlat);
    const glm::vec3 own = glm::cross(positions[2] - positions[1], positions[4] - positions[1]);
    for (uint32_t v : faces[3].vertices) checkDirection(normalAt(result, faces, 3, v), own);
    for (const glm::vec3& n : result.normals) CHECK(std::isfinite(n.x + n.y + n.z));
}
