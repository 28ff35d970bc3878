#pragma once
// A scene as users give it: NAME.obj (+ its MTL) and the camera sidecar NAME.json beside it.
#include <filesystem>
#include <optional>
#include <string>

#include "scene/camera.h"
#include "scene/obj_loader.h"
#include "scene/scene.h"

namespace strata {

struct LoadedScene {
    Scene scene;
    SceneSettings settings;
    ObjLoadReport report;
    std::filesystem::path objPath;
    std::filesystem::path cameraPath;  // empty when the camera was framed automatically
};

// A scene's files as text, read once (on MPI rank 0) and parsed from memory on every rank, so all
// render the same bytes.
struct SceneFiles {
    ObjFiles obj;
    std::string cameraText;
    std::filesystem::path objPath;
    std::filesystem::path cameraPath;  // empty: no camera file, the camera frames the scene
};

// Reads the OBJ, its MTL files and the camera file that loadScene would use; throws
// strata::Error naming a missing or malformed file.
SceneFiles readSceneFiles(const std::filesystem::path& objPath,
                          const std::optional<std::filesystem::path>& cameraPath = std::nullopt);
// Builds the scene from files read by readSceneFiles; throws strata::Error naming the bad file.
LoadedScene parseScene(const SceneFiles& files);

// Loads the OBJ and the camera: `cameraPath` when given, else NAME.json beside the OBJ when it
// exists, else a camera framing the scene's bounds. Throws strata::Error naming the bad file.
// readSceneFiles then parseScene.
LoadedScene loadScene(const std::filesystem::path& objPath,
                      const std::optional<std::filesystem::path>& cameraPath = std::nullopt);

// One line for the log: triangles, dropped, emitters, emitting area, max albedo.
std::string describeScene(const LoadedScene& loaded);

}  // namespace strata
