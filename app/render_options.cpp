#include "render_options.h"

#include <CLI/App.hpp>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "bundled_assets.h"
#include "usage.h"
#include "util/error.h"
#include "integrator/truncation.h"
#include "io/image_io.h"

namespace strata {

void RenderOptions::addTo(CLI::App& command) {
    command.add_option("scene", scene,
                       "Scene file (" + knownSceneExtensions() +
                           "; camera and lights from NAME.json beside it; default: the bundled "
                           "Cornell box)");
    command.add_option("--camera", cameraFile, "Camera JSON (default: NAME.json beside the scene; lights stay the scene's)");
    command.add_option("--width", width, "Image width (default: from the camera file)");
    command.add_option("--height", height, "Image height (default: from the camera file)");
    command.add_option("--aperture", aperture,
                       "Thin-lens aperture radius in scene units, for depth of field (0: a pinhole, "
                       "everything sharp; default: the camera's, 0 unless its JSON gives aperture_radius)");
    command.add_option("--focus-distance", focusDistance,
                       "Distance along the view axis to the plane in focus (0: the camera's look_at; "
                       "default: the camera's)");
    command.add_option("--depth", depth, "Recursion depth K: bounces per path (0 = emission only)")
        ->capture_default_str();
    command.add_option("--epsilon", epsilon,
                       "Choose K as the smallest depth whose truncation bound Le_max a^(K+1)/(1-a) <= E");
    command.add_option("--sampler", sampler, "Hemisphere sampler: " + samplerNames())
        ->capture_default_str();
    acceptUnsigned64(*command.add_option("--seed", seed, "Random seed")->capture_default_str());
    command.add_option("--threads", threads, "Render threads (0: all cores)")->capture_default_str();
    command.add_option("--roulette-depth", rouletteDepth,
                       "Russian roulette from this bounce on, survival by path weight (-1: off)")
        ->capture_default_str();
    command.add_flag("--nee,!--no-nee", nee,
                     "Next-event estimation (on by default; --no-nee: off): sample emitting "
                     "triangles and the environment (MIS with the sampler) and point lights "
                     "(reached only this way)");
    command.add_option("--light-sampler", lightSampler,
                       "How next-event estimation chooses a light: " + lightSamplerNames() +
                           " (power: by power alone; tree: by a light tree weighing each light by "
                           "what it can send to the point; auto: the tree in scenes with many emitters)")
        ->capture_default_str();
    command.add_option("--terminator-offset", terminatorOffset,
                       "Shadow terminator of coarse smooth meshes: a shadow ray toward a light less than "
                       "this cosine above a facet with vertex normals (or below it, but above the "
                       "shading normal's horizon) leaves from the curved surface the normals describe "
                       "(0: off, the triangles as they are; Cycles' geometry offset is 0.1)")
        ->capture_default_str();
    auto* envOption = command.add_option(
        "--env", env,
        "Environment seen by rays leaving the scene: a latitude-longitude EXR (2:1, +y up) or "
        "'none' (default: none, or uniform white for a scene with no light)");
    command.add_option("--env-color", envColor, "Uniform environment of radiance R G B")
        ->expected(3)
        ->excludes(envOption);
    command.add_option("--env-rotate", envRotate, "Turn the environment map about +y (degrees)")
        ->capture_default_str();
    command.add_option("--background", background,
                       std::string("What camera rays that miss every surface show: ") + kBackdropSyntax +
                           " (env: the environment; default: a grey gradient under the default white "
                           "sky, else the environment)");
    command.add_option("--noise-threshold", noiseThreshold,
                       "Adaptive sampling: a pixel stops receiving passes at this relative "
                       "standard error (0: off)")
        ->capture_default_str();
    command.add_flag("--allow-outside-files", allowOutsideFiles,
                     "Read the files a scene refers to (MTL, textures, glTF buffers and images, the "
                     "description's environment) also outside the scene file's folder: for your own "
                     "scenes only (default: such a reference is refused)");
    command.add_flag("--watertight", watertight,
                     "Always trace with Embree's watertight triangle test (default: only where the "
                     "scene's rounding gap share needs it)");
    command
        .add_option("--texture-budget", textureBudget,
                    "GiB that the scene's decoded textures and environment map may take together; a "
                    "file that would go over is refused before it is decoded")
        ->capture_default_str()
        ->check(CLI::Validator(
            [](const std::string& text) {
                // Finite and positive, and no more than 2^24 GiB, which a byte count holds.
                const double gib = std::strtod(text.c_str(), nullptr);
                return gib > 0.0 && gib <= 16777216.0 ? std::string() : "must be a positive number of GiB";
            },
            "GIB"));
    acceptUnsigned64(*command
                          .add_option("--max-triangles", maxTriangles,
                                      "Refuse a scene that stores more triangles than this after instancing (a "
                                      "shared mesh's once, each instance counted as 3), before reading its geometry")
                          ->capture_default_str());
}

std::vector<std::string> RenderOptions::arguments() const {
    // The shortest text that reads back as the same double.
    const auto text = [](double value) {
        char digits[32];
        return std::string(digits, std::to_chars(digits, digits + sizeof digits, value).ptr);
    };
    // Only what differs from the defaults, which the command fills in again.
    const RenderOptions defaults;
    std::vector<std::string> args;
    if (!scene.empty()) args.push_back(scene);
    if (!cameraFile.empty()) args.insert(args.end(), {"--camera", cameraFile});
    if (width) args.insert(args.end(), {"--width", std::to_string(*width)});
    if (height) args.insert(args.end(), {"--height", std::to_string(*height)});
    if (aperture) args.insert(args.end(), {"--aperture", text(*aperture)});
    if (focusDistance) args.insert(args.end(), {"--focus-distance", text(*focusDistance)});
    if (depth != defaults.depth) args.insert(args.end(), {"--depth", std::to_string(depth)});
    if (epsilon) args.insert(args.end(), {"--epsilon", text(*epsilon)});
    if (sampler != defaults.sampler) args.insert(args.end(), {"--sampler", sampler});
    if (seed != defaults.seed) args.insert(args.end(), {"--seed", std::to_string(seed)});
    if (threads != defaults.threads) args.insert(args.end(), {"--threads", std::to_string(threads)});
    if (rouletteDepth != defaults.rouletteDepth) {
        args.insert(args.end(), {"--roulette-depth", std::to_string(rouletteDepth)});
    }
    if (nee != defaults.nee) args.push_back(nee ? "--nee" : "--no-nee");
    if (lightSampler != defaults.lightSampler) args.insert(args.end(), {"--light-sampler", lightSampler});
    if (terminatorOffset != defaults.terminatorOffset) {
        args.insert(args.end(), {"--terminator-offset", text(terminatorOffset)});
    }
    if (!env.empty()) args.insert(args.end(), {"--env", env});
    if (!envColor.empty()) {
        args.push_back("--env-color");
        for (float c : envColor) args.push_back(text(c));
    }
    if (envRotate != defaults.envRotate) args.insert(args.end(), {"--env-rotate", text(envRotate)});
    if (!background.empty()) args.insert(args.end(), {"--background", background});
    if (noiseThreshold != defaults.noiseThreshold) {
        args.insert(args.end(), {"--noise-threshold", text(noiseThreshold)});
    }
    if (watertight) args.push_back("--watertight");
    if (allowOutsideFiles) args.push_back("--allow-outside-files");
    if (textureBudget != defaults.textureBudget) {
        args.insert(args.end(), {"--texture-budget", text(textureBudget)});
    }
    if (maxTriangles != defaults.maxTriangles) args.insert(args.end(), {"--max-triangles", std::to_string(maxTriangles)});
    return args;
}

RenderSettings RenderOptions::renderSettings(const Scene& scene) const {
    RenderSettings settings;
    const auto kind = parseSamplerKind(sampler);
    if (!kind) throw UsageError("--sampler: unknown sampler '" + sampler + "' (use " + samplerNames() + ")");
    if (depth < 0 || depth > 100000) throw UsageError("--depth: must be in 0..100000");
    settings.integrator.depth = depth;
    if (epsilon) {
        if (!(*epsilon > 0.0)) throw UsageError("--epsilon: must be positive");
        TruncationChoice choice{};
        try {
            choice = chooseSceneTruncationDepth(*epsilon, scene);
        } catch (const Error& e) {
            throw UsageError(std::string("--epsilon: ") + e.what() + "; give --depth instead");
        }
        settings.integrator.depth = choice.depth;
        std::fprintf(stderr, "depth K = %d from --epsilon %g: truncation bound %.3g (max albedo %.3g, max Le %.3g)\n",
                     choice.depth, *epsilon, choice.bound, scene.summary().maxAlbedo,
                     maxEmittedRadiance(scene));
    }
    settings.integrator.sampler = *kind;
    settings.integrator.nextEventEstimation = nee;
    const auto lightKind = parseLightSamplerKind(lightSampler);
    if (!lightKind) {
        throw UsageError("--light-sampler: unknown light sampler '" + lightSampler + "' (use " +
                         lightSamplerNames() + ")");
    }
    settings.integrator.lightSampler = *lightKind;
    if (rouletteDepth < -1) throw UsageError("--roulette-depth: must be -1 (off) or at least 0");
    settings.integrator.rouletteDepth = rouletteDepth;
    if (!(terminatorOffset >= 0.0f && terminatorOffset <= 1.0f)) {
        throw UsageError("--terminator-offset: must be a cosine in 0..1 (0: off)");
    }
    settings.integrator.terminatorOffset = terminatorOffset;
    settings.seed = seed;
    settings.threads = threadCount();
    if (!(noiseThreshold >= 0.0 && noiseThreshold <= 10.0)) {
        throw UsageError("--noise-threshold: must be in 0..10 (0: off)");
    }
    settings.adaptive.threshold = noiseThreshold;
    settings.backdrop = backdrop();
    return settings;
}

SceneBundle RenderOptions::readSceneBundle() const {
    std::optional<std::filesystem::path> cameraPath;
    if (!cameraFile.empty()) cameraPath = cameraFile;
    SceneBundle bundle = strata::readSceneBundle(
        scene.empty() ? bundledScene("cornell") : std::filesystem::path(scene), cameraPath, readOptions());
    if (!env.empty() && env != "none") bundle.environmentMap = SceneFile{env, readExrFile(env)};
    return bundle;
}

int RenderOptions::threadCount() const {
    if (threads < 0 || threads > 1024) throw UsageError("--threads: must be in 0..1024 (0: all cores)");
    return threads;
}

BackdropSetting RenderOptions::backdrop() const {
    if (background.empty()) return {};
    const auto setting = parseBackdrop(background);
    if (!setting) {
        throw UsageError("--background: expected " + std::string(kBackdropSyntax) +
                         " (radiances finite and >= 0), got '" + background + "'");
    }
    return *setting;
}

namespace {

// The environment `options` give, its map decoded from `files` within the scene's texture
// `budget`; a note on the map to `warnings`.
Environment optionsEnvironment(const RenderOptions& options, SceneBundle& files,
                               SceneBudget& budget, std::vector<std::string>& warnings) {
    if (!std::isfinite(options.envRotate)) throw UsageError("--env-rotate: must be a finite angle in degrees");
    Environment environment;
    if (!options.envColor.empty()) {
        for (float c : options.envColor) {
            if (!(std::isfinite(c) && c >= 0.0f)) {
                throw UsageError("--env-color: must be three finite radiances >= 0");
            }
        }
        environment.kind = Environment::Kind::Uniform;
        environment.radiance = glm::vec3(options.envColor[0], options.envColor[1], options.envColor[2]);
    } else if (options.env == "none") {
        environment.kind = Environment::Kind::None;
    } else if (files.environmentMap) {
        environment.kind = Environment::Kind::Map;
        SceneFile& map = *files.environmentMap;
        // Decoded first: the scene's textures then share what the map leaves of the budget. The
        // file's bytes are taken and freed once decoded: as many as the map's own, they are not
        // kept with the scene for the render's life.
        const EnvironmentMapFile file = readEnvironmentMap(
            std::move(map.bytes), map.name, TextureBudget(budget.textureBytes, budget.textureBytesSpent));
        budget.textureBytesSpent += file.bytes;
        if (file.zeroedNegatives > 0) {
            warnings.push_back(map.name + ": " + std::to_string(file.zeroedNegatives) +
                               " slightly negative texel components (lossy compression) read as 0");
        }
        environment.map = file.map;
        environment.rotationDegrees = options.envRotate;
    }
    return environment;
}

}  // namespace

SceneBudget RenderOptions::sceneBudget() const {
    if (maxTriangles < 1) throw UsageError("--max-triangles: must be at least 1");
    SceneBudget budget;
    budget.triangles = maxTriangles;
    budget.textureBytes = static_cast<uint64_t>(std::llround(std::ldexp(textureBudget, 30)));
    return budget;
}

LoadedScene RenderOptions::parseScene(SceneBundle files, Environment* environment) const {
    for (const auto& [option, value] : {std::pair{"--aperture", aperture}, std::pair{"--focus-distance", focusDistance}}) {
        if (value && !(*value >= 0.0f && std::isfinite(*value))) {
            throw UsageError(std::string(option) + ": must be a finite number >= 0");
        }
    }
    SceneBudget budget = sceneBudget();
    std::vector<std::string> warnings;
    const Environment given = optionsEnvironment(*this, files, budget, warnings);
    LoadedScene loaded = strata::parseScene(std::move(files), watertight ? Traversal::Watertight : Traversal::Automatic,
                                            budget);
    loaded.report.warnings.insert(loaded.report.warnings.end(), warnings.begin(), warnings.end());
    if (aperture) loaded.settings.pose.apertureRadius = *aperture;
    if (focusDistance) loaded.settings.pose.focusDistance = *focusDistance;
    // The --env options override the scene description's environment; without them it stands.
    if (given.kind != Environment::Kind::Default) loaded.scene.setEnvironment(given);
    if (environment) *environment = given;
    return loaded;
}

LoadedScene RenderOptions::loadScene() const { return parseScene(readSceneBundle()); }

Camera RenderOptions::makeCamera(const LoadedScene& loaded) const {
    if (width && (*width < 1 || *width > 65536)) throw UsageError("--width: must be in 1..65536");
    if (height && (*height < 1 || *height > 65536)) throw UsageError("--height: must be in 1..65536");
    return Camera(loaded.settings.pose, width.value_or(loaded.settings.width),
                  height.value_or(loaded.settings.height));
}

}  // namespace strata
