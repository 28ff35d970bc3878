#pragma once
// The options every rendering command shares (render, view, bench), registered on a CLI11
// subcommand, checked and turned into the renderer's settings in one place. The bench fills them
// in code for its own renders and for the `strata render` children it times.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "cli_forward.h"

#include "scene/camera.h"
#include "integrator/progressive_renderer.h"
#include "scene/scene_loader.h"

namespace strata {

struct RenderOptions {
    std::string scene;  // empty: the bundled Cornell box
    std::string cameraFile;
    std::optional<int> width;   // unset: from the camera file
    std::optional<int> height;
    int depth = 5;
    std::optional<double> epsilon;  // when set, the depth comes from the truncation error
    std::string sampler = "strata24-bsdf";
    uint64_t seed = 0;
    int threads = 0;
    bool nee = true;
    int rouletteDepth = kRouletteDepthDefault;
    std::string env;               // --env FILE.exr or "none"; empty: the default rule
    std::vector<float> envColor;   // --env-color R G B
    float envRotate = 0.0f;        // --env-rotate, degrees about +y
    double noiseThreshold = 0.0;  // adaptive sampling (film/adaptive_sampling.h); 0: off
    bool watertight = false;      // always Embree's watertight triangle test (traversal_precision.h)
    double textureBudget = 4.0;   // --texture-budget, GiB of decoded texels (texture_budget.h)
    uint64_t maxTriangles = SceneBudget{}.triangles;  // the scene's budget (scene_format.h)

    // Registers the optional SCENE and the options on `command`.
    void addTo(CLI::App& command);
    // The command-line arguments that addTo parses back into these options (the scene first).
    std::vector<std::string> arguments() const;
    // Validated settings for the renderer, the depth from --epsilon when given (logged on
    // stderr); throws strata::Error naming the bad option.
    RenderSettings renderSettings(const Scene& scene) const;
    // Reads the scene's files (the scene file and those it names, its description, the camera
    // file) without parsing them.
    SceneBundle readSceneBundle() const;
    // The environment the options give (lights/environment.h), its map read and checked; throws
    // strata::Error naming the option or the file.
    Environment environment() const;
    // What the scene may take: --max-triangles, and --texture-budget in bytes; throws
    // strata::Error naming a bad value.
    SceneBudget sceneBudget() const;
    // Builds the scene from its files; `environment` (environment(), read once by the caller),
    // unless Default, overrides the scene description's.
    LoadedScene parseScene(SceneBundle files, const Environment& environment) const;
    // Loads the scene and camera: parseScene(readSceneBundle(), environment()).
    LoadedScene loadScene() const;
    // The camera; width/height options override the camera file.
    Camera makeCamera(const LoadedScene& loaded) const;
};

}  // namespace strata
