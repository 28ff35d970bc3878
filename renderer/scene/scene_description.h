#pragma once
// The scene description: NAME.json beside the scene file NAME.EXT (of any format), with what the
// scene's geometry does not say. Every key is optional; unknown keys are ignored so that later
// versions can add their own.
//   camera: "position", "look_at", "up": [x,y,z], "fov_y": degrees (all four, or none: the
//           default camera, default_camera.h), "width", "height": the image size in pixels (default 256)
//   "lights": [{"type": "point", "position": [x,y,z], "intensity": [r,g,b]}]   intensity in W/sr
//   "point_lights": [{"position": [x,y,z], "intensity": [r,g,b]}]   point lights, the older key
//   "environment": what rays that leave the scene see (lights/environment.h): "none",
//           {"color": [r,g,b]} a uniform radiance, or {"file": "sky.exr", "rotate": degrees} a
//           latitude-longitude map, its path relative to the description; --env options override it
// A --camera file has the camera keys, all required, and may have "point_lights"; its "lights"
// are not read: with --camera the lights are still the scene's.
#include <string>
#include <vector>

#include "lights/environment.h"
#include "scene/camera.h"
#include "scene/mesh.h"

namespace strata {

struct SceneDescription {
    CameraSettings camera;  // the image size, and the pose when hasPose
    bool hasPose = false;
    std::vector<PointLight> pointLights;
    std::vector<SpotLight> spotLights;
    // Kind Default without the key. A map's image is not read here: its file, one of `files`, is
    // environmentFile, which parseScene decodes from the bundle.
    Environment environment;
    std::string environmentFile;
    // Files its entries refer to, relative to its folder: the scene's bundle carries them beside
    // the scene's own files (scene_format.h), so that every rank parses the same bytes.
    std::vector<std::string> files;
};

// Parses and validates a scene description; `name` stands for the file in messages. Throws
// strata::Error naming it (and the line for syntax errors, the key or light type for a bad value).
SceneDescription parseSceneDescription(const std::string& text, const std::string& name);

// The same for a --camera file: hasPose is always set, the lights are its "point_lights".
SceneDescription parseCameraFile(const std::string& text, const std::string& name);

}  // namespace strata
