#include "render_options.h"

#include <cstdio>

#include "bundled_assets.h"
#include "error.h"
#include "truncation.h"

namespace strata {

void RenderOptions::addTo(CLI::App& command) {
    command.add_option("scene", scene,
                       "Scene .obj, camera from NAME.json beside it (default: the bundled Cornell box)");
    command.add_option("--camera", cameraFile, "Camera JSON (default: NAME.json beside the scene)");
    command.add_option("--width", width, "Image width (default: from the camera file)");
    command.add_option("--height", height, "Image height (default: from the camera file)");
    command.add_option("--depth", depth, "Recursion depth K: bounces per path (0 = emission only)")
        ->capture_default_str();
    command.add_option("--epsilon", epsilon,
                       "Choose K as the smallest depth whose truncation bound Le_max a^(K+1)/(1-a) <= E");
    command.add_option("--sampler", sampler, "Hemisphere sampler: " + samplerNames())
        ->capture_default_str();
    command.add_option("--seed", seed, "Random seed")->capture_default_str();
    command.add_option("--threads", threads, "Render threads (0: all cores)")->capture_default_str();
    command.add_option("--roulette-depth", rouletteDepth,
                       "Russian roulette from this bounce on, survival by path weight (-1: off)")
        ->capture_default_str();
    command.add_flag("--general-materials", generalMaterials,
                     "Run the general material code even when every material is Lambertian");
    command.add_flag("--nee", nee,
                     "Next-event estimation: sample emitting triangles (MIS with the sampler) "
                     "and point lights (reached only this way)");
}

RenderSettings RenderOptions::renderSettings(const LoadedScene& loaded) const {
    RenderSettings settings;
    const auto kind = parseSamplerKind(sampler);
    if (!kind) throw Error("--sampler: unknown sampler '" + sampler + "' (use " + samplerNames() + ")");
    if (depth < 0 || depth > 100000) throw Error("--depth: must be in 0..100000");
    if (threads < 0 || threads > 1024) throw Error("--threads: must be in 0..1024 (0: all cores)");
    settings.integrator.depth = depth;
    if (epsilon) {
        if (!(*epsilon > 0.0)) throw Error("--epsilon: must be positive");
        TruncationChoice choice{};
        try {
            choice = chooseSceneTruncationDepth(*epsilon, loaded.scene);
        } catch (const Error& e) {
            throw Error(std::string("--epsilon: ") + e.what() + "; give --depth instead");
        }
        const SceneSummary& summary = loaded.scene.summary();
        settings.integrator.depth = choice.depth;
        std::fprintf(stderr, "depth K = %d from --epsilon %g: truncation bound %.3g (max albedo %.3g, max Le %.3g)\n",
                     choice.depth, *epsilon, choice.bound, summary.maxAlbedo, summary.maxEmission);
    }
    settings.integrator.sampler = *kind;
    settings.integrator.nextEventEstimation = nee;
    if (rouletteDepth < -1) throw Error("--roulette-depth: must be -1 (off) or at least 0");
    settings.integrator.rouletteDepth = rouletteDepth;
    settings.integrator.lambertianFastPath = !generalMaterials;
    settings.seed = seed;
    settings.threads = threads;
    return settings;
}

SceneFiles RenderOptions::readSceneFiles() const {
    std::optional<std::filesystem::path> cameraPath;
    if (!cameraFile.empty()) cameraPath = cameraFile;
    return strata::readSceneFiles(scene.empty() ? bundledScene("cornell") : std::filesystem::path(scene),
                                  cameraPath);
}

LoadedScene RenderOptions::loadScene() const { return parseScene(readSceneFiles()); }

Camera RenderOptions::makeCamera(const LoadedScene& loaded) const {
    if (width && (*width < 1 || *width > 65536)) throw Error("--width: must be in 1..65536");
    if (height && (*height < 1 || *height > 65536)) throw Error("--height: must be in 1..65536");
    return Camera(loaded.settings.pose, width.value_or(loaded.settings.width),
                  height.value_or(loaded.settings.height));
}

}  // namespace strata
