#include <doctest/doctest.h>

#include <cmath>
#include <glm/geometric.hpp>

#include "scene/camera.h"
#include "util/error.h"

using namespace strata;

TEST_CASE("camera: the centre ray looks at look_at and corners span fov_y") {
    const CameraPose pose{{1, 2, 3}, {1, 2, 13}, {0, 1, 0}, 90.0f};
    const Camera camera(pose, 100, 100);
    const Ray centre = camera.generateRay(50, 50, {0.0f, 0.0f});
    CHECK(centre.direction.z == doctest::Approx(1.0));
    const Ray top = camera.generateRay(50, 0, {0.0f, 0.0f});
    // fov 90: the top edge is 45 degrees up.
    CHECK(std::acos(glm::dot(top.direction, glm::vec3(0, 0, 1))) == doctest::Approx(M_PI / 4).epsilon(1e-5));
    CHECK(top.direction.y > 0.0f);
}

TEST_CASE("camera: degenerate poses are refused") {
    CHECK_THROWS_AS(Camera(CameraPose{{0, 0, 0}, {0, 0, 0}, {0, 1, 0}, 45.0f}, 8, 8), Error);
    CHECK_THROWS_AS(Camera(CameraPose{{0, 0, 0}, {0, 1, 0}, {0, 1, 0}, 45.0f}, 8, 8), Error);
    CHECK_THROWS_AS(Camera(CameraPose{{0, 0, 0}, {0, 0, 1}, {0, 1, 0}, 180.0f}, 8, 8), Error);
    CHECK_THROWS_AS(Camera(CameraPose{{0, 0, 0}, {0, 0, 1}, {0, 1, 0}, 45.0f}, 0, 8), Error);
}

TEST_CASE("camera: an orthographic camera's rays are parallel, from the plane it sees, half-height as given") {
    CameraPose pose{{1, 2, 3}, {1, 2, 13}, {0, 1, 0}, 45.0f};
    pose.orthographicHalfHeight = 2.0f;
    const Camera camera(pose, 200, 100);
    const Ray centre = camera.generateRay(100, 50, {0.0f, 0.0f});
    CHECK(centre.origin == glm::vec3(1, 2, 3));
    CHECK(centre.direction == glm::vec3(0, 0, 1));
    // The top-left corner: 2 up and, at aspect 2, 4 to the left (+x, looking down +z with +y up).
    const Ray corner = camera.generateRay(0, 0, {0.0f, 0.0f});
    CHECK(corner.direction == glm::vec3(0, 0, 1));
    CHECK(corner.origin.x == doctest::Approx(5.0f));
    CHECK(corner.origin.y == doctest::Approx(4.0f));
    CHECK(corner.origin.z == doctest::Approx(3.0f));
    pose.orthographicHalfHeight = -1.0f;
    CHECK_THROWS_AS(Camera(pose, 8, 8), Error);
}
