#include "scene/mesh.h"

#include <limits>
#include <glm/common.hpp>

namespace strata {

std::pair<glm::vec3, glm::vec3> worldBounds(const MeshData& mesh) {
    std::vector<bool> shared(mesh.sharedMeshes.empty() ? 0 : mesh.positions.size(), false);
    std::vector<std::pair<glm::vec3, glm::vec3>> sharedBoxes;
    for (const SharedMesh& s : mesh.sharedMeshes) {
        glm::vec3 lower(std::numeric_limits<float>::infinity());
        glm::vec3 upper = -lower;
        for (uint32_t t = s.firstTriangle; t < s.firstTriangle + s.triangleCount; ++t) {
            for (uint32_t v : mesh.triangles[t]) {
                shared[v] = true;
                lower = glm::min(lower, mesh.positions[v]);
                upper = glm::max(upper, mesh.positions[v]);
            }
        }
        sharedBoxes.emplace_back(lower, upper);
    }
    glm::vec3 lower(std::numeric_limits<float>::infinity());
    glm::vec3 upper = -lower;
    for (size_t v = 0; v < mesh.positions.size(); ++v) {
        if (!shared.empty() && shared[v]) continue;
        lower = glm::min(lower, mesh.positions[v]);
        upper = glm::max(upper, mesh.positions[v]);
    }
    for (size_t i = 0; i < mesh.sharedMeshes.size(); ++i) {
        const auto& [boxLower, boxUpper] = sharedBoxes[i];
        if (!(boxLower.x <= boxUpper.x)) continue;  // no triangles
        for (const glm::mat4& placement : mesh.sharedMeshes[i].placements) {
            for (int corner = 0; corner < 8; ++corner) {
                const glm::vec3 local((corner & 1) ? boxUpper.x : boxLower.x, (corner & 2) ? boxUpper.y : boxLower.y,
                                      (corner & 4) ? boxUpper.z : boxLower.z);
                const glm::vec3 world(placement * glm::vec4(local, 1.0f));
                lower = glm::min(lower, world);
                upper = glm::max(upper, world);
            }
        }
    }
    return {lower, upper};
}

uint64_t placedTriangles(const MeshData& mesh) {
    uint64_t placed = mesh.triangles.size();
    for (const SharedMesh& s : mesh.sharedMeshes) placed += (s.placements.size() * s.triangleCount) - s.triangleCount;
    return placed;
}

}  // namespace strata
