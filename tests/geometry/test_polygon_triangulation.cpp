#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include "geometry/polygon_triangulation.h"
#include "sampling/random.h"

using namespace strata;

namespace {

using Triangles = std::vector<std::array<uint32_t, 3>>;

// The vector area of a closed polygon (half its Newell normal): its length is the area.
glm::dvec3 vectorArea(const std::vector<glm::vec3>& corners) {
    glm::dvec3 sum(0.0);
    for (size_t i = 0; i < corners.size(); ++i) {
        sum += glm::cross(glm::dvec3(corners[i]), glm::dvec3(corners[(i + 1) % corners.size()]));
    }
    return 0.5 * sum;
}

Triangles triangulate(const std::vector<glm::vec3>& corners, uint64_t visits = kTriangulationVisits,
                      bool* withinBudget = nullptr) {
    TriangulationBudget budget{visits};
    Triangles triangles;
    const bool clipped = triangulatePolygon(corners, budget, triangles);
    if (withinBudget) *withinBudget = clipped;
    return triangles;
}

// A tiling of the polygon: n - 2 triangles, each turning as the polygon does, whose areas add
// up to the polygon's. A fan over a concave polygon fails the last two: its triangles across a
// notch turn the other way, and their areas (counted positive) add up to more.
void checkTiles(const std::vector<glm::vec3>& corners, const Triangles& triangles) {
    REQUIRE(triangles.size() == corners.size() - 2);
    const glm::dvec3 polygon = vectorArea(corners);
    const glm::dvec3 facing = glm::normalize(polygon);
    double sum = 0.0;
    for (const auto& t : triangles) {
        for (uint32_t corner : t) REQUIRE(corner < corners.size());
        const glm::dvec3 area = vectorArea({corners[t[0]], corners[t[1]], corners[t[2]]});
        CHECK(glm::dot(area, facing) >= -1e-9 * glm::length(polygon));
        sum += glm::length(area);
    }
    CHECK(sum == doctest::Approx(glm::length(polygon)).epsilon(1e-5));
}

// A star-shaped polygon about the origin in the xy plane, concave where the radius dips: simple
// whatever the radii, since every ray from the centre crosses its boundary once.
std::vector<glm::vec3> randomStar(uint64_t seed, size_t n) {
    std::vector<glm::vec3> corners;
    for (size_t i = 0; i < n; ++i) {
        const double angle = 2.0 * std::numbers::pi * double(i) / double(n);
        const float radius = 0.2f + uniformFloat(mixBits(seed * 1000 + i));
        corners.emplace_back(radius * std::cos(angle), radius * std::sin(angle), 0.0f);
    }
    return corners;
}

// `corners` turned by a rotation about a skew axis and moved far from the origin.
std::vector<glm::vec3> placed(std::vector<glm::vec3> corners, float angle, const glm::vec3& offset) {
    const glm::vec3 axis = glm::normalize(glm::vec3(0.3f, -0.8f, 0.5f));
    const float c = std::cos(angle);
    const float s = std::sin(angle);
    const glm::mat3 cross(0.0f, axis.z, -axis.y, -axis.z, 0.0f, axis.x, axis.y, -axis.x, 0.0f);
    const glm::mat3 rotation = c * glm::mat3(1.0f) + s * cross + (1.0f - c) * glm::outerProduct(axis, axis);
    for (glm::vec3& corner : corners) corner = rotation * corner + offset;
    return corners;
}

}  // namespace

TEST_CASE("polygon triangulation: a triangle is itself, a convex polygon a fan from its first corner") {
    CHECK(triangulate({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}) == Triangles{{0, 1, 2}});
    const std::vector<glm::vec3> pentagon{{0, 0, 0}, {2, 0, 0}, {3, 1, 0}, {1, 2, 0}, {-1, 1, 0}};
    CHECK(triangulate(pentagon) == Triangles{{0, 1, 2}, {0, 2, 3}, {0, 3, 4}});
    checkTiles(pentagon, triangulate(pentagon));
}

TEST_CASE("polygon triangulation: a convex quad splits along its shorter diagonal") {
    const std::vector<glm::vec3> kite{{0, 0, 0}, {1, -1, 0}, {3, 0, 0}, {1, 1, 0}};  // 0-2 long, 1-3 short
    CHECK(triangulate(kite) == Triangles{{0, 1, 3}, {1, 2, 3}});
    const std::vector<glm::vec3> wide{{0, 0, 0}, {1, -3, 0}, {2, 0, 0}, {1, 3, 0}};  // 0-2 short
    CHECK(triangulate(wide) == Triangles{{0, 1, 2}, {0, 2, 3}});
}

