#pragma once
// Interactive camera: orbit (left drag), pan (middle drag or shift+left), dolly (wheel), fly (right
// drag to look, W/A/S/D/Q/E to move), frame the scene (F), reset (R). It reads Dear ImGui's input
// state, so the same code runs under GLFW and under synthetic input offscreen. Keys are GLFW key
// codes (ASCII for letters), the indices the ImGui GLFW backend fills io.KeysDown with.
#include <glm/vec3.hpp>

#include "scene/camera.h"

struct ImGuiIO;

namespace strata::viewer {

class CameraController {
public:
    CameraController(const CameraPose& initial, const glm::vec3& boundsMin, const glm::vec3& boundsMax);

    // Applies this frame's input; `mouse` / `keyboard` false when ImGui wants them. Returns
    // whether the pose changed.
    bool update(const ImGuiIO& io, bool mouse, bool keyboard);
    void frameScene();
    void reset();
    CameraPose pose() const;

private:
    void orbit(float dx, float dy);
    void pan(float dx, float dy);
    void dolly(float wheel);
    void look(float dx, float dy);
    void move(const glm::vec3& local, float seconds);
    glm::vec3 viewDirection() const;  // unit, from the camera to the target

    CameraPose initial_;
    glm::vec3 boundsMin_;
    glm::vec3 boundsMax_;
    glm::vec3 worldUp_;
    glm::vec3 target_;
    float distance_;
    float yaw_;    // radians about worldUp_
    float pitch_;  // radians above the plane normal to worldUp_
};

}  // namespace strata::viewer
