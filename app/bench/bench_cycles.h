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

// Which Strata settings race Cycles: every lever of the defaults turned off alone, or (on the
// real scenes, to keep their run short) the defaults, plain BSDF sampling and, where something
// lights the scene that next-event estimation samples (emitters, a map), the defaults without it.
enum class CyclesLevers { All, Few };

struct CyclesBenchSettings {
    // An OBJ (Lambertian, textured by map_Kd or not) or glTF model, lit by its emitting triangles,
    // by `sky` or by `environmentMap`, seen by its JSON camera or the default view.
    std::filesystem::path scene;
    // A uniform environment of this radiance (Strata's --env-color, Cycles' world colour); none:
    // the scene's own lights, the world black.
    std::optional<glm::vec3> sky;
    // A latitude-longitude EXR (Strata's --env, turned by --env-rotate) instead.
    std::filesystem::path environmentMap;
    float environmentRotation = 0.0f;
    // For a binary glTF: render a copy whose materials are all white metal of this roughness
    // (writeWhiteMetalGlb), the part of glTF's model Cycles' Glossy BSDF computes exactly.
    std::optional<float> whiteMetalRoughness;
    CyclesLevers levers = CyclesLevers::All;
    int depth = 9;                // Strata's K; Cycles' max_bounces K - 1
    int width = 256;
    int height = 256;
    std::vector<int> cyclesSpp{64, 256};  // each rounded to the nearest multiple of 24
    int repeats = 3;
    int threads = 0;  // 0: all cores
    uint64_t seed = 0;
    std::filesystem::path outDir;
};

// The relMSE x seconds ratio of Strata's defaults to Cycles' at one Cycles budget.
struct CyclesRatio {
    int cyclesSpp = 0;
    double sameSpp = 0.0;
    double equalTime = 0.0;  // the same-spp ratio when that run also took Cycles' time
};

struct CyclesComparison {
    // The markdown section for the summary, or a one-line note why it could not run (no
    // `blender` on PATH, a scene Cycles cannot be given as Strata sees it, a failed run).
    std::string markdown;
    std::vector<CyclesRatio> ratios;  // empty when it did not run
};

CyclesComparison runCyclesComparison(const CyclesBenchSettings& settings);

}  // namespace strata
