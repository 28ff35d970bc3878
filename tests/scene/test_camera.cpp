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
