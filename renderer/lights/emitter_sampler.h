#pragma once
// Light sampling for next-event estimation: an emitting triangle chosen with probability
// proportional to its power (area times mean emitted radiance; pi cancels), then a point on it
// uniform by area. Emission is one-sided (front = counter-clockwise), as everywhere.
#include <cstdint>
#include <vector>
#include <glm/vec3.hpp>

#include "scene/mesh.h"

namespace strata {

struct EmitterSample {
    glm::vec3 point;
    glm::vec3 normal;    // the emitting (front) side's unit normal
    glm::vec3 emission;  // Ke
    float areaPdf;       // density of the point per unit area: P(triangle) / area(triangle)
};

class EmitterSampler {
public:
    explicit EmitterSampler(const MeshData& mesh);

    bool empty() const { return cdf_.empty(); }
    // `u` in [0,1)^3: u.x picks the triangle, (u.y, u.z) the point. Not to be called when empty.
    EmitterSample sample(const glm::vec3& u) const;
    // The area density sample() gives points of `triangle` (0 for a non-emitting one).
    float areaPdf(uint32_t triangle) const;

private:
    const MeshData& mesh_;
    std::vector<uint32_t> triangles_;  // the emitting triangles
    std::vector<double> cdf_;          // running power fractions, last = 1
    std::vector<float> areaPdf_;       // per scene triangle
};

}  // namespace strata
