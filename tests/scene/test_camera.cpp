#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <utility>
#include <glm/geometric.hpp>

#include "sampling/hemisphere.h"
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

TEST_CASE("camera: a thin lens sees each point of its focal plane at one image position, through its whole aperture") {
    CameraPose pose{{1, 2, 3}, {1, 2, 13}, {0, 1, 0}, 60.0f};
    pose.apertureRadius = 0.5f;
    pose.focusDistance = 7.0f;
    const Camera camera(pose, 64, 48);
    REQUIRE(camera.hasLens());
    CameraPose pinholePose = pose;
    pinholePose.apertureRadius = 0.0f;
    const Camera pinhole(pinholePose, 64, 48);
    CHECK_FALSE(pinhole.hasLens());
    for (const auto& [x, y] : {std::pair{0, 0}, std::pair{31, 20}, std::pair{63, 47}}) {
        const glm::vec2 jitter(0.3f, 0.8f);
        const Ray through = pinhole.generateRay(x, y, jitter);
        // The pinhole ray meets the focal plane z = 3 + 7 at this point.
        const glm::vec3 focus = through.origin + (7.0f / through.direction.z) * through.direction;
        // The lens's centre is the pinhole.
        const Ray centre = camera.generateRay(x, y, jitter, glm::vec2(0.5f));
        CHECK(glm::length(centre.origin - through.origin) < 1e-6f);
        CHECK(glm::length(centre.direction - through.direction) < 1e-6f);
        for (const glm::vec2 lens : {glm::vec2(0.0f), glm::vec2(0.99f, 0.2f), glm::vec2(0.1f, 0.9f)}) {
            const Ray ray = camera.generateRay(x, y, jitter, lens);
            // Leaves the aperture: on the lens plane z = 3, within its radius, where the concentric
            // map puts the lens point (x right, which is -x in the world looking down +z).
            CHECK(ray.origin.z == doctest::Approx(3.0f));
            const glm::vec2 disk = 0.5f * sampleConcentricDisk(lens);
            CHECK(ray.origin.x == doctest::Approx(1.0f - disk.x).epsilon(1e-5));
            CHECK(ray.origin.y == doctest::Approx(2.0f + disk.y).epsilon(1e-5));
            CHECK(glm::length(ray.direction) == doctest::Approx(1.0f));
            // Reaches the same point of the focal plane.
            const glm::vec3 hit = ray.origin + ((10.0f - ray.origin.z) / ray.direction.z) * ray.direction;
            CHECK(glm::length(hit - focus) < 1e-4f);
        }
    }
    // Focus distance 0 focuses on look_at's plane: through the centre pixel, look_at itself.
    pose.focusDistance = 0.0f;
    const Camera atLookAt(pose, 65, 65);
    const Ray corner = atLookAt.generateRay(32, 32, glm::vec2(0.5f), glm::vec2(0.0f));
    const glm::vec3 hit = corner.origin + ((13.0f - corner.origin.z) / corner.direction.z) * corner.direction;
    CHECK(glm::length(hit - glm::vec3(1, 2, 13)) < 1e-4f);
    // Negative or non-finite lenses are refused.
    pose.apertureRadius = -1.0f;
    CHECK_THROWS_AS(Camera(pose, 8, 8), Error);
    pose.apertureRadius = 0.1f;
    pose.focusDistance = std::numeric_limits<float>::infinity();
    CHECK_THROWS_AS(Camera(pose, 8, 8), Error);
}
