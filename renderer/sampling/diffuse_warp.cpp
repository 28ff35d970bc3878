#include "sampling/diffuse_warp.h"

#include "sampling/hemisphere.h"
#include "sampling/strata24.h"
#include "sampling/strata24_cosine.h"
#include "sampling/strata24_warped.h"

namespace strata {
namespace {

// 24 PSA_i, the stratum-cosine map's cos / pdf in stratum i.
float stratumCosineCosOverPdf(int stratum) {
    return static_cast<float>(kStrataCount * stratumProjectedSolidAngle(stratum));
}

}  // namespace

WarpedDirection warpDiffuse(const DiffuseSampling& s) {
    switch (s.warp) {
        case DiffuseWarp::Uniform: {
            const glm::vec3 d = sampleUniformHemisphere(s.point);
            return {d, d.z * kHemisphereSolidAngle};
        }
        case DiffuseWarp::Strata24: {
            const glm::vec3 d = sampleStratum(s.stratum, s.point);
            return {d, d.z * kHemisphereSolidAngle};
        }
        case DiffuseWarp::Cosine: return {sampleCosineHemisphere(s.point), kPi};
        case DiffuseWarp::Strata24Cosine:
            return {sampleStratumCosine(s.stratum, s.point), stratumCosineCosOverPdf(s.stratum)};
        case DiffuseWarp::WarpedStrata: return {sampleWarpedStratum(s.stratum, s.point), kPi};
    }
    return {glm::vec3(0.0f, 0.0f, 1.0f), kPi};
}

float diffuseWarpPdf(DiffuseWarp warp, const glm::vec3& wi) {
    if (wi.z <= 0.0f) return 0.0f;
    switch (warp) {
        case DiffuseWarp::Uniform:
        case DiffuseWarp::Strata24: return 1.0f / kHemisphereSolidAngle;
        case DiffuseWarp::Cosine:
        case DiffuseWarp::WarpedStrata: return cosineHemispherePdf(wi);
        case DiffuseWarp::Strata24Cosine: return wi.z / stratumCosineCosOverPdf(classifyStratum(wi));
    }
    return 0.0f;
}

}  // namespace strata
