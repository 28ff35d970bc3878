#pragma once
// A scene as users give it: a scene file of a registered format (scene_format.h), the files it
// refers to, and the scene description NAME.json beside it (scene_description.h).
#include <filesystem>
#include <functional>
#include <optional>
#include <string>

#include "scene/camera.h"
#include "scene/scene.h"
#include "scene/scene_format.h"

namespace strata {

struct LoadedScene {
    Scene scene;
    CameraSettings settings;
    LoadReport report;
    SceneBundle bundle;  // the files it was parsed from

    const std::filesystem::path& scenePath() const { return bundle.path; }
};

// Reads the scene's files: the scene file `path` and those it refers to, the scene description
// NAME.json beside it when there is one (and the files it refers to), and the camera file when
// given; the files the scene refers to (the description among them) only inside the scene file's
// folder unless `options` allow others (scene_folder.h). Throws strata::Error naming a missing or
// malformed file or a refused reference; for a folder, "PATH: is a folder, ...", for a scene file
// that is not there (or not a regular file), "PATH: no such scene file", else for an extension no
// format has,
// "PATH: unknown scene format '.EXT' (known: ...)", before any file is read.
SceneBundle readSceneBundle(const std::filesystem::path& path,
                            const std::optional<std::filesystem::path>& cameraPath = std::nullopt,
                            const SceneReadOptions& options = {});

// What parseScene builds the scene from, all of parsing without building the scene's
// acceleration structure (the loader fuzzer runs this): the mesh with the lights of the
// description and of the camera file's "point_lights" and the description's environment, the
// camera settings of the camera file, else the description (`posed` when they give the pose), the
// scene file's own camera, and the load report. Throws strata::Error naming the bad file, or the
// budget the scene exceeds (scene_format.h), before its geometry is read.
struct SceneContents {
    ParsedScene parsed;
    CameraSettings settings;
    bool posed = false;
    LoadReport report;
};
SceneContents parseSceneContents(const SceneBundle& bundle, const SceneBudget& budget = {});

// The two stages of parseScene, for a progress line: the format's parse (with the description
// and camera files), then the Scene itself (its lights and Embree's BVH build).
enum class ParseStage { Parsing, Building };

// Builds the scene from its files (from readSceneBundle, here or on another MPI rank): the mesh
// by the main file's format, the point lights of the description and of the camera file's
// "point_lights", the camera from the camera file, else the description, else the scene file's
// own (glTF), else the default camera (default_camera.h); `traversal` picks Embree's triangle test
// (traversal_precision.h); the textures and the description's environment map are decoded
// within `budget`. Throws as parseSceneContents does: strata::Error naming the bad file, or the
// budget the scene exceeds (scene_format.h): its triangles before its geometry is read, the
// texture or map that would go over it before that is decoded. `onStage`, when given, is called
// as each stage begins; an exception it throws ends the parse there (how the viewer cancels a
// load between stages).
LoadedScene parseScene(SceneBundle bundle, Traversal traversal = Traversal::Automatic,
                       const SceneBudget& budget = {},
                       const std::function<void(ParseStage)>& onStage = {});

// readSceneBundle then parseScene.
LoadedScene loadScene(const std::filesystem::path& path,
                      const std::optional<std::filesystem::path>& cameraPath = std::nullopt,
                      const SceneReadOptions& options = {});

// One line for the log: triangles, dropped, emitters, emitting area, max albedo, point lights,
// the triangle test and the rounding gap share that chose it, the extent (the bounding box's
// size, in the scene's units: metres for glTF), the triangles placed by instances when there
// are any, and how many warnings loading gave.
std::string describeScene(const LoadedScene& loaded);

// Those warnings for the log, printed with that line: "warning: ...\n" each; empty when none.
std::string describeWarnings(const LoadedScene& loaded);

}  // namespace strata
