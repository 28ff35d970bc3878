// The curved surface of a triangle's vertex normals (geometry/smooth_surface.h): exact lifts on a
// triangle inscribed in the unit sphere with radial normals, none on a flat triangle or on the
// side the normals turn away from, and the share of it a shadow ray takes.
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <glm/geometric.hpp>

#include "geometry/smooth_surface.h"

using namespace strata;

namespace {

// Three points on the unit sphere at polar angle `theta`, 120 degrees apart about +z: their
// centroid is (0, 0, cos theta), and their radial normals are the points themselves.
std::array<glm::vec3, 3> capTriangle(float theta) {
    std::array<glm::vec3, 3> corners;
    for (int i = 0; i < 3; ++i) {
        const float phi = 2.0943951f * static_cast<float>(i);
        corners[i] = {std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta)};
    }
    return corners;
}

const glm::vec3 kCentroid(1.0f / 3.0f);

}  // namespace

TEST_CASE("smooth surface: the centroid of a triangle in the unit sphere is lifted to c (2 - c^2), nearer the sphere") {
    for (float theta : {0.1f, 0.4f, 0.8f}) {
        const auto corners = capTriangle(theta);
        const glm::vec3 lift = smoothSurfaceLift(corners, corners, kCentroid);
        // Each vertex's tangent plane: dot(p - p_i, p_i) = c^2 - 1 below it, so the lift is
        // (1 - c^2) times the mean normal (0, 0, c).
        const double c = std::cos(theta);
        CHECK(lift.x == doctest::Approx(0.0).epsilon(1e-6).scale(1.0));
        CHECK(lift.y == doctest::Approx(0.0).epsilon(1e-6).scale(1.0));
        CHECK(lift.z == doctest::Approx(c * (1.0 - c * c)).epsilon(1e-5));
        // Nearer the sphere than the facet's centroid, c^2 + c - 1 times as far (past it, as the
        // tangent planes lie outside it).
        const double lifted = c + lift.z;
        CHECK(lifted - 1.0 == doctest::Approx((1.0 - c) * (c * c + c - 1.0)).epsilon(1e-4));
        CHECK(std::abs(lifted - 1.0) < 1.0 - c);
        // Normals of any length describe the same planes.
        const std::array<glm::vec3, 3> longer{3.0f * corners[0], 0.5f * corners[1], 2.0f * corners[2]};
        const glm::vec3 same = smoothSurfaceLift(corners, longer, kCentroid);
        CHECK(glm::length(same - lift) < 1e-6f);
    }
}

TEST_CASE("smooth surface: no lift at a vertex, on a flat triangle, or on the side the normals leave") {
    const auto corners = capTriangle(0.5f);
    CHECK(smoothSurfaceLift(corners, corners, glm::vec3(1.0f, 0.0f, 0.0f)) == glm::vec3(0.0f));
    // Normals that agree with the face's: the surface is the triangle.
    const glm::vec3 face = glm::normalize(glm::cross(corners[1] - corners[0], corners[2] - corners[0]));
    CHECK(glm::length(smoothSurfaceLift(corners, {face, face, face}, kCentroid)) < 1e-6f);
    // Seen from inside the sphere, the tangent planes lie behind the point: nothing to lift.
    CHECK(smoothSurfaceLift(corners, {-corners[0], -corners[1], -corners[2]}, kCentroid) == glm::vec3(0.0f));
    // A zero normal describes no plane.
    CHECK(smoothSurfaceLift(corners, {glm::vec3(0.0f), glm::vec3(0.0f), glm::vec3(0.0f)}, kCentroid) ==
          glm::vec3(0.0f));
}

TEST_CASE("smooth surface: a shadow ray takes all of the lift below the facet's plane, none from the cutoff up") {
    CHECK(terminatorLiftShare(-0.5f, 0.1f) == 1.0f);
    CHECK(terminatorLiftShare(0.0f, 0.1f) == 1.0f);
    CHECK(terminatorLiftShare(0.05f, 0.1f) == doctest::Approx(0.5f));
    CHECK(terminatorLiftShare(0.1f, 0.1f) == 0.0f);
    CHECK(terminatorLiftShare(0.7f, 0.1f) == 0.0f);
    // Off.
    CHECK(terminatorLiftShare(-0.5f, 0.0f) == 0.0f);
}
