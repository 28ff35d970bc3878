#include "scene/camera.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "util/error.h"

namespace strata {

Camera::Camera(const CameraPose& pose, int width, int height)
    : pose_(pose), width_(width), height_(height) {
    if (width < 1 || height < 1) throw Error("image size must be at least 1x1");
    const bool orthographic = pose.orthographicHalfHeight > 0.0f;
    if (!orthographic && !(pose.fovYDegrees > 0.0f && pose.fovYDegrees < 180.0f)) {
        throw Error("fov_y must be in (0, 180) degrees");
    }
    if (!(pose.orthographicHalfHeight >= 0.0f && std::isfinite(pose.orthographicHalfHeight))) {
        throw Error("an orthographic camera's half-height must be a finite number > 0");
    }
    const glm::vec3 view = pose.lookAt - pose.position;
    if (!(glm::length(view) > 0.0f)) throw Error("look_at must differ from position");
    forward_ = glm::normalize(view);
    const glm::vec3 side = glm::cross(forward_, pose.up);
    if (!(glm::length(side) > 1e-6f * glm::length(pose.up))) {
        throw Error("up must not be parallel to the view direction");
    }
    // The image plane's half-height: at distance 1 for a pinhole, the view's own for an
    // orthographic camera.
    const float halfHeight =
        orthographic ? pose.orthographicHalfHeight : std::tan(glm::radians(pose.fovYDegrees) * 0.5f);
    const float halfWidth = halfHeight * static_cast<float>(width) / static_cast<float>(height);
    right_ = glm::normalize(side) * halfWidth;
    upScaled_ = glm::normalize(glm::cross(side, forward_)) * halfHeight;
}

Ray Camera::generateRay(int x, int y, glm::vec2 jitter) const {
    const float ndcX = 2.0f * (static_cast<float>(x) + jitter.x) / static_cast<float>(width_) - 1.0f;
    const float ndcY = 1.0f - 2.0f * (static_cast<float>(y) + jitter.y) / static_cast<float>(height_);
    const glm::vec3 onPlane = ndcX * right_ + ndcY * upScaled_;
    if (pose_.orthographicHalfHeight > 0.0f) return {pose_.position + onPlane, forward_};
    return {pose_.position, glm::normalize(forward_ + onPlane)};
}

}  // namespace strata
