#pragma once
// The options every rendering command shares (render, view, bench), registered on a CLI11
// subcommand and checked in one place.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <CLI/App.hpp>

#include "camera.h"
#include "progressive_renderer.h"
#include "scene_loader.h"

namespace strata {

struct RenderOptions {
    std::string scene;  // empty: the bundled Cornell box
    std::string cameraFile;
    std::optional<int> width;   // unset: from the camera file
    std::optional<int> height;
    int depth = 5;
    std::optional<double> epsilon;  // when set, the depth comes from the truncation error
    std::string sampler = "strata24";
    uint64_t seed = 0;
    int threads = 0;
    bool nee = false;
    int rouletteDepth = -1;
    bool generalMaterials = false;

    // Registers the optional SCENE and the options on `command`.
    void addTo(CLI::App& command);
    // Validated settings for the renderer, the depth from --epsilon when given (logged on
    // stderr); throws strata::Error naming the bad option.
    RenderSettings renderSettings(const LoadedScene& loaded) const;
    // Reads the scene's files (OBJ, MTL, camera JSON) without parsing them.
    SceneFiles readSceneFiles() const;
    // Loads the scene and camera: parseScene(readSceneFiles()).
    LoadedScene loadScene() const;
    // The camera; width/height options override the camera file.
    Camera makeCamera(const LoadedScene& loaded) const;
};

}  // namespace strata
