// The viewer's camera controller under synthetic ImGui input (no OpenGL needed).
#include <doctest/doctest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <imgui.h>

#include "app/viewer/headless_imgui.h"
#include "camera_controller.h"

using namespace strata;
using namespace strata::viewer;

namespace {

struct ImGuiFrames {
    test::HeadlessImGui context{ImVec2(640, 480)};
    // One frame of input through the controller.
    bool step(CameraController& camera) {
        ImGui::NewFrame();
        const bool changed = camera.update(ImGui::GetIO(), true, true);
        ImGui::EndFrame();
        return changed;
    }
};

CameraPose initialPose() {
    CameraPose pose;
    pose.position = {0.0f, 1.0f, 5.0f};
    pose.lookAt = {0.0f, 1.0f, 0.0f};
    pose.up = {0.0f, 1.0f, 0.0f};
    pose.fovYDegrees = 40.0f;
    return pose;
}

void checkSame(const glm::vec3& a, const glm::vec3& b) {
    for (int i = 0; i < 3; ++i) CHECK(a[i] == doctest::Approx(b[i]).epsilon(1e-5));
}

}  // namespace

TEST_CASE("camera controller starts at the scene's pose, orbits at constant distance, resets with R") {
    ImGuiFrames frames;
    CameraController camera(initialPose(), glm::vec3(-1.0f), glm::vec3(1.0f, 3.0f, 1.0f));
    checkSame(camera.pose().position, initialPose().position);
    checkSame(camera.pose().lookAt, initialPose().lookAt);

    ImGuiIO& io = ImGui::GetIO();
    io.MousePos = ImVec2(100, 100);
    frames.step(camera);
    io.MouseDown[0] = true;
    frames.step(camera);
    io.MousePos = ImVec2(180, 130);  // a left drag orbits about the target
    CHECK(frames.step(camera));
    io.MouseDown[0] = false;
    frames.step(camera);
    const CameraPose orbited = camera.pose();
    CHECK(glm::length(orbited.position - initialPose().position) > 0.1f);
    checkSame(orbited.lookAt, initialPose().lookAt);
    CHECK(glm::length(orbited.position - orbited.lookAt) == doctest::Approx(5.0f).epsilon(1e-5));

    io.MouseWheel = 2.0f;  // two notches in: 0.9^2 of the distance
    CHECK(frames.step(camera));
    io.MouseWheel = 0.0f;
    CHECK(glm::length(camera.pose().position - camera.pose().lookAt) == doctest::Approx(5.0f * 0.81f).epsilon(1e-5));

    io.KeysDown['R'] = true;
    CHECK(frames.step(camera));
    io.KeysDown['R'] = false;
    frames.step(camera);
    checkSame(camera.pose().position, initialPose().position);
    checkSame(camera.pose().lookAt, initialPose().lookAt);
}

TEST_CASE("camera controller frames the scene's bounds with F and flies with W") {
    ImGuiFrames frames;
    CameraController camera(initialPose(), glm::vec3(2.0f, 0.0f, -1.0f), glm::vec3(4.0f, 2.0f, 1.0f));
    ImGuiIO& io = ImGui::GetIO();
    io.KeysDown['F'] = true;
    CHECK(frames.step(camera));
    io.KeysDown['F'] = false;
    frames.step(camera);
    checkSame(camera.pose().lookAt, glm::vec3(3.0f, 1.0f, 0.0f));
    // The bounding sphere (radius sqrt(3)) fits the vertical field of view.
    const float distance = glm::length(camera.pose().position - camera.pose().lookAt);
    CHECK(distance == doctest::Approx(std::sqrt(3.0f) / std::sin(glm::radians(20.0f))).epsilon(1e-5));

    const glm::vec3 before = camera.pose().position;
    const glm::vec3 forward = glm::normalize(camera.pose().lookAt - before);
    io.KeysDown['W'] = true;  // forward, target and camera together
    CHECK(frames.step(camera));
    io.KeysDown['W'] = false;
    const glm::vec3 moved = camera.pose().position - before;
    CHECK(glm::dot(moved, forward) > 0.0f);
    CHECK(glm::length(glm::cross(moved, forward)) == doctest::Approx(0.0f).epsilon(1e-4));
}
