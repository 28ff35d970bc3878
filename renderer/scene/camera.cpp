#include "scene/camera.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "sampling/hemisphere.h"
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
    if (!(pose.apertureRadius >= 0.0f && std::isfinite(pose.apertureRadius))) {
        throw Error("aperture_radius must be a finite number >= 0");
    }
    if (!(pose.focusDistance >= 0.0f && std::isfinite(pose.focusDistance))) {
        throw Error("focus_distance must be a finite number >= 0");
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
    lensRight_ = glm::normalize(side);
    lensUp_ = glm::normalize(glm::cross(side, forward_));
    right_ = lensRight_ * halfWidth;
    upScaled_ = lensUp_ * halfHeight;
    focusDistance_ = pose.focusDistance > 0.0f ? pose.focusDistance : glm::length(view);
}

Ray Camera::generateRay(int x, int y, glm::vec2 jitter, glm::vec2 lens) const {
    const float ndcX = 2.0f * (static_cast<float>(x) + jitter.x) / static_cast<float>(width_) - 1.0f;
    const float ndcY = 1.0f - 2.0f * (static_cast<float>(y) + jitter.y) / static_cast<float>(height_);
    const glm::vec3 onPlane = ndcX * right_ + ndcY * upScaled_;
    const bool orthographic = pose_.orthographicHalfHeight > 0.0f;
    const Ray pinhole = orthographic ? Ray{pose_.position + onPlane, forward_}
                                     : Ray{pose_.position, glm::normalize(forward_ + onPlane)};
    if (!hasLens()) return pinhole;
    // The pinhole ray's point on the plane of focus, seen from a point of the aperture (pbrt-v4,
    // "Thin Lens Model and Depth of Field").
    const glm::vec3 focus = pinhole.origin + (focusDistance_ / glm::dot(pinhole.direction, forward_)) * pinhole.direction;
    const glm::vec2 disk = pose_.apertureRadius * sampleConcentricDisk(lens);
    const glm::vec3 origin = pinhole.origin + disk.x * lensRight_ + disk.y * lensUp_;
    return {origin, glm::normalize(focus - origin)};
}

}  // namespace strata
