// The default camera (default_camera.h): a three-quarter view of the whole bounding sphere with the
// model's up, and a flat model head-on from its face side.
#include <doctest/doctest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "scene/camera.h"
#include "scene/default_camera.h"
#include "test_support.h"

using namespace strata;

namespace {

// The unit cube [0,1]^3, faces outward.
MeshData cube() {
    MeshData mesh;
    mesh.materials.resize(1);
    test::addQuad(mesh, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}, 0);  // +z
    test::addQuad(mesh, {1, 0, 0}, {0, 0, 0}, {0, 1, 0}, {1, 1, 0}, 0);  // -z
    test::addQuad(mesh, {1, 0, 1}, {1, 0, 0}, {1, 1, 0}, {1, 1, 1}, 0);  // +x
    test::addQuad(mesh, {0, 0, 0}, {0, 0, 1}, {0, 1, 1}, {0, 1, 0}, 0);  // -x
    test::addQuad(mesh, {0, 1, 1}, {1, 1, 1}, {1, 1, 0}, {0, 1, 0}, 0);  // +y
    test::addQuad(mesh, {0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}, 0);  // -y
    return mesh;
}

// A flat square of side 2 about `centre` in the plane normal to axis `axis`, counter-clockwise
// seen from +axis when `towardPlus`.
void addSquare(MeshData& mesh, const glm::vec3& centre, int axis, bool towardPlus) {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    glm::vec3 corners[4];
    const float us[4] = {-1, 1, 1, -1}, vs[4] = {-1, -1, 1, 1};
    for (int i = 0; i < 4; ++i) {
        corners[i] = centre;
        corners[i][u] += us[i];
        corners[i][v] += vs[i];
    }
    if (towardPlus) {
        test::addQuad(mesh, corners[0], corners[1], corners[2], corners[3], 0);
    } else {
        test::addQuad(mesh, corners[0], corners[3], corners[2], corners[1], 0);
    }
}

MeshData square(int axis, bool towardPlus) {
    MeshData mesh;
    mesh.materials.resize(1);
    addSquare(mesh, glm::vec3(2.0f, 3.0f, 4.0f), axis, towardPlus);
    return mesh;
}

glm::vec3 toCamera(const CameraPose& pose) { return glm::normalize(pose.position - pose.lookAt); }


}  // namespace

TEST_CASE("default camera: a three-quarter view of the bounding sphere's centre, all of it in frame") {
    const MeshData mesh = cube();
    const CameraPose pose = defaultCameraPose(mesh, kGltfOrientation);
    test::checkNear(pose.lookAt, glm::vec3(0.5f));
    test::checkNear(pose.up, glm::vec3(0, 1, 0));
    CHECK(pose.fovYDegrees == kDefaultFovYDegrees);
    // 25 degrees above, 40 degrees from the front (+z) toward the side (+x).
    const glm::vec3 d = toCamera(pose);
    CHECK(glm::degrees(std::asin(d.y)) == doctest::Approx(kElevationDegrees).epsilon(1e-5));
    CHECK(glm::degrees(std::atan2(d.x, d.z)) == doctest::Approx(kAzimuthDegrees).epsilon(1e-5));
    // The sphere (radius sqrt(3)/2) fills the vertical field of view exactly.
    const float distance = glm::length(pose.position - pose.lookAt);
    CHECK(std::asin(std::sqrt(3.0f) / 2.0f / distance) ==
          doctest::Approx(glm::radians(kDefaultFovYDegrees) / 2.0f).epsilon(1e-5));
    // Every corner of the box projects inside the image, and the camera sees three faces.
    const Camera camera(pose, 64, 64);
    const glm::vec3 forward = -d;
    const float halfTan = std::tan(glm::radians(kDefaultFovYDegrees) / 2.0f);
    const glm::vec3 right = glm::normalize(glm::cross(forward, pose.up));
    const glm::vec3 up = glm::cross(right, forward);
    for (int corner = 0; corner < 8; ++corner) {
        const glm::vec3 p(corner & 1, (corner >> 1) & 1, (corner >> 2) & 1);
        const glm::vec3 v = p - pose.position;
        CHECK(std::abs(glm::dot(v, right) / glm::dot(v, forward)) < halfTan);
        CHECK(std::abs(glm::dot(v, up) / glm::dot(v, forward)) < halfTan);
    }
    CHECK(d.x > 0.0f);
    CHECK(d.y > 0.0f);
    CHECK(d.z > 0.0f);
}

TEST_CASE("default camera: a Z-up model is seen with +z up from its front, -y") {
    MeshData mesh = cube();
    const ModelOrientation zUp{{0, 0, 1}, {0, -1, 0}};
    const CameraPose pose = defaultCameraPose(mesh, zUp);
    test::checkNear(pose.up, glm::vec3(0, 0, 1));
    const glm::vec3 d = toCamera(pose);
    CHECK(glm::degrees(std::asin(d.z)) == doctest::Approx(kElevationDegrees).epsilon(1e-5));
    // The side is up x front = +x, as Blender's default camera stands (+x, -y, above).
    CHECK(glm::degrees(std::atan2(d.x, -d.y)) == doctest::Approx(kAzimuthDegrees).epsilon(1e-5));
}

TEST_CASE("default camera: a flat model is seen head-on from its face side") {
    for (int axis = 0; axis < 3; ++axis) {
        for (bool towardPlus : {true, false}) {
            CAPTURE(axis);
            CAPTURE(towardPlus);
            const CameraPose pose = defaultCameraPose(square(axis, towardPlus), kGltfOrientation);
            glm::vec3 normal(0.0f);
            normal[axis] = towardPlus ? 1.0f : -1.0f;
            test::checkNear(toCamera(pose), normal);
            test::checkNear(pose.lookAt, glm::vec3(2.0f, 3.0f, 4.0f));
            CHECK(std::abs(glm::dot(pose.up, normal)) < 1e-6f);
            // Upright where the plane stands (its up the model's, +y); a plan seen from above or
            // below has the model's back (-z) up.
            test::checkNear(pose.up, axis == 1 ? glm::vec3(0, 0, -1) : glm::vec3(0, 1, 0));
            CHECK_NOTHROW(Camera(pose, 8, 8));
        }
    }
}

TEST_CASE("default camera: a flat model whose faces cancel is seen from the three-quarter view's side") {
    // The square x = 2 twice, once facing each way: the three-quarter view is on the +x side.
    MeshData mesh = square(0, true);
    addSquare(mesh, glm::vec3(2.0f, 3.0f, 4.0f), 0, false);
    test::checkNear(toCamera(defaultCameraPose(mesh, kGltfOrientation)), glm::vec3(1, 0, 0));
    // Within 1% of the radius of one plane is flat; farther is not.
    MeshData nearlyFlat = square(0, false);
    nearlyFlat.positions[0].x += 0.01f;
    CHECK(toCamera(defaultCameraPose(nearlyFlat, kGltfOrientation)).x < -0.999f);
    MeshData bent = square(0, false);
    bent.positions[0].x += 0.05f;
    CHECK(toCamera(defaultCameraPose(bent, kGltfOrientation)).y > 0.4f);  // the three-quarter view
}
