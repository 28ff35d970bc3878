#include "materials/sheen.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "materials/layer_mixture.h"
#include "sampling/hemisphere.h"
#include "util/components.h"
#include "util/constants.h"
#include "util/tbb_hand_off.h"

namespace strata {
namespace {

float mix(float atRough, float atSmooth, float t) { return atRough + (atSmooth - atRough) * t; }

// Estevez & Kulla's fit of log Lambda at x: a / (1 + b x^c) + d x + e.
float fittedLogLambda(const std::array<float, 5>& fit, float x) {
    return fit[0] / (1.0f + fit[1] * std::pow(x, fit[2])) + fit[3] * x + fit[4];
}

// E(mu) by quadrature over the half vector h, wi = reflect(wo, h), d(wi) = 4 (wo.h) d(h), with
// d(h) = d(cos theta_h) d(phi). The distribution peaks at the horizon (cos theta_h = 0) with a
// width of about sqrt(alpha), so cos theta_h = t^2 over a midpoint rule in t puts 30 nodes within
// 0.014 of it, sqrt of the smallest alpha; wo lies in the xz-plane, so phi in [0, pi] counts twice.
float integratedAlbedo(const SheenLobe& lobe, float mu) {
    const glm::vec3 wo(std::sqrt(std::max(0.0f, 1.0f - mu * mu)), 0.0f, mu);
    constexpr int kHeights = 256;
    constexpr int kAzimuths = 64;
    double sum = 0.0;
    for (int j = 0; j < kHeights; ++j) {
        const double t = (j + 0.5) / kHeights;
        const double c = t * t;
        const double dc = 2.0 * t / kHeights;
        const double s = std::sqrt(1.0 - c * c);
        for (int k = 0; k < kAzimuths; ++k) {
            const double phi = kPi * (k + 0.5) / kAzimuths;
            const glm::vec3 h(static_cast<float>(s * std::cos(phi)), static_cast<float>(s * std::sin(phi)),
                              static_cast<float>(c));
            const float cosOH = glm::dot(wo, h);
            if (!(cosOH > 0.0f)) continue;
            const glm::vec3 wi = 2.0f * cosOH * h - wo;
            if (!(wi.z > 0.0f)) continue;
            sum += static_cast<double>(lobe.reflectance(wo, wi)) * wi.z * 4.0 * cosOH * dc;
        }
    }
    return static_cast<float>(sum * 2.0 * kPi / kAzimuths);
}

}  // namespace

float sheenAlphaFromRoughness(float roughness) { return std::clamp(roughness * roughness, kMinSheenAlpha, 1.0f); }

SheenLobe::SheenLobe(float alpha) : alpha_(alpha) {
    // Estevez & Kulla's fit of log Lambda, its coefficients interpolated between alpha = 1 and
    // alpha = 0 by (1 - alpha)^2.
    const float t = (1.0f - alpha_) * (1.0f - alpha_);
    lambdaFit_ = {mix(21.5473f, 25.3245f, t), mix(3.82987f, 3.32435f, t), mix(0.19823f, 0.16801f, t),
                  mix(-1.97760f, -1.27393f, t), mix(-4.32054f, -4.85967f, t)};
    // The entries in parallel, as the GGX tables' (microfacet.cpp): a sheen roughness texture
    // builds kRoughnessLevels tables at load, 16 ms each on one thread.
    const auto computeEntries = [&](const tbb::blocked_range<int>& entries) {
        for (int i = entries.begin(); i != entries.end(); ++i) {
            // The first entry a little off the horizon, where wo itself has no solid angle.
            const float mu = std::max(static_cast<float>(i) / (kEntries - 1), 1e-3f);
            table_[static_cast<size_t>(i)] = integratedAlbedo(*this, mu);
        }
    };
    tbb::parallel_for(tbb::blocked_range<int>(0, kEntries, 2), handedOff(computeEntries), tbb::simple_partitioner());
    receiveHandOff();
}

float SheenLobe::density(const glm::vec3& h) const {
    const float sin2 = std::max(0.0f, 1.0f - h.z * h.z);
    return (2.0f + 1.0f / alpha_) * std::pow(sin2, 0.5f / alpha_) / (2.0f * kPi);
}

float SheenLobe::lambda(float mu) const {
    // Toward the normal the fit is mirrored about mu = 1/2, which softens the terminator.
    if (mu < 0.5f) return std::exp(fittedLogLambda(lambdaFit_, mu));
    return std::exp(2.0f * fittedLogLambda(lambdaFit_, 0.5f) - fittedLogLambda(lambdaFit_, 1.0f - mu));
}

float SheenLobe::reflectance(const glm::vec3& wo, const glm::vec3& wi) const {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
    const glm::vec3 h = glm::normalize(wo + wi);
    return density(h) / ((1.0f + lambda(wo.z) + lambda(wi.z)) * 4.0f * wo.z * wi.z);
}

float SheenLobe::albedo(float mu) const {
    const float x = std::clamp(mu, 0.0f, 1.0f) * (kEntries - 1);
    const int i = std::min(static_cast<int>(x), kEntries - 2);
    const float w = x - static_cast<float>(i);
    return table_[static_cast<size_t>(i)] * (1.0f - w) + table_[static_cast<size_t>(i + 1)] * w;
}

glm::vec3 SheenLayer::albedo(float mu) const { return colour * lobe->albedo(mu); }

float SheenLayer::passing(float mu) const { return 1.0f - maxComponent(colour) * lobe->albedo(mu); }

glm::vec3 Sheened::albedo(const glm::vec3& wo) const {
    return sheen_.albedo(wo.z) + sheen_.passing(wo.z) * base_.albedo(wo);
}

float Sheened::sheenProbability(const glm::vec3& wo) const {
    const float sheen = meanComponent(sheen_.albedo(wo.z));
    const float base = meanComponent(sheen_.passing(wo.z) * base_.albedo(wo));
    if (!(base > 0.0f)) return 1.0f;
    // Both keep some probability so that the mixture's density covers each.
    return std::clamp(sheen / (sheen + base), 0.05f, 0.95f);
}

glm::vec3 Sheened::evaluate(const glm::vec3& wo, const glm::vec3& wi, TransportMode mode) const {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return glm::vec3(0.0f);
    return sheen_.colour * sheen_.lobe->reflectance(wo, wi) +
           (sheen_.passing(wo.z) * sheen_.passing(wi.z)) * base_.evaluate(wo, wi, mode);
}

float Sheened::pdf(const glm::vec3& wo, const glm::vec3& wi, DiffuseWarp warp) const {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
    const float p = sheenProbability(wo);
    return p / kHemisphereSolidAngle + (1.0f - p) * base_.pdf(wo, wi, warp);
}

std::optional<BsdfSample> Sheened::sample(const glm::vec3& wo, const BsdfNumbers& numbers, TransportMode mode) const {
    if (!(wo.z > 0.0f)) return std::nullopt;
    const float p = sheenProbability(wo);
    glm::vec3 wi;
    BsdfFlags lobe = kReflection | kGlossy;
    int stratum = -1;  // the sheen's direction lies in no particular stratum
    if (numbers.lobeChoice < p) {
        wi = sampleUniformHemisphere(numbers.lobePoint);
    } else {
        const auto s = base_.sample(wo, baseNumbers(numbers, p), mode);
        if (!s) return std::nullopt;
        wi = s->wi;
        lobe = s->flags;
        stratum = s->stratum;
    }
    return mixtureSample(*this, wo, wi, lobe, stratum, numbers.diffuse.warp, mode);
}

}  // namespace strata
