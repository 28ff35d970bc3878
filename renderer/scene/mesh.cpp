#include "scene/mesh.h"

#include <cmath>
#include <limits>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

namespace strata {

std::pair<glm::vec3, glm::vec3> worldBounds(const MeshData& mesh) {
    glm::vec3 lower(std::numeric_limits<float>::infinity());
    glm::vec3 upper = -lower;
    const auto include = [&](const glm::vec3& p) {
        lower = glm::min(lower, p);
        upper = glm::max(upper, p);
    };
    if (mesh.sharedMeshes.empty()) {
        for (const glm::vec3& p : mesh.positions) include(p);
        return {lower, upper};
    }
    size_t worldFirst = 0;
    const auto includeWorld = [&](size_t end) {
        for (size_t t = worldFirst; t < end; ++t) {
            for (uint32_t v : mesh.triangles[t]) include(mesh.positions[v]);
        }
    };
    for (const SharedMesh& shared : mesh.sharedMeshes) {
        includeWorld(shared.firstTriangle);
        worldFirst = shared.firstTriangle + size_t{shared.triangleCount};
        glm::vec3 boxLower(std::numeric_limits<float>::infinity());
        glm::vec3 boxUpper = -boxLower;
        for (size_t t = shared.firstTriangle; t < worldFirst; ++t) {
            for (uint32_t v : mesh.triangles[t]) {
                boxLower = glm::min(boxLower, mesh.positions[v]);
                boxUpper = glm::max(boxUpper, mesh.positions[v]);
            }
        }
        if (!(boxLower.x <= boxUpper.x)) continue;  // no triangles
        for (const glm::mat4& placement : shared.placements) {
            for (int corner = 0; corner < 8; ++corner) {
                const glm::vec3 local((corner & 1) ? boxUpper.x : boxLower.x, (corner & 2) ? boxUpper.y : boxLower.y,
                                      (corner & 4) ? boxUpper.z : boxLower.z);
                include(glm::vec3(placement * glm::vec4(local, 1.0f)));
            }
        }
    }
    includeWorld(mesh.triangles.size());
    return {lower, upper};
}

uint64_t placedTriangles(const MeshData& mesh) {
    uint64_t placed = mesh.triangles.size();
    for (const SharedMesh& s : mesh.sharedMeshes) placed += (s.placements.size() * s.triangleCount) - s.triangleCount;
    return placed;
}

double worldArea(const MeshData& mesh) {
    const auto areaOf = [&](size_t first, size_t end) {
        double area = 0.0;
        for (size_t t = first; t < end; ++t) {
            const auto& c = mesh.triangles[t];
            const glm::dvec3 p0(mesh.positions[c[0]]);
            area += 0.5 * glm::length(glm::cross(glm::dvec3(mesh.positions[c[1]]) - p0,
                                                 glm::dvec3(mesh.positions[c[2]]) - p0));
        }
        return area;
    };
    double area = 0.0;
    size_t worldFirst = 0;
    for (const SharedMesh& shared : mesh.sharedMeshes) {
        area += areaOf(worldFirst, shared.firstTriangle);
        worldFirst = shared.firstTriangle + size_t{shared.triangleCount};
        const double local = areaOf(shared.firstTriangle, worldFirst);
        for (const glm::mat4& placement : shared.placements) {
            const double determinant = std::abs(static_cast<double>(glm::determinant(glm::mat3(placement))));
            area += local * std::pow(determinant, 2.0 / 3.0);
        }
    }
    return area + areaOf(worldFirst, mesh.triangles.size());
}

}  // namespace strata
