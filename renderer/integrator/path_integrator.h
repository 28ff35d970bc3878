#pragma once
// The path tracer: the Neumann series of the rendering equation truncated at recursion depth K
// (paper, section 4). The camera ray finds x_1; bounce j samples a direction around x_j (sampler:
// direction_sampler.h; material: material.h), traces it with Embree and adds the emitted radiance
// found at x_{j+1} times the path weight, the product of f_r cos(theta) / pdf. K counts bounces:
// K = 0 shows only directly visible emission, and a furnace of albedo rho and emission Le gives
// Le (1 - rho^(K+1)) / (1 - rho).
//
// With next-event estimation each scattering vertex x_j (j < K) also connects to one point on an
// emitting triangle (emitter_sampler.h) and to every point light. Emission is then reached two
// ways, by the light sample and by the next bounce's direction; the two are combined by multiple
// importance sampling with the power heuristic (Veach & Guibas 1995), whose weights sum to 1 for
// every direction, so the estimate stays unbiased for every sampler.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>
#include <glm/vec3.hpp>

#include "sampling/direction_sampler.h"
#include "lights/emitter_sampler.h"
#include "geometry/frame.h"
#include "materials/material.h"
#include "sampling/path_samples.h"
#include "geometry/ray.h"
#include "scene/scene.h"

namespace strata {

struct PathIntegratorSettings {
    int depth = 5;  // K, number of bounces
    SamplerKind sampler = SamplerKind::Strata24;
    // Next-event estimation: at each scattering vertex, a shadow ray to a point sampled on the
    // emitting triangles (combined with the bounce's own direction by MIS) and one to every point
    // light (delta lights, reachable no other way).
    bool nextEventEstimation = false;
    // Russian roulette from this many bounces on (-1: off): the path goes on with probability
    // q = min(1, max component of its weight) and its weight is divided by q. Unbiased; it trades
    // a little variance for not tracing paths whose weight has become small.
    int rouletteDepth = -1;
    // A scene whose materials are all Lambertian runs a path compiled for LambertianBsdf, with no
    // microfacet code on it; false forces the general LayeredBsdf path (to measure the gain).
    bool lambertianFastPath = true;
};

// Why every path of this scene carries zero radiance, or nullopt when light can reach the camera:
// no emitting triangle, and no point light that next-event estimation would reach.
std::optional<std::string> whyBlack(const Scene& scene, const PathIntegratorSettings& settings);

class PathIntegrator {
public:
    PathIntegrator(const Scene& scene, const PathIntegratorSettings& settings);

    // Radiance arriving along -ray.direction at ray.origin. `rays` counts the rays traced.
    glm::vec3 radiance(const Ray& ray, const PathSamples& samples, uint64_t& rays) const;

    const PathIntegratorSettings& settings() const { return settings_; }
    // Whether paths run the Lambertian-only specialisation.
    bool usesLambertianPath() const { return !lambertianBsdfs_.empty(); }

private:
    // The path loop, compiled once per material model (LayeredBsdf, LambertianBsdf).
    template <class Bsdf>
    glm::vec3 trace(const std::vector<Bsdf>& bsdfs, const Ray& ray, const PathSamples& samples,
                    uint64_t& rays) const;
    // The reflected radiance from one light sample on the emitting triangles, MIS-weighted
    // against the direction sampler, at `surface` (normal facing the viewer) toward wo.
    template <class Bsdf>
    glm::vec3 emitterLight(const SurfaceHit& surface, const Frame& frame, const glm::vec3& wo,
                           const Bsdf& bsdf, const PathSamples& samples, int bounce,
                           uint64_t& rays) const;
    // The reflected radiance from the scene's point lights: f_r I cos / r^2 for each visible one.
    template <class Bsdf>
    glm::vec3 pointLightRadiance(const SurfaceHit& surface, const Frame& frame, const glm::vec3& wo,
                                 const Bsdf& bsdf, uint64_t& rays) const;

    const Scene& scene_;
    PathIntegratorSettings settings_;
    // One per scene material: the Lambertian ones when the fast path applies, else the layered.
    std::vector<LayeredBsdf> layeredBsdfs_;
    std::vector<LambertianBsdf> lambertianBsdfs_;
    EmitterSampler emitters_;
};

}  // namespace strata
