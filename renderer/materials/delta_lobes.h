#pragma once
// What the models made only of Dirac delta lobes share (the smooth conductor, the smooth and the
// thin dielectric): no direction drawn from a density, a light sample's or another lobe's, meets
// a delta lobe, so its value and density are 0 everywhere and only its sample() scatters.
#include <glm/vec3.hpp>

#include "materials/bsdf_sample.h"

namespace strata {

struct DeltaLobes {
    glm::vec3 evaluate(const glm::vec3&, const glm::vec3&, TransportMode = TransportMode::Radiance) const {
        return glm::vec3(0.0f);
    }
    float pdf(const glm::vec3&, const glm::vec3&, DiffuseWarp) const { return 0.0f; }
};

}  // namespace strata
