#pragma once
// The choice of estimator for the scattering integral at each bounce: which direction a path takes,
// its density and the weight f_r cos(theta) / pdf it carries. Densities are marginal over the
// path's stratum: the schedule (stratum_schedule.h) gives every path each stratum with
// probability 1/24, so a direction in stratum i with conditional density p_i has density p_i / 24.
//   uniform         - the paper's xi_N: i.i.d. uniform directions, pdf 1 / (2 pi) (section 3);
//   strata24        - the paper's xi*_N: one direction per stratum per pass, uniform in it
//                     (pdf 12/pi, marginally 1 / (2 pi)); the path's weight 2 pi f cos is
//                     24 (pi/12) f cos, the paper's pi / (12 N_i) once a pass's 24 paths are
//                     averaged, and the product over bounces is section 4's (pi/12)^k per cell;
//   cosine          - i.i.d. cosine-weighted directions, pdf cos / pi;
//   strata24-cosine - one direction per stratum per pass with density cos / PSA_i inside it
//                     (strata24_cosine.h), weight 24 PSA_i f: each stratum weighted by its exact
//                     projected solid angle;
//   strata24-qmc    - strata24 with each stratum's points taken from its own Owen-scrambled
//                     Sobol' sequence (PathSamples::stratumSequencePoint), so successive passes
//                     refine every stratum (the paper's future work);
//   strata24-cosine-qmc - strata24-cosine with the points of strata24-qmc: cosine-weighted inside
//                     each stratum, each stratum refined by its Sobol' sequence;
//   strata24-bsdf   - the flagship: for the diffuse layer one direction per pass in each of the
//                     24 strata carried onto the cosine-weighted hemisphere (strata24_warped.h:
//                     every warped stratum holds 1/24 of the cosine measure, so the weight is
//                     f pi, as cosine sampling's), refined by the points of strata24-qmc; the
//                     specular layer by GGX visible normals, chosen as bsdf chooses its lobe;
//                     densities are the mixture's, so it is unbiased for every material;
//   bsdf            - importance sampling of the whole material (material.h: cosine for the
//                     Lambertian layer, GGX visible normals for the specular one).
// All are unbiased for every path, so a partial pass is an unbiased estimate.
#include <optional>
#include <string>
#include <string_view>
#include <glm/vec3.hpp>

#include "materials/layered_bsdf.h"
#include "sampling/path_samples.h"

namespace strata {

enum class SamplerKind { Uniform, Strata24, Cosine, Strata24Cosine, Strata24Qmc, Strata24CosineQmc, Strata24Bsdf, Bsdf };

std::optional<SamplerKind> parseSamplerKind(std::string_view name);
std::string_view samplerName(SamplerKind kind);
// "uniform|strata24|...", for option help and error messages.
std::string samplerNames();
// Whether the sampler gives each pass one path per stratum, so that a pass's 24 paths are not
// independent and a pixel's error must be judged from the spread of its pass means.
bool stratifies(SamplerKind kind);

struct SampledDirection {
    glm::vec3 local;   // unit direction in the surface's local frame, z >= 0
    float pdf;         // marginal density of `local` under the sampler (for MIS); 0 if no sample
    glm::vec3 weight;  // f_r(wo, local) cos(theta) / pdf; 0 when the sample is lost (below the
                       // surface), which still counts as a sample
    int stratum;       // 0..23, or -1 when the sampler does not stratify (for strata24-bsdf's
                       // diffuse layer the direction lies in the stratum's warped image)
};

// The numbers a sampler draws at `bounce` whatever the surface: the path's stratum (-1 for a
// sampler that does not stratify) and the point that it maps onto the hemisphere, or into that
// stratum. Apart from sampleDirection so that a path tracer can draw them before it works out the
// surface: their arithmetic then overlaps that work instead of waiting for it.
PathSamples::StratumPoint directionNumbers(SamplerKind kind, const PathSamples& samples, int bounce);

// The direction of bounce `bounce` of the path `samples`, whose directionNumbers are `numbers`,
// at a surface with material `bsdf`, seen from the local direction `wo` (z > 0).
SampledDirection sampleDirection(SamplerKind kind, const PathSamples::StratumPoint& numbers,
                                 const PathSamples& samples, int bounce, const LayeredBsdf& bsdf,
                                 const glm::vec3& wo);
// The same, drawing the numbers itself.
SampledDirection sampleDirection(SamplerKind kind, const PathSamples& samples, int bounce,
                                 const LayeredBsdf& bsdf, const glm::vec3& wo);

// The direction alone, as sampled at a white Lambertian surface seen head-on (where the bsdf
// sampler is the cosine sampler): for `strata samples` and tests of the partition.
SampledDirection sampleDirection(SamplerKind kind, const PathSamples& samples, int bounce);

// The marginal density with which sampleDirection would produce the local direction `wi`, the
// other technique's density in multiple importance sampling with light sampling.
float directionPdf(SamplerKind kind, const LayeredBsdf& bsdf, const glm::vec3& wo, const glm::vec3& wi);

}  // namespace strata
