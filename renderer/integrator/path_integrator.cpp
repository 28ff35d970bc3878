#include "integrator/path_integrator.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "util/constants.h"

namespace strata {
namespace {

bool isBlack(const glm::vec3& v) { return v.x == 0.0f && v.y == 0.0f && v.z == 0.0f; }

// Veach's power heuristic (exponent 2): the weight of the technique with density `own`.
float powerHeuristic(float own, float other) {
    const float a = own * own;
    const float b = other * other;
    return a > 0.0f ? a / (a + b) : 0.0f;
}

// A shadow ray toward a point on an emitter must stop short of the emitter's own surface: the
// segment is shortened by this fraction of its length (relative, so independent of scene scale).
constexpr float kShadowRayShortening = 1e-4f;

}  // namespace

PathIntegrator::PathIntegrator(const Scene& scene, const PathIntegratorSettings& settings)
    : scene_(scene), settings_(settings), emitters_(scene.mesh()) {
    const auto& materials = scene.mesh().materials;
    const bool lambertian = settings.lambertianFastPath && allLambertian(materials);
    for (const Material& material : materials) {
        if (lambertian) {
            lambertianBsdfs_.emplace_back(material);
        } else {
            layeredBsdfs_.emplace_back(material);
        }
    }
}

std::optional<std::string> whyBlack(const Scene& scene, const PathIntegratorSettings& settings) {
    if (scene.summary().emitters > 0) return std::nullopt;
    if (scene.mesh().pointLights.empty()) return "the scene has no emitter (no Ke > 0, no point lights)";
    if (!settings.nextEventEstimation) return "its only lights are point lights, which need --nee";
    if (settings.depth == 0) return "its only lights are point lights, which depth 0 never reaches";
    return std::nullopt;
}

glm::vec3 PathIntegrator::radiance(const Ray& ray, const PathSamples& samples,
                                   uint64_t& rays) const {
    return usesLambertianPath() ? trace(lambertianBsdfs_, ray, samples, rays)
                                : trace(layeredBsdfs_, ray, samples, rays);
}

template <class Bsdf>
glm::vec3 PathIntegrator::trace(const std::vector<Bsdf>& bsdfs, const Ray& cameraRay,
                                const PathSamples& samples, uint64_t& rays) const {
    const bool sampleEmitters = settings_.nextEventEstimation && !emitters_.empty();
    glm::vec3 radiance(0.0f);
    glm::vec3 weight(1.0f);  // product of f_r cos / pdf along the path so far
    Ray ray = cameraRay;
    // The density with which the last direction was sampled, for the MIS weight of the emission
    // it finds; 0 for the camera ray, whose emission no light sample could have found.
    float directionDensity = 0.0f;
    glm::vec3 previousPoint(0.0f);
    // A loop, not recursion: depth 10000 costs no stack.
    for (int bounce = 0;; ++bounce) {
        ++rays;
        const auto hit = scene_.intersect(ray);
        if (!hit) break;  // the path left the scene: nothing more arrives along it
        const uint32_t materialIndex = scene_.mesh().triangleMaterials[hit->triangle];
        const Material& material = scene_.mesh().materials[materialIndex];
        const float cosEmitter = -glm::dot(hit->normal, ray.direction);
        const bool frontFacing = cosEmitter > 0.0f;
        // Emission is one-sided: only the counter-clockwise (front) side emits.
        if (frontFacing && !isBlack(material.emission)) {
            float misWeight = 1.0f;
            if (sampleEmitters && directionDensity > 0.0f) {
                const glm::vec3 offset = hit->point - previousPoint;
                const float lightDensity =
                    emitters_.areaPdf(hit->triangle) * glm::dot(offset, offset) / cosEmitter;
                misWeight = powerHeuristic(directionDensity, lightDensity);
            }
            radiance += weight * material.emission * misWeight;
        }
        if (bounce == settings_.depth) break;

        const Bsdf& bsdf = bsdfs[materialIndex];
        if (bsdf.isBlack()) break;  // a black surface ends the path (its weight is zero)
        // Reflection is two-sided: the hemisphere is on the side the ray came from.
        SurfaceHit surface = *hit;
        if (!frontFacing) surface.normal = -surface.normal;
        const Frame frame = Frame::fromNormal(surface.normal);
        const glm::vec3 wo = frame.toLocal(-ray.direction);
        if (!(wo.z > 0.0f)) break;  // a ray exactly along the surface sees nothing of it
        // Light that reaches the camera after this vertex's reflection counts as bounce + 1
        // bounces, which the depth allows here.
        if (settings_.nextEventEstimation) {
            radiance += weight * pointLightRadiance(surface, frame, wo, bsdf, rays);
            if (sampleEmitters) {
                radiance += weight * emitterLight(surface, frame, wo, bsdf, samples, bounce, rays);
            }
        }
        const SampledDirection sampled =
            sampleDirection(settings_.sampler, samples, bounce, bsdf, wo);
        weight *= sampled.weight;
        if (isBlack(weight)) break;
        if (settings_.rouletteDepth >= 0 && bounce + 1 >= settings_.rouletteDepth) {
            const float survival = std::min(1.0f, std::max(std::max(weight.x, weight.y), weight.z));
            if (samples.roulette(bounce) >= survival) break;
            weight /= survival;
        }
        directionDensity = sampled.pdf;
        previousPoint = surface.point;
        const glm::vec3 direction = frame.toWorld(sampled.local);
        ray = Ray{offsetRayOrigin(surface, direction), direction};
    }
    return radiance;
}

template <class Bsdf>
glm::vec3 PathIntegrator::emitterLight(const SurfaceHit& surface, const Frame& frame,
                                       const glm::vec3& wo, const Bsdf& bsdf,
                                       const PathSamples& samples, int bounce,
                                       uint64_t& rays) const {
    const EmitterSample light = emitters_.sample(samples.lightSample(bounce));
    const glm::vec3 toLight = light.point - surface.point;
    const float distanceSquared = glm::dot(toLight, toLight);
    if (!(distanceSquared > 0.0f)) return glm::vec3(0.0f);
    const float distance = std::sqrt(distanceSquared);
    const glm::vec3 direction = toLight / distance;
    const float cosEmitter = -glm::dot(light.normal, direction);
    if (!(cosEmitter > 0.0f)) return glm::vec3(0.0f);  // the point shows its back (one-sided)
    const glm::vec3 wi = frame.toLocal(direction);
    if (!(wi.z > 0.0f)) return glm::vec3(0.0f);  // behind the surface (or on it)
    const glm::vec3 f = bsdf.evaluate(wo, wi);
    if (isBlack(f)) return glm::vec3(0.0f);
    ++rays;
    const glm::vec3 origin = offsetRayOrigin(surface, direction);
    const float reach = glm::length(light.point - origin) * (1.0f - kShadowRayShortening);
    if (scene_.occluded(Ray{origin, direction}, reach)) return glm::vec3(0.0f);
    // The light sample's density per solid angle at the shading point.
    const float lightDensity = light.areaPdf * distanceSquared / cosEmitter;
    const float misWeight =
        powerHeuristic(lightDensity, directionPdf(settings_.sampler, bsdf, wo, wi));
    return f * light.emission * (wi.z * misWeight / lightDensity);
}

template <class Bsdf>
glm::vec3 PathIntegrator::pointLightRadiance(const SurfaceHit& surface, const Frame& frame,
                                             const glm::vec3& wo, const Bsdf& bsdf,
                                             uint64_t& rays) const {
    glm::vec3 reflected(0.0f);
    for (const PointLight& light : scene_.mesh().pointLights) {
        const glm::vec3 toLight = light.position - surface.point;
        const float distanceSquared = glm::dot(toLight, toLight);
        const glm::vec3 direction = toLight / std::sqrt(distanceSquared);
        const glm::vec3 wi = frame.toLocal(direction);
        if (!(wi.z > 0.0f)) continue;  // behind the surface (or on it)
        ++rays;
        const glm::vec3 origin = offsetRayOrigin(surface, direction);
        if (scene_.occluded(Ray{origin, direction}, glm::length(light.position - origin))) continue;
        reflected += bsdf.evaluate(wo, wi) * light.intensity * (wi.z / distanceSquared);
    }
    return reflected;
}

}  // namespace strata
