#pragma once
// The path tracer: the Neumann series of the rendering equation truncated at recursion depth K
// (paper, section 4). The camera ray finds x_1; bounce j samples a direction on the hemisphere
// around x_j (sampler: direction_sampler.h), traces it with Embree and adds the emitted radiance
// found at x_{j+1} times the path weight, the product of f_r cos(theta) / pdf. K counts bounces:
// K = 0 shows only directly visible emission, and a furnace of albedo rho and emission Le gives
// Le (1 - rho^(K+1)) / (1 - rho).
#include <cstdint>
#include <optional>
#include <string>
#include <glm/vec3.hpp>

#include "direction_sampler.h"
#include "path_samples.h"
#include "ray.h"
#include "scene.h"

namespace strata {

struct PathIntegratorSettings {
    int depth = 5;  // K, number of bounces
    SamplerKind sampler = SamplerKind::Strata24;
    // Next-event estimation: at each scattering vertex, connect to every point light with a
    // shadow ray. Point lights are delta lights, reachable no other way.
    bool nextEventEstimation = false;
};

// Why every path of this scene carries zero radiance, or nullopt when light can reach the camera:
// no emitting triangle, and no point light that next-event estimation would reach.
std::optional<std::string> whyBlack(const Scene& scene, const PathIntegratorSettings& settings);

class PathIntegrator {
public:
    PathIntegrator(const Scene& scene, const PathIntegratorSettings& settings)
        : scene_(scene), settings_(settings) {}

    // Radiance arriving along -ray.direction at ray.origin. `rays` counts the rays traced.
    glm::vec3 radiance(const Ray& ray, const PathSamples& samples, uint64_t& rays) const;

    const PathIntegratorSettings& settings() const { return settings_; }

private:
    // Radiance from the scene's point lights reflected at `surface` (normal facing the viewer),
    // divided by f_r: sum of I cos / r^2 over the unoccluded lights.
    glm::vec3 pointLightIrradiance(const SurfaceHit& surface, uint64_t& rays) const;

    const Scene& scene_;
    PathIntegratorSettings settings_;
};

}  // namespace strata
