#pragma once
// `strata bench`, real scenes: models as found in the wild (Debian's assimp-testmodels, read
// where the package installs them) against the Cornell box, for what a user waits on before the
// first image (loading, the BVH build, start-up) and what a large mesh costs per path and in
// memory.
#include <filesystem>
#include <string>

namespace strata {

// Where Debian's assimp-testmodels installs its models: read in place, never copied into the
// repository.
inline const std::filesystem::path kAssimpModels = "/usr/share/assimp/models";

struct RealScenesSettings {
    std::filesystem::path baseline;  // the Cornell box the others are compared with
    int depth = 5;
    int width = 160;   // of the whole-process renders and the in-process rate
    int height = 120;
    int spp = 24;      // of the whole-process renders: the first image
    int viewerWidth = 1280;  // the viewer's window for its first image (its default)
    int viewerHeight = 720;
    int ratePasses = 4;  // of the in-process rate, after one warm-up pass
    int repeats = 3;
    int threads = 0;  // 0: all cores
    std::filesystem::path outDir;
};

// Measures every scene, writes real-scenes.csv to outDir and returns the markdown section for the
// summary, or a note why it could not run (the models are not installed).
std::string runRealScenes(const RealScenesSettings& settings);

}  // namespace strata
