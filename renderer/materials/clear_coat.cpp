#include "materials/clear_coat.h"

#include <algorithm>
#include <glm/geometric.hpp>

#include "materials/fresnel.h"
#include "materials/layer_mixture.h"
#include "util/components.h"

namespace strata {
glm::vec3 CoatLayer::albedo(float mu) const {
    mu = std::max(mu, 0.0f);
    if (!lobe) return weight * schlickFresnel(f0, mu);
    const glm::vec2 e = lobe->albedo.albedo(mu);
    return weight * (f0 * e.x + (glm::vec3(1.0f) - f0) * e.y);
}

template <class Base>
std::pair<glm::vec3, glm::vec3> Coated<Base>::inCoatFrame(const glm::vec3& wo, const glm::vec3& wi) const {
    if (!tilted()) return {wo, wi};
    const Frame coat = Frame::fromNormal(axis_);
    return {coat.toLocal(wo), coat.toLocal(wi)};
}

template <class Base>
float Coated<Base>::coatProbability(const glm::vec3& wo, float coatCosine) const {
    // A tilted coat seen from below its own plane reflects nothing there.
    if (!(coatCosine > 0.0f)) return 0.0f;
    const glm::vec3 coat = coat_.albedo(coatCosine);
    const float c = meanComponent(coat);
    const float b = meanComponent((glm::vec3(1.0f) - coat) * base_.albedo(wo));
    if (!(b > 0.0f)) return 1.0f;
    // Both keep some probability so that the mixture's density covers each.
    return std::clamp(c / (c + b), 0.05f, 0.95f);
}

template <class Base>
glm::vec3 Coated<Base>::albedo(const glm::vec3& wo) const {
    const glm::vec3 coat = coat_.albedo(inCoatFrame(wo, wo).first.z);
    return coat + (glm::vec3(1.0f) - coat) * base_.albedo(wo);
}

template <class Base>
glm::vec3 Coated<Base>::roughCoat(const glm::vec3& wo, const glm::vec3& wi) const {
    if (!coat_.lobe) return glm::vec3(0.0f);
    const glm::vec3 h = glm::normalize(wo + wi);
    return coat_.weight * schlickFresnel(coat_.f0, glm::dot(wo, h)) * coat_.lobe->distribution.reflectance(wo, wi);
}

template <class Base>
glm::vec3 Coated<Base>::evaluate(const glm::vec3& wo, const glm::vec3& wi, TransportMode mode) const {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return glm::vec3(0.0f);
    const auto [coatWo, coatWi] = inCoatFrame(wo, wi);
    const glm::vec3 through = (glm::vec3(1.0f) - coat_.albedo(coatWo.z)) * (glm::vec3(1.0f) - coat_.albedo(coatWi.z));
    // The coat's lobe projected on its own normal (1 untilted).
    const float projection = coatWi.z == wi.z ? 1.0f : coatWi.z / wi.z;
    return roughCoat(coatWo, coatWi) * projection + through * base_.evaluate(wo, wi, mode);
}

template <class Base>
float Coated<Base>::pdf(const glm::vec3& wo, const glm::vec3& wi, DiffuseWarp warp) const {
    if (wo.z <= 0.0f || wi.z <= 0.0f) return 0.0f;
    const auto [coatWo, coatWi] = inCoatFrame(wo, wi);
    const float p = coatProbability(wo, coatWo.z);
    float density = (1.0f - p) * base_.pdf(wo, wi, warp);
    // Densities of directions: the same in the coat's frame as in the local one.
    if (coat_.lobe) density += p * coat_.lobe->distribution.reflectionPdf(coatWo, coatWi);
    return density;
}

template <class Base>
std::optional<BsdfSample> Coated<Base>::sample(const glm::vec3& wo, const BsdfNumbers& numbers,
                                               TransportMode mode) const {
    if (!(wo.z > 0.0f)) return std::nullopt;
    const bool tilted = this->tilted();
    const Frame coat = tilted ? Frame::fromNormal(axis_) : Frame{};
    const glm::vec3 coatWo = tilted ? coat.toLocal(wo) : wo;
    const float p = coatProbability(wo, coatWo.z);
    glm::vec3 wi;
    int stratum = -1;
    BsdfFlags lobe = kReflection | kGlossy;
    if (numbers.lobeChoice < p) {
        if (!coat_.lobe) {
            // The smooth coat's mirror direction: a delta, weighted by itself alone.
            wi = tilted ? coat.toWorld(reflectLocal(coatWo)) : reflectLocal(wo);
            if (wi.z <= 0.0f) return std::nullopt;
            const glm::vec3 reflectance = coat_.albedo(coatWo.z);
            return BsdfSample{wi, reflectance / wi.z, p, reflectance / p, kReflection | kSpecular, 1.0f, -1};
        }
        const glm::vec3 h = coat_.lobe->distribution.sampleVisibleNormal(coatWo, numbers.lobePoint);
        glm::vec3 coatWi = reflect(coatWo, h);
        if (coatWi.z <= 0.0f) return std::nullopt;
        coatWi = glm::normalize(coatWi);
        wi = tilted ? coat.toWorld(coatWi) : coatWi;
        if (wi.z <= 0.0f) return std::nullopt;
    } else {
        const auto s = base_.sample(wo, baseNumbers(numbers, p), mode);
        if (!s) return std::nullopt;
        if (isSpecular(s->flags)) {
            // A delta of the base (a mirror under the coat): its weight through the coat.
            const float coatCosine = tilted ? coat.toLocal(s->wi).z : s->wi.z;
            const glm::vec3 through =
                (glm::vec3(1.0f) - coat_.albedo(coatWo.z)) * (glm::vec3(1.0f) - coat_.albedo(coatCosine));
            return BsdfSample{s->wi, through * s->f, (1.0f - p) * s->pdf, through * s->weight / (1.0f - p),
                              s->flags, s->eta, -1};
        }
        wi = s->wi;
        lobe = s->flags;
        stratum = s->stratum;
    }
    return mixtureSample(*this, wo, wi, lobe, stratum, numbers.diffuse.warp, mode);
}

template class Coated<LayeredBsdf>;
template class Coated<SmoothConductor>;
template class Coated<Sheened>;

}  // namespace strata
