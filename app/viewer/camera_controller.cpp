#include "camera_controller.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <imgui.h>

namespace strata::viewer {
namespace {
constexpr float kRadiansPerPixel = 0.005f;
constexpr float kPitchLimit = 1.55f;       // just short of straight up/down, where up is degenerate
constexpr float kDollyPerNotch = 0.9f;     // distance factor per wheel notch
constexpr float kFlySpeedPerSecond = 0.5f; // scene diagonals per second
// GLFW key codes (letters are their ASCII capitals).
constexpr int kKeyW = 'W', kKeyA = 'A', kKeyS = 'S', kKeyD = 'D', kKeyQ = 'Q', kKeyE = 'E';
constexpr int kKeyF = 'F', kKeyR = 'R';

// An orthonormal basis with `up` as its second axis: (a, up, b).
void basis(const glm::vec3& up, glm::vec3& a, glm::vec3& b) {
    const glm::vec3 helper = std::abs(up.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 0, 1);
    a = glm::normalize(glm::cross(up, helper));
    b = glm::cross(a, up);
}
}  // namespace

CameraController::CameraController(const CameraPose& initial, const glm::vec3& boundsMin,
                                   const glm::vec3& boundsMax)
    : initial_(initial), boundsMin_(boundsMin), boundsMax_(boundsMax) {
    reset();
}

void CameraController::reset() {
    worldUp_ = glm::normalize(initial_.up);
    target_ = initial_.lookAt;
    const glm::vec3 offset = initial_.position - initial_.lookAt;  // from target to camera
    distance_ = glm::length(offset);
    glm::vec3 a, b;
    basis(worldUp_, a, b);
    const glm::vec3 toTarget = -offset / distance_;
    pitch_ = std::asin(std::clamp(glm::dot(toTarget, worldUp_), -1.0f, 1.0f));
    yaw_ = std::atan2(glm::dot(toTarget, b), glm::dot(toTarget, a));
}

glm::vec3 CameraController::viewDirection() const {
    glm::vec3 a, b;
    basis(worldUp_, a, b);
    return std::cos(pitch_) * (std::cos(yaw_) * a + std::sin(yaw_) * b) + std::sin(pitch_) * worldUp_;
}

CameraPose CameraController::pose() const {
    CameraPose pose = initial_;
    pose.lookAt = target_;
    pose.position = target_ - distance_ * viewDirection();
    pose.up = worldUp_;
    return pose;
}

void CameraController::frameScene() {
    const glm::vec3 centre = 0.5f * (boundsMin_ + boundsMax_);
    const float radius = std::max(0.5f * glm::length(boundsMax_ - boundsMin_), 1e-3f);
    target_ = centre;
    distance_ = radius / std::sin(glm::radians(0.5f * initial_.fovYDegrees));
}

void CameraController::orbit(float dx, float dy) {
    yaw_ += dx * kRadiansPerPixel;
    pitch_ = std::clamp(pitch_ + dy * kRadiansPerPixel, -kPitchLimit, kPitchLimit);
}

void CameraController::look(float dx, float dy) {
    // Turn the view about the camera's position: the target moves, the camera stays.
    const glm::vec3 position = target_ - distance_ * viewDirection();
    yaw_ += dx * kRadiansPerPixel;
    pitch_ = std::clamp(pitch_ - dy * kRadiansPerPixel, -kPitchLimit, kPitchLimit);
    target_ = position + distance_ * viewDirection();
}

void CameraController::pan(float dx, float dy) {
    const glm::vec3 forward = viewDirection();
    const glm::vec3 right = glm::normalize(glm::cross(forward, worldUp_));
    const glm::vec3 up = glm::cross(right, forward);
    const float scale = distance_ * 0.0015f;
    target_ += (-dx * right + dy * up) * scale;
}

void CameraController::dolly(float wheel) {
    distance_ = std::max(distance_ * std::pow(kDollyPerNotch, wheel), 1e-4f);
}

void CameraController::move(const glm::vec3& local, float seconds) {
    const glm::vec3 forward = viewDirection();
    const glm::vec3 right = glm::normalize(glm::cross(forward, worldUp_));
    const float speed = kFlySpeedPerSecond * glm::length(boundsMax_ - boundsMin_) * seconds;
    target_ += (local.x * right + local.y * worldUp_ + local.z * forward) * speed;
}

bool CameraController::update(const ImGuiIO& io, bool mouse, bool keyboard) {
    bool changed = false;
    if (mouse) {
        const float dx = io.MouseDelta.x;
        const float dy = io.MouseDelta.y;
        const bool moved = dx != 0.0f || dy != 0.0f;
        if (moved && (io.MouseDown[2] || (io.MouseDown[0] && io.KeyShift))) {
            pan(dx, dy);
            changed = true;
        } else if (moved && io.MouseDown[0]) {
            orbit(-dx, -dy);
            changed = true;
        } else if (moved && io.MouseDown[1]) {
            look(-dx, dy);
            changed = true;
        }
        if (io.MouseWheel != 0.0f) {
            dolly(io.MouseWheel);
            changed = true;
        }
    }
    if (keyboard) {
        const glm::vec3 direction((io.KeysDown[kKeyD] ? 1.0f : 0.0f) - (io.KeysDown[kKeyA] ? 1.0f : 0.0f),
                                  (io.KeysDown[kKeyE] ? 1.0f : 0.0f) - (io.KeysDown[kKeyQ] ? 1.0f : 0.0f),
                                  (io.KeysDown[kKeyW] ? 1.0f : 0.0f) - (io.KeysDown[kKeyS] ? 1.0f : 0.0f));
        if (direction != glm::vec3(0.0f)) {
            move(direction, io.DeltaTime);
            changed = true;
        }
        if (ImGui::IsKeyPressed(kKeyF, false)) {
            frameScene();
            changed = true;
        }
        if (ImGui::IsKeyPressed(kKeyR, false)) {
            reset();
            changed = true;
        }
    }
    return changed;
}

}  // namespace strata::viewer
