#pragma once
// The choice of estimator for the scattering integral at each bounce, as `--sampler` names it:
// which point set a path's bounce draws and which warp (diffuse_warp.h) carries it onto the
// hemisphere of a BSDF's diffuse lobe. Every other lobe (glossy, specular, transmission) samples
// itself the same way under every sampler (materials/bsdf.h), so two samplers differ only where
// the paper's comparison is made: in the directions of the diffuse lobe.
//   uniform         - the paper's xi_N: i.i.d. uniform directions (section 3);
//   strata24        - the paper's xi*_N: one direction per stratum per pass, uniform in it; the
//                     path's weight 2 pi f cos is 24 (pi/12) f cos, the paper's pi / (12 N_i) once
//                     a pass's 24 paths are averaged, and the product over bounces is section 4's
//                     (pi/12)^k per cell;
//   cosine          - i.i.d. cosine-weighted directions;
//   strata24-cosine - one direction per stratum per pass with density cos / PSA_i inside it
//                     (strata24_cosine.h): each stratum weighted by its projected solid angle;
//   strata24-qmc    - strata24 with each stratum's points from its own Owen-scrambled Sobol'
//                     sequence (PathSamples::stratumSequencePoint), so successive passes refine
//                     every stratum (the paper's future work);
//   strata24-cosine-qmc - strata24-cosine with the points of strata24-qmc;
//   strata24-bsdf   - the flagship: one direction per pass in each of the 24 strata carried onto
//                     the cosine-weighted hemisphere (strata24_warped.h), refined by the points of
//                     strata24-qmc;
//   bsdf            - the BSDF's own importance sampling with independent points: its diffuse
//                     lobe by cosine, as `cosine`.
// All are unbiased for every path, so a partial pass is an unbiased estimate.
#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <glm/vec3.hpp>

#include "sampling/diffuse_warp.h"
#include "sampling/path_samples.h"

namespace strata {

enum class SamplerKind { Uniform, Strata24, Cosine, Strata24Cosine, Strata24Qmc, Strata24CosineQmc, Strata24Bsdf, Bsdf };
// Every kind, in the enum's order.
inline constexpr std::array kSamplerKinds{
    SamplerKind::Uniform,     SamplerKind::Strata24,          SamplerKind::Cosine,       SamplerKind::Strata24Cosine,
    SamplerKind::Strata24Qmc, SamplerKind::Strata24CosineQmc, SamplerKind::Strata24Bsdf, SamplerKind::Bsdf};

// The points a sampler draws for the diffuse lobe at a bounce: independent uniform points (with
// the schedule's stratum for a stratified warp), or each stratum's Sobol' sequence over the passes.
enum class PointSet { Independent, StratumSequence };

struct SamplerChoice {
    PointSet points;
    DiffuseWarp warp;
};

// What each name means: its point set and warp (the one table of the eight names).
SamplerChoice samplerChoice(SamplerKind kind);

std::optional<SamplerKind> parseSamplerKind(std::string_view name);
std::string_view samplerName(SamplerKind kind);
// "uniform|strata24|...", for option help and error messages.
std::string samplerNames();
// Whether the sampler gives each pass one path per stratum, so that a pass's 24 paths are not
// independent and a pixel's error must be judged from the spread of its pass means.
bool stratifies(SamplerKind kind);

// The numbers the sampler draws for the diffuse lobe at `bounce` whatever the surface: the warp,
// the path's stratum (-1 for a warp that does not stratify) and the point. Apart from the BSDF's
// sample so that a path tracer can draw them before it works out the surface: their arithmetic
// then overlaps that work instead of waiting for it.
DiffuseSampling diffuseNumbers(SamplerKind kind, const PathSamples& samples, int bounce);

struct SampledDirection {
    glm::vec3 local;  // unit direction in the local frame, z >= 0
    int stratum;      // 0..23, or -1 when the sampler does not stratify (for strata24-bsdf the
                      // direction lies in the stratum's warped image)
};

// The direction the sampler gives the diffuse lobe at `bounce` of the path `samples`: for
// `strata samples` and tests of the partition.
SampledDirection sampleDirection(SamplerKind kind, const PathSamples& samples, int bounce);

}  // namespace strata
