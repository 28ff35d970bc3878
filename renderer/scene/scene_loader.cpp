#include "scene/scene_loader.h"

#include <cstdio>
#include <string>
#include <system_error>

#include "scene/default_camera.h"
#include "scene/scene_description.h"
#include "util/error.h"
#include "util/printable.h"
#include "util/text_file.h"

namespace strata {
namespace {

bool sameFile(const std::filesystem::path& a, const std::filesystem::path& b) {
    std::error_code error;
    return std::filesystem::equivalent(a, b, error);
}

// The description's environment, a map decoded from the bundle's copy of its file, so that every
// MPI rank lights the scene with the same bytes; its texels count with the textures' against the
// budget.
Environment describedEnvironment(const SceneDescription& description, const SceneBundle& bundle,
                                 const SceneBudget& budget, LoadReport& report) {
    Environment environment = description.environment;
    if (environment.kind != Environment::Kind::Map) return environment;
    const std::string name = bundle.pathOf(description.environmentFile);
    const SceneFile* file = bundle.find(description.environmentFile);
    if (!file) throw Error(name + ": no such EXR file (the scene description's \"environment\")");
    const EnvironmentMapFile map =
        readEnvironmentMap(file->bytes, name, TextureBudget(budget.textureBytes, budget.textureBytesSpent + report.textureBytes));
    if (map.zeroedNegatives > 0) {
        report.warnings.push_back(name + ": " + std::to_string(map.zeroedNegatives) +
                                  " slightly negative texel components (lossy compression) read as 0");
    }
    environment.map = map.map;
    return environment;
}

}  // namespace

SceneBundle readSceneBundle(const std::filesystem::path& path,
                            const std::optional<std::filesystem::path>& cameraPath,
                            const SceneReadOptions& options) {
    std::error_code error;
    if (std::filesystem::is_directory(path, error)) {
        throw Error(printable(path.string()) + ": is a folder, not a scene file (give one of its " +
                    knownSceneExtensions() + " files)");
    }
    if (fileKindOf(path) != FileKind::Regular) {
        throw Error(printable(path.string()) + ": no such scene file");
    }
    SceneFolder folder(path, options);
    SceneBundle bundle{path, sceneFormatOf(path).read(path, folder), std::nullopt, std::nullopt};
    const auto sidecar = std::filesystem::path(path).replace_extension(".json");
    // --camera naming the description itself: read once, or its point lights would count twice.
    const bool cameraIsSidecar = cameraPath && sameFile(*cameraPath, sidecar);
    const std::string mainName = printable(path.string());
    if (auto bytes = folder.read(sidecar.filename().string(), mainName + ": scene description")) {
        SceneFile description{sidecar.filename().string(), std::move(*bytes)};
        const std::string name = bundle.pathOf(description.name);
        if (cameraIsSidecar) parseCameraFile(description.bytes, name);  // its camera is required
        for (const std::string& file : parseSceneDescription(description.bytes, name).files) {
            if (bundle.find(file)) continue;
            bundle.files.push_back({file, folder.require(file, name + ": \"environment\" file")});
        }
        bundle.description = std::move(description);
    }
    if (cameraPath && !cameraIsSidecar) {
        bundle.camera = SceneFile{cameraPath->string(), readTextFile(*cameraPath, "camera file")};
    }
    bundle.outsideNotes = folder.outsideNotes();
    return bundle;
}

SceneContents parseSceneContents(const SceneBundle& bundle, const SceneBudget& budget) {
    SceneContents contents;
    LoadReport& report = contents.report;
    contents.parsed = parseSceneFile(bundle, &report, budget);
    report.warnings.insert(report.warnings.end(), bundle.outsideNotes.begin(), bundle.outsideNotes.end());
    MeshData& mesh = contents.parsed.mesh;
    if (mesh.triangles.empty()) {
        throw Error(printable(bundle.path.string()) + ": the scene has no usable triangles");
    }
    SceneDescription description;
    if (bundle.description) {
        description = parseSceneDescription(bundle.description->bytes,
                                            bundle.pathOf(bundle.description->name));
    }
    mesh.pointLights.insert(mesh.pointLights.end(), description.pointLights.begin(),
                            description.pointLights.end());
    mesh.spotLights.insert(mesh.spotLights.end(), description.spotLights.begin(), description.spotLights.end());
    mesh.environment = describedEnvironment(description, bundle, budget, report);
    contents.settings = description.camera;
    contents.posed = description.hasPose;
    if (bundle.camera) {
        const SceneDescription cameraFile = parseCameraFile(bundle.camera->bytes, bundle.camera->name);
        contents.settings = cameraFile.camera;
        contents.posed = true;
        mesh.pointLights.insert(mesh.pointLights.end(), cameraFile.pointLights.begin(),
                                cameraFile.pointLights.end());
    }
    return contents;
}

LoadedScene parseScene(SceneBundle bundle, Traversal traversal, const SceneBudget& budget,
                       const std::function<void(ParseStage)>& onStage) {
    if (onStage) onStage(ParseStage::Parsing);
    SceneContents contents = parseSceneContents(bundle, budget);
    if (onStage) onStage(ParseStage::Building);
    Scene scene(std::move(contents.parsed.mesh), traversal);
    CameraSettings& settings = contents.settings;
    // The mesh as the scene keeps it: its triangles turned to agree with their normals.
    if (!contents.posed) {
        settings.pose = contents.parsed.camera ? *contents.parsed.camera
                                               : defaultCameraPose(scene.mesh(), contents.parsed.orientation);
    }
    return LoadedScene{std::move(scene), settings, std::move(contents.report), std::move(bundle)};
}

LoadedScene loadScene(const std::filesystem::path& path,
                      const std::optional<std::filesystem::path>& cameraPath, const SceneReadOptions& options) {
    return parseScene(readSceneBundle(path, cameraPath, options));
}

std::string describeScene(const LoadedScene& loaded) {
    const SceneSummary& s = loaded.scene.summary();
    const glm::vec3 extent = loaded.scene.boundsMax() - loaded.scene.boundsMin();
    char line[512];
    std::snprintf(line, sizeof line,
                  "%s: %zu triangles (%zu degenerate dropped, %zu non-finite vertices), "
                  "%zu emitting (area %.4g), max albedo %.3g, %zu point lights, "
                  "%s triangle test (rounding gap share %.2g), extent %.4g x %.4g x %.4g",
                  loaded.scenePath().string().c_str(), s.triangles, loaded.report.droppedTriangles,
                  loaded.report.nonFiniteVertices, s.emitters, s.emittingArea, s.maxAlbedo,
                  loaded.scene.mesh().pointLights.size(), s.watertight ? "watertight" : "fast",
                  s.roundingGapShare, extent.x, extent.y, extent.z);
    std::string text = line;
    if (const size_t spots = loaded.scene.mesh().spotLights.size(); spots > 0) {
        text += ", " + std::to_string(spots) + " spot lights";
    }
    if (s.placements > 0) {
        text += ", " + std::to_string(s.placedTriangles) + " triangles placed by " + std::to_string(s.placements) +
                " instances";
    }
    const size_t warnings = loaded.report.warnings.size();
    if (warnings == 0) return text;
    return text + (", " + std::to_string(warnings) + (warnings == 1 ? " warning" : " warnings"));
}

std::string describeWarnings(const LoadedScene& loaded) {
    std::string lines;
    for (const std::string& warning : loaded.report.warnings) lines += "warning: " + warning + "\n";
    return lines;
}

}  // namespace strata
