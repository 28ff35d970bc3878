#pragma once
// A scene as users give it: NAME.obj (+ its MTL) and the camera sidecar NAME.json beside it.
#include <filesystem>
#include <optional>
#include <string>

#include "camera.h"
#include "obj_loader.h"
#include "scene.h"

namespace strata {

struct LoadedScene {
    Scene scene;
    SceneSettings settings;
    ObjLoadReport report;
    std::filesystem::path objPath;
    std::filesystem::path cameraPath;  // empty when the camera was framed automatically
};

// Loads the OBJ and the camera: `cameraPath` when given, else NAME.json beside the OBJ when it
// exists, else a camera framing the scene's bounds. Throws strata::Error naming the bad file.
LoadedScene loadScene(const std::filesystem::path& objPath,
                      const std::optional<std::filesystem::path>& cameraPath = std::nullopt);

// One line for the log: triangles, dropped, emitters, emitting area, max albedo.
std::string describeScene(const LoadedScene& loaded);

}  // namespace strata
