#pragma once
// A pinhole or orthographic camera, and the settings that make one: its pose and image size (from
// the scene description or a --camera file, scene_description.h, a glTF file's camera, or the
// default camera, default_camera.h).
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "geometry/ray.h"

namespace strata {

struct CameraPose {
    glm::vec3 position{0.0f};
    glm::vec3 lookAt{0.0f, 0.0f, -1.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    float fovYDegrees = 45.0f;
    // > 0: an orthographic camera (glTF's "orthographic" type) that sees this half-height, in
    // scene units, about its view axis, its rays parallel from the plane through `position`;
    // fovYDegrees is then unused. 0: a pinhole.
    float orthographicHalfHeight = 0.0f;
};

struct CameraSettings {
    CameraPose pose;
    int width = 256;
    int height = 256;
};

class Camera {
public:
    // Throws strata::Error for a degenerate pose (look_at == position, up parallel to the view
    // direction, fov outside (0, 180)) or a non-positive image size.
    Camera(const CameraPose& pose, int width, int height);

    // The ray through image position (x + jitter.x, y + jitter.y); y = 0 is the top row.
    Ray generateRay(int x, int y, glm::vec2 jitter) const;

    int width() const { return width_; }
    int height() const { return height_; }
    const CameraPose& pose() const { return pose_; }

private:
    CameraPose pose_;
    int width_;
    int height_;
    glm::vec3 forward_;
    glm::vec3 right_;  // scaled by the half-width of the image plane (at distance 1 for a pinhole)
    glm::vec3 upScaled_;  // scaled by the half-height
};

}  // namespace strata
