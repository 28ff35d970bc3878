#include "scene/scene_loader.h"

#include <cstdio>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "util/error.h"
#include "util/text_file.h"

namespace strata {
namespace {

// A view down -z onto the bounding box, far enough to see all of it.
SceneSettings framingSettings(const Scene& scene) {
    const glm::vec3 centre = 0.5f * (scene.boundsMin() + scene.boundsMax());
    const float radius = 0.5f * glm::length(scene.boundsMax() - scene.boundsMin());
    SceneSettings settings;
    settings.pose.fovYDegrees = 40.0f;
    settings.pose.lookAt = centre;
    settings.pose.position = centre + glm::vec3(0.0f, 0.0f, 3.0f * glm::max(radius, 1e-3f));
    return settings;
}

}  // namespace

SceneFiles readSceneFiles(const std::filesystem::path& objPath,
                          const std::optional<std::filesystem::path>& cameraPath) {
    if (!std::filesystem::is_regular_file(objPath)) {
        throw Error(objPath.string() + ": no such scene file");
    }
    SceneFiles files{readObjFiles(objPath), "", objPath, {}};
    if (cameraPath) {
        files.cameraPath = *cameraPath;
    } else if (auto sidecar = std::filesystem::path(objPath).replace_extension(".json");
               std::filesystem::is_regular_file(sidecar)) {
        files.cameraPath = sidecar;
    }
    if (!files.cameraPath.empty()) files.cameraText = readTextFile(files.cameraPath, "camera file");
    return files;
}

LoadedScene parseScene(const SceneFiles& files) {
    ObjLoadReport report;
    MeshData mesh = parseObj(files.obj.objText, files.obj.objName, files.obj.mtlText,
                             files.obj.mtlName, &report);
    if (mesh.triangles.empty()) {
        throw Error(files.obj.objName + ": the scene has no usable triangles");
    }
    std::optional<SceneSettings> settings;
    if (!files.cameraPath.empty()) {
        settings = parseSceneSettings(files.cameraText, files.cameraPath.string());
        mesh.pointLights = settings->pointLights;
    }
    Scene scene(std::move(mesh));
    if (!settings) settings = framingSettings(scene);
    return LoadedScene{std::move(scene), std::move(*settings), report, files.objPath,
                       files.cameraPath};
}

LoadedScene loadScene(const std::filesystem::path& objPath,
                      const std::optional<std::filesystem::path>& cameraPath) {
    return parseScene(readSceneFiles(objPath, cameraPath));
}

std::string describeScene(const LoadedScene& loaded) {
    const SceneSummary& s = loaded.scene.summary();
    char line[512];
    std::snprintf(line, sizeof line,
                  "%s: %zu triangles (%zu degenerate dropped, %zu non-finite vertices), "
                  "%zu emitting (area %.4g), max albedo %.3g, %zu point lights",
                  loaded.objPath.string().c_str(), s.triangles, loaded.report.droppedTriangles,
                  loaded.report.nonFiniteVertices, s.emitters, s.emittingArea, s.maxAlbedo,
                  loaded.scene.mesh().pointLights.size());
    return line;
}

}  // namespace strata
