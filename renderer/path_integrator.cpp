#include "path_integrator.h"

#include <cmath>
#include <glm/geometric.hpp>

#include "constants.h"
#include "frame.h"

namespace strata {

std::optional<std::string> whyBlack(const Scene& scene, const PathIntegratorSettings& settings) {
    if (scene.summary().emitters > 0) return std::nullopt;
    if (scene.mesh().pointLights.empty()) return "the scene has no emitter (no Ke > 0, no point lights)";
    if (!settings.nextEventEstimation) return "its only lights are point lights, which need --nee";
    if (settings.depth == 0) return "its only lights are point lights, which depth 0 never reaches";
    return std::nullopt;
}

glm::vec3 PathIntegrator::radiance(const Ray& cameraRay, const PathSamples& samples,
                                   uint64_t& rays) const {
    glm::vec3 radiance(0.0f);
    glm::vec3 weight(1.0f);  // product of f_r cos / pdf along the path so far
    Ray ray = cameraRay;
    // A loop, not recursion: depth 10000 costs no stack.
    for (int bounce = 0;; ++bounce) {
        ++rays;
        const auto hit = scene_.intersect(ray);
        if (!hit) break;  // the path left the scene: nothing more arrives along it
        const Material& material = scene_.material(hit->triangle);
        const bool frontFacing = glm::dot(hit->normal, ray.direction) < 0.0f;
        // Emission is one-sided: only the counter-clockwise (front) side emits.
        if (frontFacing) radiance += weight * material.emission;
        if (bounce == settings_.depth) break;

        // Lambertian f_r = Kd / pi; a black surface ends the path (its weight is zero).
        weight *= material.diffuse * (1.0f / kPi);
        if (weight.x == 0.0f && weight.y == 0.0f && weight.z == 0.0f) break;
        // Reflection is two-sided: the hemisphere is on the side the ray came from.
        SurfaceHit surface = *hit;
        if (!frontFacing) surface.normal = -surface.normal;
        // Light that reaches the camera after this vertex's reflection counts as bounce + 1
        // bounces, which the depth allows here.
        if (settings_.nextEventEstimation) radiance += weight * pointLightIrradiance(surface, rays);
        const SampledDirection sampled = sampleDirection(settings_.sampler, samples, bounce);
        weight *= sampled.cosOverPdf;
        const glm::vec3 direction = Frame::fromNormal(surface.normal).toWorld(sampled.local);
        ray = Ray{offsetRayOrigin(surface, direction), direction};
    }
    return radiance;
}

glm::vec3 PathIntegrator::pointLightIrradiance(const SurfaceHit& surface, uint64_t& rays) const {
    glm::vec3 irradiance(0.0f);
    for (const PointLight& light : scene_.mesh().pointLights) {
        const glm::vec3 toLight = light.position - surface.point;
        const float distanceSquared = glm::dot(toLight, toLight);
        const float distance = std::sqrt(distanceSquared);
        const glm::vec3 direction = toLight / distance;
        const float cosine = glm::dot(direction, surface.normal);
        if (!(cosine > 0.0f)) continue;  // behind the surface (or on it)
        ++rays;
        const glm::vec3 origin = offsetRayOrigin(surface, direction);
        if (scene_.occluded(Ray{origin, direction}, glm::length(light.position - origin))) continue;
        irradiance += light.intensity * (cosine / distanceSquared);
    }
    return irradiance;
}

}  // namespace strata
