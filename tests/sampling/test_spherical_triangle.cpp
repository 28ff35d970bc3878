// A triangle seen from a point (spherical_triangle.h): its solid angle in closed-form cases, and
// Arvo's map giving directions that all hit the triangle, uniformly by solid angle (a chi-square
// over sub-triangles whose solid angles are computed independently of the map).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>
#include <glm/geometric.hpp>

#include "sampling/spherical_triangle.h"
#include "test_support.h"

using namespace strata;

namespace {

struct Configuration {
    const char* name;
    glm::dvec3 point, p0, p1, p2;
};

// Big, nearly a hemisphere, small and far, and an obtuse sliver-like one seen obliquely.
const Configuration kConfigurations[] = {
    {"octant", {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
    {"almost a hemisphere", {0.3, 0.3, 0.02}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}},
    {"small and far", {0.1, -0.2, 0.0}, {3, 1, 9}, {3.1, 1, 9}, {3, 1.05, 9.1}},
    {"obtuse, oblique", {0, 0, 0}, {-1, 0.2, 2}, {1, 0.25, 2}, {0, 0.3, 2.5}},
};

// Where the ray from `point` along `direction` meets the triangle's plane, as the coefficients
// (l1, l2) of p1 - p0 and p2 - p0; nullopt when it runs parallel or away from it.
std::optional<glm::dvec2> planeCoordinates(const Configuration& c, const glm::dvec3& direction) {
    const glm::dvec3 e1 = c.p1 - c.p0, e2 = c.p2 - c.p0;
    const glm::dvec3 normal = glm::cross(e1, e2);
    const double along = glm::dot(normal, direction);
    if (along == 0.0) return std::nullopt;
    const double t = glm::dot(normal, c.p0 - c.point) / along;
    if (!(t > 0.0)) return std::nullopt;
    const glm::dvec3 r = c.point + t * direction - c.p0;
    // Solve r = l1 e1 + l2 e2 by Cramer's rule in the plane.
    const double n2 = glm::dot(normal, normal);
    return glm::dvec2(glm::dot(glm::cross(r, e2), normal) / n2, glm::dot(glm::cross(e1, r), normal) / n2);
}

}  // namespace

TEST_CASE("spherical triangle: solid angles of the octant, a far triangle and a point on the plane") {
    // One eighth of the sphere.
    CHECK(sphericalTriangleSolidAngle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}) ==
          doctest::Approx(M_PI / 2).epsilon(1e-14));
    CHECK(sphericalTriangleSolidAngle({0, 0, 0}, {0, 0, 5}, {0, 3, 0}, {2, 0, 0}) ==
          doctest::Approx(M_PI / 2).epsilon(1e-14));
    // Half of the square [-1,1]^2 at height 1, whose solid angle is 4 asin(1/2) = 2 pi / 3.
    CHECK(sphericalTriangleSolidAngle({0, 0, 0}, {-1, -1, 1}, {1, -1, 1}, {1, 1, 1}) ==
          doctest::Approx(M_PI / 3).epsilon(1e-14));
    // Small and far: area A, tilted by theta from the line of sight at distance d:
    // A cos(theta) / d^2 to relative order (size / d)^2 = 1e-12.
    const double d = 1e5, theta = 0.6;
    const glm::dvec3 centre(0, 0, d), u(1, 0, 0), v(0, std::cos(theta), std::sin(theta));
    // A right triangle of area 1/2 spanned by u and v, its centroid at `centre`.
    const glm::dvec3 q0 = centre - u / 3.0 - v / 3.0, q1 = q0 + u, q2 = q0 + v;
    CHECK(sphericalTriangleSolidAngle({0, 0, 0}, q0, q1, q2) ==
          doctest::Approx(0.5 * std::cos(theta) / (d * d)).epsilon(1e-9));
    // On the triangle's own plane: 2 pi inside it (it fills the hemisphere), 0 outside it.
    CHECK(sphericalTriangleSolidAngle({0.2, 0.2, 0}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}) ==
          doctest::Approx(2 * M_PI).epsilon(1e-14));
    CHECK(sphericalTriangleSolidAngle({2, 2, 0}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}) == 0.0);
    CHECK(sphericalTriangleSolidAngle({0, 0, 0}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}) == 0.0);
}

