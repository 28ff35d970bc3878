#pragma once
// The choice of estimator for the hemisphere integral at each bounce: which direction a path takes
// and the factor cos(theta) / pdf it carries. Both samplers have the same marginal density
// 1/(2 pi), so their paths carry the same weights and a pass (24 paths per pixel) costs the same:
//   uniform  - the paper's xi_N: i.i.d. uniform directions (section 3);
//   strata24 - the paper's xi*_N: one direction per stratum per pass, pdf 12/pi inside the
//              stratum; the 1/24 chance of each stratum within the pass makes each path's weight
//              2 pi f cos = 24 * (pi/12) f cos, i.e. the paper's pi/(12 N_i) once the pass's 24
//              paths are averaged (section 3), and the product over bounces is section 4's
//              (pi/12)^k per cell.
#include <optional>
#include <string>
#include <string_view>
#include <glm/vec3.hpp>

#include "path_samples.h"

namespace strata {

enum class SamplerKind { Uniform, Strata24 };

std::optional<SamplerKind> parseSamplerKind(std::string_view name);
std::string_view samplerName(SamplerKind kind);
// "uniform|strata24", for option help and error messages.
std::string samplerNames();

struct SampledDirection {
    glm::vec3 local;    // unit direction in the surface's local frame, z >= 0
    float cosOverPdf;   // cos(theta) / pdf(direction)
    int stratum;        // 0..23, or -1 when the sampler does not stratify
};

SampledDirection sampleDirection(SamplerKind kind, const PathSamples& samples, int bounce);

}  // namespace strata
