#pragma once
// The path tracer: the Neumann series of the rendering equation truncated at recursion depth K
// (paper, section 4). The camera ray finds x_1; bounce j samples a direction on the hemisphere
// around x_j (sampler: direction_sampler.h), traces it with Embree and adds the emitted radiance
// found at x_{j+1} times the path weight, the product of f_r cos(theta) / pdf. K counts bounces:
// K = 0 shows only directly visible emission, and a furnace of albedo rho and emission Le gives
// Le (1 - rho^(K+1)) / (1 - rho).
#include <cstdint>
#include <glm/vec3.hpp>

#include "direction_sampler.h"
#include "path_samples.h"
#include "ray.h"
#include "scene.h"

namespace strata {

struct PathIntegratorSettings {
    int depth = 5;  // K, number of bounces
    SamplerKind sampler = SamplerKind::Strata24;
};

class PathIntegrator {
public:
    PathIntegrator(const Scene& scene, const PathIntegratorSettings& settings)
        : scene_(scene), settings_(settings) {}

    // Radiance arriving along -ray.direction at ray.origin. `rays` counts the rays traced.
    glm::vec3 radiance(const Ray& ray, const PathSamples& samples, uint64_t& rays) const;

    const PathIntegratorSettings& settings() const { return settings_; }

private:
    const Scene& scene_;
    PathIntegratorSettings settings_;
};

}  // namespace strata