TEST_CASE("spherical triangle: tiny, degenerate and too small triangles are refused") {
    // Below the caller's threshold.
    CHECK_FALSE(SphericalTriangle::make({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, 2.0));
    CHECK(SphericalTriangle::make({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, 1.5));
    // Tinier than the map can resolve, whatever the caller asks (1e-10 sr).
    CHECK_FALSE(SphericalTriangle::make({0, 0, 0}, {0, 0, 1}, {1e-5, 0, 1}, {0, 2e-5, 1}, 0.0));
    // Collinear vertices, a repeated vertex, the point on a vertex, the point on the plane
    // outside the triangle.
    CHECK_FALSE(SphericalTriangle::make({0, 0, 0}, {0, 0, 1}, {1, 0, 1}, {2, 0, 1}, 0.0));
    CHECK_FALSE(SphericalTriangle::make({0, 0, 0}, {0, 0, 1}, {0, 0, 1}, {1, 0, 1}, 0.0));
    CHECK_FALSE(SphericalTriangle::make({0, 0, 1}, {0, 0, 1}, {1, 0, 1}, {0, 1, 1}, 0.0));
    CHECK_FALSE(SphericalTriangle::make({2, 2, 0}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 0.0));
    // A point 1e-3 off the plane sees almost a hemisphere: still sampled.
    const auto close = SphericalTriangle::make({0.3, 0.3, 1e-3}, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 0.0);
    REQUIRE(close);
    CHECK(close->solidAngle() > 6.2);
}

TEST_CASE("spherical triangle: every sampled direction is unit and hits the triangle, corners too") {
    const float almostOne = std::nextafter(1.0f, 0.0f);
    for (const Configuration& c : kConfigurations) {
        INFO(std::string(c.name));
        const auto triangle = SphericalTriangle::make(c.point, c.p0, c.p1, c.p2, 0.0);
        REQUIRE(triangle);
        std::vector<glm::vec2> us = {{0, 0}, {0, almostOne}, {almostOne, 0}, {almostOne, almostOne},
                                     {0.5f, 1e-7f}, {1e-7f, 0.5f}};
        for (uint64_t k = 0; k < 20000; ++k) us.push_back(test::hashedPoint(k + 987654321));
        for (const glm::vec2 u : us) {
            const glm::dvec3 direction = triangle->sample(u);
            REQUIRE(std::abs(glm::length(direction) - 1.0) < 1e-12);
            const auto l = planeCoordinates(c, direction);
            REQUIRE(l);
            // Inside up to rounding: 1e-9 of the triangle's extent.
            INFO("u " << u.x << " " << u.y << ": l1 " << l->x << ", l2 " << l->y);
            CHECK(l->x >= -1e-9);
            CHECK(l->y >= -1e-9);
            CHECK(l->x + l->y <= 1.0 + 1e-9);
        }
    }
}

TEST_CASE("spherical triangle: directions are uniform by solid angle (chi-square over 64 sub-triangles)") {
    // The triangle split into n^2 sub-triangles by a barycentric grid; each one's expected share
    // is its own solid angle (Van Oosterom-Strackee, independent of the map) over the whole's.
    constexpr int n = 8;
    constexpr int kSamples = 200000;
    for (const Configuration& c : kConfigurations) {
        INFO(std::string(c.name));
        const auto triangle = SphericalTriangle::make(c.point, c.p0, c.p1, c.p2, 0.0);
        REQUIRE(triangle);
        const auto gridPoint = [&](int i, int j) {
            return c.p0 + (static_cast<double>(i) / n) * (c.p1 - c.p0) + (static_cast<double>(j) / n) * (c.p2 - c.p0);
        };
        // Cell (i, j, flipped): flipped = 0 the triangle at (i, j), 1 the one above its diagonal.
        std::vector<double> expected(2 * n * n, 0.0);
        double total = 0.0;
        for (int i = 0; i < n; ++i) {
            for (int j = 0; i + j < n; ++j) {
                expected[2 * (i * n + j)] = sphericalTriangleSolidAngle(c.point, gridPoint(i, j), gridPoint(i + 1, j), gridPoint(i, j + 1));
                if (i + j + 2 <= n) {
                    expected[2 * (i * n + j) + 1] = sphericalTriangleSolidAngle(
                        c.point, gridPoint(i + 1, j), gridPoint(i + 1, j + 1), gridPoint(i, j + 1));
                }
            }
        }
        for (double e : expected) total += e;
        CHECK(total == doctest::Approx(triangle->solidAngle()).epsilon(1e-9));
        std::vector<int> counts(expected.size(), 0);
        for (uint64_t k = 0; k < kSamples; ++k) {
            const auto l = planeCoordinates(c, triangle->sample(test::hashedPoint(k + 1000000 + 987654321)));
            REQUIRE(l);
            const double x = std::clamp(l->x, 0.0, 1.0) * n, y = std::clamp(l->y, 0.0, 1.0) * n;
            int i = std::min(n - 1, static_cast<int>(x)), j = std::min(n - 1 - i, static_cast<int>(y));
            const bool flipped = (x - i) + (y - j) > 1.0 && i + j + 2 <= n;
            ++counts[2 * (i * n + j) + (flipped ? 1 : 0)];
        }
        double chiSquare = 0.0;
        size_t cells = 0;
        for (size_t cell = 0; cell < counts.size(); ++cell) {
            if (expected[cell] == 0.0) {
                CHECK(counts[cell] == 0);
                continue;
            }
            const double e = kSamples * expected[cell] / total;
            chiSquare += (counts[cell] - e) * (counts[cell] - e) / e;
            ++cells;
        }
        CHECK(cells == n * n);
        MESSAGE(std::string(c.name) << ": chi-square " << chiSquare << " on " << cells - 1 << " degrees of freedom");
        CHECK(chiSquare < test::chiSquareCritical(cells - 1));
    }
}
