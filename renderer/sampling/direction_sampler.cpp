#include "sampling/direction_sampler.h"

#include "sampling/hemisphere.h"
#include "util/name_table.h"
#include "sampling/strata24.h"
#include "sampling/strata24_cosine.h"
#include "sampling/strata24_warped.h"

namespace strata {
namespace {
constexpr NameTable<SamplerKind, 8> kSamplers{{{{"uniform", SamplerKind::Uniform},
                                                {"strata24", SamplerKind::Strata24},
                                                {"cosine", SamplerKind::Cosine},
                                                {"strata24-cosine", SamplerKind::Strata24Cosine},
                                                {"strata24-qmc", SamplerKind::Strata24Qmc},
                                                {"strata24-cosine-qmc", SamplerKind::Strata24CosineQmc},
                                                {"strata24-bsdf", SamplerKind::Strata24Bsdf},
                                                {"bsdf", SamplerKind::Bsdf}}}};

// A direction from a hemisphere sampler whose cos / pdf is known in closed form: the weight is
// f * (cos / pdf) with no pdf division, so a Lambertian weight is exactly Kd * (pi / pi).
SampledDirection hemisphereSample(const LayeredBsdf& bsdf, const glm::vec3& wo,
                                  const glm::vec3& wi, float cosOverPdf, int stratum) {
    const float pdf = wi.z > 0.0f ? wi.z / cosOverPdf : 0.0f;
    return {wi, pdf, bsdf.evaluate(wo, wi) * cosOverPdf, stratum};
}

// The cosine-weighted stratum's density of `wi` marginal over the path's stratum (1/24 each):
// cos / (24 PSA_i) for the stratum i that holds it.
float stratumCosinePdf(const glm::vec3& wi) {
    return wi.z / static_cast<float>(kStrataCount * stratumProjectedSolidAngle(classifyStratum(wi)));
}

// strata24-bsdf's density of `wi`: the warped strata (cosine-weighted, marginally over the path's
// stratum) with probability 1 - pSpecular, the specular lobe with pSpecular (the BSDF's
// specularProbability(wo), which the caller has).
float strataBsdfMixturePdf(const LayeredBsdf& bsdf, const glm::vec3& wo, const glm::vec3& wi, float pSpecular) {
    const float diffuse = (1.0f - pSpecular) * cosineHemispherePdf(wi);
    return pSpecular > 0.0f ? diffuse + pSpecular * bsdf.specularPdf(wo, wi) : diffuse;
}

// A direction of strata24-bsdf's mixture (the warped strata and the specular lobe), weighted by the
// mixture's density; `stratum` is -1 for a specular direction.
SampledDirection strataBsdfMixtureSample(const LayeredBsdf& bsdf, const glm::vec3& wo, const glm::vec3& d,
                                         float pSpecular, int stratum) {
    const float pdf = strataBsdfMixturePdf(bsdf, wo, d, pSpecular);
    if (!(pdf > 0.0f)) return {d, 0.0f, glm::vec3(0.0f), stratum};
    return {d, pdf, bsdf.evaluate(wo, d) * (d.z / pdf), stratum};
}

// A cosine-weighted direction in stratum `stratum` from the point `u`: weight 24 PSA_i f.
SampledDirection cosineStratumSample(const LayeredBsdf& bsdf, const glm::vec3& wo, int stratum, glm::vec2 u) {
    const glm::vec3 d = sampleStratumCosine(stratum, u);
    const auto cosOverPdf = static_cast<float>(kStrataCount * stratumProjectedSolidAngle(stratum));
    return hemisphereSample(bsdf, wo, d, cosOverPdf, stratum);
}

}  // namespace

std::optional<SamplerKind> parseSamplerKind(std::string_view name) { return kSamplers.parse(name); }
std::string_view samplerName(SamplerKind kind) { return kSamplers.name(kind); }
std::string samplerNames() { return kSamplers.joined(); }

bool stratifies(SamplerKind kind) {
    return kind == SamplerKind::Strata24 || kind == SamplerKind::Strata24Cosine ||
           kind == SamplerKind::Strata24Qmc || kind == SamplerKind::Strata24CosineQmc ||
           kind == SamplerKind::Strata24Bsdf;
}

PathSamples::StratumPoint directionNumbers(SamplerKind kind, const PathSamples& samples, int bounce) {
    switch (kind) {
        // The paper's estimators: a plain random point in the stratum.
        case SamplerKind::Strata24:
        case SamplerKind::Strata24Cosine: return {samples.stratum(bounce), samples.bouncePoint(bounce)};
        // Refined pass by pass by the stratum's low-discrepancy sequence.
        case SamplerKind::Strata24Qmc:
        case SamplerKind::Strata24CosineQmc:
        case SamplerKind::Strata24Bsdf: return samples.stratumSequencePoint(bounce);
        case SamplerKind::Uniform:
        case SamplerKind::Cosine:
        case SamplerKind::Bsdf: break;
    }
    return {-1, samples.bouncePoint(bounce)};
}

SampledDirection sampleDirection(SamplerKind kind, const PathSamples& samples, int bounce,
                                 const LayeredBsdf& bsdf, const glm::vec3& wo) {
    return sampleDirection(kind, directionNumbers(kind, samples, bounce), samples, bounce, bsdf, wo);
}

SampledDirection sampleDirection(SamplerKind kind, const PathSamples::StratumPoint& numbers,
                                 const PathSamples& samples, int bounce, const LayeredBsdf& bsdf,
                                 const glm::vec3& wo) {
    const auto [id, u] = numbers;
    switch (kind) {
        case SamplerKind::Uniform: {
            const glm::vec3 d = sampleUniformHemisphere(u);
            return hemisphereSample(bsdf, wo, d, d.z * kHemisphereSolidAngle, -1);
        }
        case SamplerKind::Strata24:
        case SamplerKind::Strata24Qmc: {
            const glm::vec3 d = sampleStratum(id, u);
            return hemisphereSample(bsdf, wo, d, d.z * kHemisphereSolidAngle, id);
        }
        case SamplerKind::Cosine: {
            const glm::vec3 d = sampleCosineHemisphere(u);
            return hemisphereSample(bsdf, wo, d, kPi, -1);
        }
        case SamplerKind::Strata24Cosine:
        case SamplerKind::Strata24CosineQmc: return cosineStratumSample(bsdf, wo, id, u);
        case SamplerKind::Strata24Bsdf: {
            const float pSpecular = bsdf.specularProbability(wo);
            // The specular lobe's direction lies in no particular stratum.
            if (pSpecular > 0.0f && samples.lobeChoice(bounce) < pSpecular) {
                const auto specular = bsdf.sampleSpecular(wo, samples.bouncePoint(bounce));
                if (!specular) return {glm::vec3(0.0f, 0.0f, 1.0f), 0.0f, glm::vec3(0.0f), -1};
                return strataBsdfMixtureSample(bsdf, wo, *specular, pSpecular, -1);
            }
            const glm::vec3 d = sampleWarpedStratum(id, u);
            // A Lambertian surface: cosine sampling's exact weight.
            if (pSpecular == 0.0f) return hemisphereSample(bsdf, wo, d, kPi, id);
            return strataBsdfMixtureSample(bsdf, wo, d, pSpecular, id);
        }
        case SamplerKind::Bsdf: {
            const auto s = bsdf.sample(wo, u, samples.lobeChoice(bounce));
            if (!s) return {glm::vec3(0.0f, 0.0f, 1.0f), 0.0f, glm::vec3(0.0f), -1};
            return {s->direction, s->pdf, s->weight, -1};
        }
    }
    return {glm::vec3(0.0f, 0.0f, 1.0f), 0.0f, glm::vec3(0.0f), -1};
}

SampledDirection sampleDirection(SamplerKind kind, const PathSamples& samples, int bounce) {
    const LayeredBsdf white(glm::vec3(1.0f), glm::vec3(0.0f), nullptr);
    return sampleDirection(kind, samples, bounce, white, glm::vec3(0.0f, 0.0f, 1.0f));
}

float directionPdf(SamplerKind kind, const LayeredBsdf& bsdf, const glm::vec3& wo, const glm::vec3& wi) {
    if (wi.z <= 0.0f) return 0.0f;
    switch (kind) {
        case SamplerKind::Uniform:
        case SamplerKind::Strata24:
        case SamplerKind::Strata24Qmc: return 1.0f / kHemisphereSolidAngle;
        case SamplerKind::Cosine: return cosineHemispherePdf(wi);
        case SamplerKind::Strata24Cosine:
        case SamplerKind::Strata24CosineQmc: return stratumCosinePdf(wi);
        case SamplerKind::Strata24Bsdf: return strataBsdfMixturePdf(bsdf, wo, wi, bsdf.specularProbability(wo));
        case SamplerKind::Bsdf: return bsdf.pdf(wo, wi);
    }
    return 0.0f;
}

}  // namespace strata
