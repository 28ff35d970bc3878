#pragma once
// The maps that carry a point of [0,1)^2 (and, for the stratified ones, the path's stratum) onto
// the hemisphere above a surface, for a BSDF's diffuse lobe: the estimators the paper compares and
// the ones Strata adds (direction_sampler.h names them). Each map's cos(theta) / pdf is known in
// closed form, so a lobe's weight f cos / pdf needs no division by the density:
//   Uniform        - the paper's xi_N, p = 1 / (2 pi) (section 3): cos / p = 2 pi cos;
//   Strata24       - the paper's xi*_N: uniform inside stratum i (p_i = 12 / pi), marginally
//                    1 / (2 pi) since the schedule gives each stratum with probability 1/24;
//   Cosine         - p = cos / pi: cos / p = pi;
//   Strata24Cosine - cos / PSA_i inside stratum i (strata24_cosine.h), marginally
//                    cos / (24 PSA_i): cos / p = 24 PSA_i;
//   WarpedStrata   - the strata carried onto the cosine measure (strata24_warped.h): each warped
//                    stratum holds 1/24 of it, marginally cos / pi, so cos / p = pi.
// Densities are per unit solid angle and marginal over the path's stratum, as multiple importance
// sampling needs them.
#include <string_view>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace strata {

enum class DiffuseWarp { Uniform, Strata24, Cosine, Strata24Cosine, WarpedStrata };

// Whether the warp places the path's direction in its stratum (one per stratum per pass).
constexpr bool stratifies(DiffuseWarp warp) {
    return warp == DiffuseWarp::Strata24 || warp == DiffuseWarp::Strata24Cosine ||
           warp == DiffuseWarp::WarpedStrata;
}

// What a diffuse lobe is handed: the warp, the path's stratum at this bounce (-1 for a warp that
// does not stratify) and the point the warp maps.
struct DiffuseSampling {
    DiffuseWarp warp;
    int stratum;
    glm::vec2 point;
};

struct WarpedDirection {
    glm::vec3 direction;  // unit, z >= 0
    float cosOverPdf;     // cos(theta) / (marginal density of `direction`)
};

WarpedDirection warpDiffuse(const DiffuseSampling& sampling);

// The marginal density with which warpDiffuse gives the direction `wi` (0 below the surface).
float diffuseWarpPdf(DiffuseWarp warp, const glm::vec3& wi);

}  // namespace strata
