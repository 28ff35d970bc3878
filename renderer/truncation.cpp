#include "truncation.h"

#include <cmath>

#include "error.h"

namespace strata {

double truncationBound(int depth, double maxAlbedo, double maxEmission) {
    return maxEmission * std::pow(maxAlbedo, depth + 1) / (1.0 - maxAlbedo);
}

std::optional<TruncationChoice> chooseTruncationDepth(double epsilon, double maxAlbedo,
                                                      double maxEmission) {
    if (!(epsilon > 0.0)) throw Error("--epsilon: must be positive");
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

}  // namespace strata
