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
    // The camera's thin lens (camera.h); unset: the camera's own.
    std::optional<float> aperture;
    std::optional<float> focusDistance;
    int depth = kProgramDefaults.depth;
    std::optional<double> epsilon;  // when set, the depth comes from the truncation error
    std::string sampler{samplerName(kProgramDefaults.sampler)};
    uint64_t seed = 0;
    int threads = 0;
    bool nee = kProgramDefaults.nextEventEstimation;
    int rouletteDepth = kProgramDefaults.rouletteDepth;
    std::string lightSampler{lightSamplerName(kProgramDefaults.lightSampler)};
    float terminatorOffset = kProgramDefaults.terminatorOffset;  // PathIntegratorSettings::terminatorOffset
    std::string env;               // --env FILE.exr or "none"; empty: the default rule
    std::vector<float> envColor;   // --env-color R G B
    float envRotate = 0.0f;        // --env-rotate, degrees about +y
    std::string background;        // --background (film/backdrop.h's syntax); empty: automatic
    double noiseThreshold = 0.0;  // adaptive sampling (film/adaptive_sampling.h); 0: off
    bool watertight = false;      // always Embree's watertight triangle test (traversal_precision.h)
    bool allowOutsideFiles = false;  // read references outside the scene's folder (scene_folder.h)
    double textureBudget = 4.0;   // --texture-budget, GiB of decoded texels (texture_budget.h)
    uint64_t maxTriangles = SceneBudget{}.triangles;  // the scene's budget (scene_format.h)

    // Registers the optional SCENE and the options on `command`.
    void addTo(CLI::App& command);
    // The command-line arguments that addTo parses back into these options (the scene first).
    std::vector<std::string> arguments() const;
    // Validated settings for the renderer, the depth from --epsilon when given (logged on
    // stderr); throws strata::Error naming the bad option.
    RenderSettings renderSettings(const Scene& scene) const;
    // What camera rays that miss show (--background); throws strata::Error naming the option.
    BackdropSetting backdrop() const;
    // --threads, checked (0: all cores); throws strata::UsageError naming the option.
    int threadCount() const;
    // Reads the scene's files (the scene file and those it names, its description, the camera
    // file) and the --env map without parsing them, confined to the scene's folder unless
    // allowOutsideFiles (the --env map, the user's own, is not).
    SceneBundle readSceneBundle() const;
    // What the scene may take: --max-triangles, and --texture-budget in bytes; throws
    // strata::UsageError naming a bad value.
    SceneBudget sceneBudget() const;
    // Builds the scene from its files within sceneBudget(), its camera's lens as --aperture and
    // --focus-distance give it, lit by the environment the options
    // give (lights/environment.h) when they give one, else by the scene description's: the --env
    // map is decoded from the bundle's copy within the scene's texture budget, and what decoding
    // tolerated joins the load report's warnings. `environment`, when not null, receives the
    // options' environment (Default when they give none). Throws strata::Error naming the option
    // or the file.
    LoadedScene parseScene(SceneBundle files, Environment* environment = nullptr) const;
    // Loads the scene and camera: parseScene(readSceneBundle()).
    LoadedScene loadScene() const;
    // What reading the scene may read (allowOutsideFiles).
    SceneReadOptions readOptions() const { return {allowOutsideFiles}; }
    // The camera; width/height options override the camera file.
    Camera makeCamera(const LoadedScene& loaded) const;
};

}  // namespace strata
