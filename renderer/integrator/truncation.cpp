#include "integrator/truncation.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "util/error.h"
#include "scene/scene.h"

namespace strata {

double truncationBound(int depth, double maxAlbedo, double maxEmission) {
    return maxEmission * std::pow(maxAlbedo, depth + 1) / (1.0 - maxAlbedo);
}

std::optional<TruncationChoice> chooseTruncationDepth(double epsilon, double maxAlbedo,
                                                      double maxEmission) {
    if (!(epsilon > 0.0)) throw Error("the truncation error epsilon must be positive");
    if (maxAlbedo < 0.0 || maxEmission < 0.0) throw Error("albedo and emission must be non-negative");
    if (maxAlbedo >= 1.0) return std::nullopt;
    if (maxAlbedo == 0.0 || maxEmission == 0.0) {
        return TruncationChoice{0, truncationBound(0, maxAlbedo, maxEmission)};
    }
    // The closed form gives the answer up to rounding; step to the exact smallest K.
    int depth = static_cast<int>(
        std::max(0.0, std::ceil(std::log(epsilon * (1.0 - maxAlbedo) / maxEmission) /
                                std::log(maxAlbedo)) - 1.0));
    while (depth > 0 && truncationBound(depth - 1, maxAlbedo, maxEmission) <= epsilon) --depth;
    while (truncationBound(depth, maxAlbedo, maxEmission) > epsilon) ++depth;
    return TruncationChoice{depth, truncationBound(depth, maxAlbedo, maxEmission)};
}

double maxEmittedRadiance(const Scene& scene) {
    // The environment is an emitter at infinity that reflects nothing, so the bound of notes
    // section 5.5 holds with its radiance in Le_max.
    return std::max<double>(scene.summary().maxEmission, scene.lights().maxRadianceAtInfinity());
}

TruncationChoice chooseSceneTruncationDepth(double epsilon, const Scene& scene) {
    const MeshData& mesh = scene.mesh();
    if (!mesh.pointLights.empty() || !mesh.spotLights.empty() || !mesh.directionalLights.empty()) {
        throw Error("point, spot and directional lights have no radiance bound");
    }
    const SceneSummary& summary = scene.summary();
    const auto choice = chooseTruncationDepth(epsilon, summary.maxAlbedo, maxEmittedRadiance(scene));
    if (!choice) {
        char reason[160];
        std::snprintf(reason, sizeof reason,
                      "the scene's largest albedo is %.3g >= 1, so no finite depth bounds the "
                      "truncation error",
                      static_cast<double>(summary.maxAlbedo));
        throw Error(reason);
    }
    return *choice;
}

}  // namespace strata
