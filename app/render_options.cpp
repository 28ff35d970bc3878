#include "render_options.h"

#include "error.h"

namespace strata {

void RenderOptions::addTo(CLI::App& command, bool sceneRequired) {
    auto* sceneOption = command.add_option("scene", scene, "Scene .obj (camera from NAME.json beside it)");
    if (sceneRequired) sceneOption->required();
    command.add_option("--camera", cameraFile, "Camera JSON (default: NAME.json beside the scene)");
    command.add_option("--width", width, "Image width (default: from the camera file)");
    command.add_option("--height", height, "Image height (default: from the camera file)");
    command.add_option("--depth", depth, "Recursion depth K: bounces per path (0 = emission only)")
        ->capture_default_str();
    command.add_option("--sampler", sampler, "Hemisphere sampler: " + samplerNames())
        ->capture_default_str();
    command.add_option("--seed", seed, "Random seed")->capture_default_str();
    command.add_option("--threads", threads, "Render threads (0: all cores)")->capture_default_str();
    command.add_flag("--nee", nee,
                     "Next-event estimation: sample emitting triangles (MIS with the sampler) "
                     "and point lights (reached only this way)");
}

RenderSettings RenderOptions::renderSettings() const {
    RenderSettings settings;
    const auto kind = parseSamplerKind(sampler);
    if (!kind) throw Error("--sampler: unknown sampler '" + sampler + "' (use " + samplerNames() + ")");
    if (depth < 0 || depth > 100000) throw Error("--depth: must be in 0..100000");
    if (threads < 0 || threads > 1024) throw Error("--threads: must be in 0..1024 (0: all cores)");
    settings.integrator.depth = depth;
    settings.integrator.sampler = *kind;
    settings.integrator.nextEventEstimation = nee;
    settings.seed = seed;
    settings.threads = threads;
    return settings;
}

LoadedScene RenderOptions::loadScene() const {
    std::optional<std::filesystem::path> cameraPath;
    if (!cameraFile.empty()) cameraPath = cameraFile;
    return strata::loadScene(scene, cameraPath);
}

Camera RenderOptions::makeCamera(const LoadedScene& loaded) const {
    if (width < 0 || width > 65536) throw Error("--width: must be in 1..65536");
    if (height < 0 || height > 65536) throw Error("--height: must be in 1..65536");
    return Camera(loaded.settings.pose, width > 0 ? width : loaded.settings.width,
                  height > 0 ? height : loaded.settings.height);
}

}  // namespace strata
