#pragma once
// A pinhole or orthographic camera, with a thin lens or without, and the settings that make one:
// its pose and image size (from the scene description or a --camera file, scene_description.h, a
// glTF file's camera, or the default camera, default_camera.h).
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
    // A thin lens (as pbrt's cameras have): the radius of its aperture in scene units (0: a
    // pinhole, everything sharp), and the distance along the view axis of the plane it focuses
    // on (0: the plane through look_at). A point on that plane is seen through every point of
    // the aperture at one place in the image; a point off it is spread over a disk.
    float apertureRadius = 0.0f;
    float focusDistance = 0.0f;

    bool operator==(const CameraPose&) const = default;
};

struct CameraSettings {
    CameraPose pose;
    int width = 256;
    int height = 256;
};

class Camera {
public:
    // Throws strata::Error for a degenerate pose (look_at == position, up parallel to the view
    // direction, fov outside (0, 180), a negative or non-finite aperture or focus distance) or a
    // non-positive image size.
    Camera(const CameraPose& pose, int width, int height);

    // The ray through image position (x + jitter.x, y + jitter.y), y = 0 the top row, leaving
    // the lens at the point that `lens` in [0,1)^2 maps to (area-preserving; (0.5, 0.5) is the
    // lens's centre, which a pinhole's every ray leaves).
    Ray generateRay(int x, int y, glm::vec2 jitter, glm::vec2 lens = glm::vec2(0.5f)) const;
    bool hasLens() const { return pose_.apertureRadius > 0.0f; }

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
    // The lens's axes in the image's directions, unit length, and its focus along forward_.
    glm::vec3 lensRight_;
    glm::vec3 lensUp_;
    float focusDistance_;
};

}  // namespace strata
