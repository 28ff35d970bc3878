#pragma once
// `strata bench --vs-cycles`: Strata against Blender's Cycles on one scene, both measured
// against one converged reference (the bench's cached Strata render at high spp) at the same spp
// and at equal time. Strata runs with its default settings and with its best flags; each
// `strata render` is timed as a whole process, Cycles by its render call alone (Blender's
// start-up excluded), runs alternated and timed as medians.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>
#include <glm/vec3.hpp>

namespace strata {

struct CyclesBenchSettings {
    // A Lambertian OBJ, lit by its emitting triangles or by `sky`, seen by its JSON camera or the
    // default view.
    std::filesystem::path scene;
    // A uniform environment of this radiance (Strata's --env-color, Cycles' world colour); none:
    // the scene's own lights, the world black.
    std::optional<glm::vec3> sky;
    int depth = 9;                // Strata's K; Cycles' max_bounces K - 1
    int width = 256;
    int height = 256;
    std::vector<int> cyclesSpp{64, 256};  // each rounded to the nearest multiple of 24
    int repeats = 3;
    int threads = 0;  // 0: all cores
    uint64_t seed = 0;
    std::filesystem::path outDir;
};

// The markdown section for the summary, or a one-line note why it could not run (no `blender`
// on PATH, a scene Cycles cannot be given as Strata sees it, a failed run).
std::string runCyclesComparison(const CyclesBenchSettings& settings);

}  // namespace strata
