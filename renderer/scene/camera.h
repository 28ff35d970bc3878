#pragma once
// A pinhole camera and the scene's JSON sidecar (NAME.json beside NAME.obj):
//   {"position":[x,y,z], "look_at":[x,y,z], "up":[x,y,z], "fov_y":degrees, "width":W, "height":H,
//    "point_lights":[{"position":[x,y,z], "intensity":[r,g,b]}]}     (point_lights optional)
// Unknown keys are ignored so that later versions can add their own.
#include <filesystem>
#include <string>
#include <vector>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "scene/mesh.h"
#include "geometry/ray.h"

namespace strata {

struct CameraPose {
    glm::vec3 position{0.0f};
    glm::vec3 lookAt{0.0f, 0.0f, -1.0f};
    glm::vec3 up{0.0f, 1.0f, 0.0f};
    float fovYDegrees = 45.0f;
};

struct SceneSettings {
    CameraPose pose;
    int width = 256;
    int height = 256;
    std::vector<PointLight> pointLights;
};

// Reads and validates a scene's JSON sidecar; throws strata::Error naming the file (and line for
// syntax errors, the key for a bad value).
SceneSettings loadSceneSettings(const std::filesystem::path& path);
// The same from memory: `name` stands for the file in messages. loadSceneSettings reads the file
// and calls this, so the loader fuzzer exercises the one code path.
SceneSettings parseSceneSettings(const std::string& text, const std::string& name);

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
    glm::vec3 right_;  // scaled by the half-width of the image plane at distance 1
    glm::vec3 upScaled_;  // scaled by the half-height
};

}  // namespace strata