TEST_CASE("polygon triangulation: a concave quad splits through its inner corner, either way round") {
    // Corner 2 points inward: only the diagonal 0-2 lies inside, though 1-3 is the shorter.
    std::vector<glm::vec3> dart{{0, 0, 0}, {3, -1, 0}, {2.5f, 0, 0}, {3, 1, 0}};
    checkTiles(dart, triangulate(dart));
    std::reverse(dart.begin(), dart.end());
    checkTiles(dart, triangulate(dart));
}

TEST_CASE("polygon triangulation: an L, a C and a slit ring tile their polygon") {
    const std::vector<glm::vec3> l{{0, 0, 0}, {3, 0, 0}, {3, 1, 0}, {1, 1, 0}, {1, 3, 0}, {0, 3, 0}};
    checkTiles(l, triangulate(l));
    const std::vector<glm::vec3> c{{0, 0, 0}, {3, 0, 0}, {3, 1, 0}, {1, 1, 0}, {1, 2, 0},
                                   {3, 2, 0}, {3, 3, 0}, {0, 3, 0}};
    checkTiles(c, triangulate(c));
    // A ring cut open at the top, as a polygon runs round the outside and back round the inside
    // (the shape of assimp's concave_polygon.obj).
    std::vector<glm::vec3> ring;
    const int steps = 32;
    for (int i = 0; i <= steps; ++i) {
        const double a = std::numbers::pi / 2 + 0.01 + (2 * std::numbers::pi - 0.02) * i / steps;
        ring.emplace_back(std::cos(a), std::sin(a), 0.0f);
    }
    for (int i = steps; i >= 0; --i) {
        const double a = std::numbers::pi / 2 + 0.01 + (2 * std::numbers::pi - 0.02) * i / steps;
        ring.emplace_back(0.9 * std::cos(a), 0.9 * std::sin(a), 0.0f);
    }
    checkTiles(ring, triangulate(ring));
    // A square with a square hole, the hole joined to the outline by a slit of no width whose two
    // sides repeat its end corners (as exporters write a face with a hole).
    const std::vector<glm::vec3> holed{{0, 0, 0}, {4, 0, 0}, {4, 4, 0}, {0, 4, 0}, {0, 0, 0},
                                       {1, 1, 0}, {1, 3, 0}, {3, 3, 0}, {3, 1, 0}, {1, 1, 0}};
    const Triangles pieces = triangulate(holed);
    checkTiles(holed, pieces);
    double area = 0.0;
    for (const auto& t : pieces) area += glm::length(vectorArea({holed[t[0]], holed[t[1]], holed[t[2]]}));
    CHECK(area == doctest::Approx(12.0));
}

TEST_CASE("polygon triangulation: random star polygons tile in any plane, either winding, far from the origin") {
    for (uint64_t seed = 0; seed < 200; ++seed) {
        CAPTURE(seed);
        std::vector<glm::vec3> star = randomStar(seed, 4 + seed % 40);
        if (seed % 2) std::reverse(star.begin(), star.end());
        const glm::vec3 offset = seed % 3 == 0 ? glm::vec3(0.0f) : glm::vec3(1e3f, -2e3f, 5e2f);
        const std::vector<glm::vec3> corners = placed(star, 0.1f * float(seed), offset);
        checkTiles(corners, triangulate(corners));
    }
}

TEST_CASE("polygon triangulation: degenerate and crossing polygons still give n - 2 triangles") {
    // No area: a fan, whose triangles the loader drops as degenerate.
    CHECK(triangulate({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}, {4, 0, 0}}).size() == 3);
    // A corner not finite.
    const float nan = std::numeric_limits<float>::quiet_NaN();
    CHECK(triangulate({{0, 0, 0}, {1, 0, 0}, {nan, 1, 0}, {0, 1, 0}, {0, 0.5f, 0}}).size() == 3);
    // Repeated corners and a straight run.
    CHECK(triangulate({{0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {2, 0, 0}, {2, 2, 0}, {1, 1, 0}, {0, 2, 0}}).size() == 5);
    // A figure eight (its two loops turn opposite ways): no ear all round, and still an end.
    CHECK(triangulate({{0, 0, 0}, {2, 2, 0}, {2, 0, 0}, {0, 2, 0}, {-1, 3, 0}, {-1, -1, 0}}).size() == 4);
}

TEST_CASE("polygon triangulation: with its budget spent, a concave polygon falls back to a fan") {
    const std::vector<glm::vec3> l{{0, 0, 0}, {3, 0, 0}, {3, 1, 0}, {1, 1, 0}, {1, 3, 0}, {0, 3, 0}};
    bool withinBudget = true;
    CHECK(triangulate(l, 0, &withinBudget).size() == 4);
    CHECK_FALSE(withinBudget);
    triangulate(l, kTriangulationVisits, &withinBudget);
    CHECK(withinBudget);
    // A convex polygon needs no budget.
    triangulate({{0, 0, 0}, {2, 0, 0}, {3, 1, 0}, {1, 2, 0}, {-1, 1, 0}}, 0, &withinBudget);
    CHECK(withinBudget);
}
