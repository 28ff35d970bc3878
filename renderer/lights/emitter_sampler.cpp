#include "lights/emitter_sampler.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace strata {

EmitterSampler::EmitterSampler(const MeshData& mesh)
    : mesh_(mesh), areaPdf_(mesh.triangles.size(), 0.0f) {
    std::vector<double> areas;
    double total = 0.0;
    for (size_t i = 0; i < mesh.triangles.size(); ++i) {
        const glm::vec3 e = mesh.materials[mesh.triangleMaterials[i]].emission;
        const double radiance = (static_cast<double>(e.x) + e.y + e.z) / 3.0;
        if (!(radiance > 0.0)) continue;
        const auto& t = mesh.triangles[i];
        const glm::dvec3 p0(mesh.positions[t[0]]);
        const double area =
            0.5 * glm::length(glm::cross(glm::dvec3(mesh.positions[t[1]]) - p0,
                                         glm::dvec3(mesh.positions[t[2]]) - p0));
        if (!(area > 0.0)) continue;
        triangles_.push_back(static_cast<uint32_t>(i));
        areas.push_back(area);
        total += area * radiance;
        cdf_.push_back(total);
    }
    for (size_t k = 0; k < cdf_.size(); ++k) {
        const double previous = k == 0 ? 0.0 : cdf_[k - 1];
        areaPdf_[triangles_[k]] = static_cast<float>((cdf_[k] - previous) / total / areas[k]);
    }
    for (double& c : cdf_) c /= total;
    if (!cdf_.empty()) cdf_.back() = 1.0;
}

EmitterSample EmitterSampler::sample(const glm::vec3& u) const {
    const size_t k = std::min<size_t>(
        std::upper_bound(cdf_.begin(), cdf_.end(), static_cast<double>(u.x)) - cdf_.begin(),
        cdf_.size() - 1);
    const uint32_t triangle = triangles_[k];
    const auto& t = mesh_.triangles[triangle];
    const glm::vec3& p0 = mesh_.positions[t[0]];
    const glm::vec3& p1 = mesh_.positions[t[1]];
    const glm::vec3& p2 = mesh_.positions[t[2]];
    // Uniform by area: barycentrics (1 - sqrt(u), sqrt(u)(1 - v), sqrt(u) v).
    const float s = std::sqrt(u.y);
    const float b1 = s * (1.0f - u.z);
    const float b2 = s * u.z;
    const glm::vec3 point = (1.0f - b1 - b2) * p0 + b1 * p1 + b2 * p2;
    return {point, glm::normalize(glm::cross(p1 - p0, p2 - p0)),
            mesh_.materials[mesh_.triangleMaterials[triangle]].emission, areaPdf_[triangle]};
}

float EmitterSampler::areaPdf(uint32_t triangle) const { return areaPdf_[triangle]; }

}  // namespace strata
