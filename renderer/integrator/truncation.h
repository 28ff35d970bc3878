#pragma once
// Choosing the recursion depth from a truncation error instead of guessing it (paper, section 4:
// k_eps; derivation in ../shared/notes/strata-math.md section 5.5).
//
// With a = the largest albedo in the scene (sup of the integral of f_r cos) and Le_max the largest
// emitted radiance, the Neumann series truncated after K bounces misses at most
//     Le_max a^(K+1) / (1 - a),
// and the furnace (every surface of albedo a emitting Le_max) attains it exactly. The smallest K
// whose bound is at most epsilon is K_eps = max(0, ceil(ln(eps (1 - a) / Le_max) / ln a) - 1).
// For a >= 1 the series need not converge and no finite K bounds the error.
#include <optional>

namespace strata {

class Scene;

struct TruncationChoice {
    int depth;     // K_eps
    double bound;  // Le_max a^(K+1) / (1 - a) at that depth
};

// nullopt when maxAlbedo >= 1 (no finite depth bounds the error). Throws strata::Error for
// epsilon <= 0 or a negative albedo or emission.
std::optional<TruncationChoice> chooseTruncationDepth(double epsilon, double maxAlbedo,
                                                      double maxEmission);

// The bound Le_max a^(K+1) / (1 - a) for a given depth (a < 1).
double truncationBound(int depth, double maxAlbedo, double maxEmission);

// Le_max of a scene: the largest Ke component in use or the environment's largest radiance.
double maxEmittedRadiance(const Scene& scene);

// K_eps for a loaded scene, from its summary's largest albedo and maxEmittedRadiance: what
// `--epsilon` and the viewer's epsilon control use. Throws strata::Error saying why no finite
// depth bounds the error: point lights (a delta light has no radiance bound) or a largest
// albedo >= 1.
TruncationChoice chooseSceneTruncationDepth(double epsilon, const Scene& scene);

}  // namespace strata
