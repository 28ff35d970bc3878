#include "scene/traversal_precision.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace strata {

namespace {

// The largest perimeter / area of triangles [first, end) of the mesh (of nonzero area), 0 for none.
double largestPerimeterPerArea(const MeshData& mesh, size_t first, size_t end) {
    double largest = 0.0;
    for (size_t t = first; t < end; ++t) {
        const auto& triangle = mesh.triangles[t];
        const glm::dvec3 a(mesh.positions[triangle[0]]);
        const glm::dvec3 b(mesh.positions[triangle[1]]);
        const glm::dvec3 c(mesh.positions[triangle[2]]);
        const double area = 0.5 * glm::length(glm::cross(b - a, c - a));
        if (!(area > 0.0)) continue;
        const double perimeter = glm::length(b - a) + glm::length(c - b) + glm::length(a - c);
        largest = std::max(largest, perimeter / area);
    }
    return largest;
}

// How much a linear map L can raise a triangle's perimeter / area: sigma_1^2 / |det L| (edges
// grow by sigma_1 at most, the area shrinks by sigma_2 sigma_3 = |det L| / sigma_1 at most);
// 1 / s for a similarity of scale s, exactly. sigma_1^2 is the largest eigenvalue of L^T L, by
// the closed form for symmetric 3 x 3 matrices (Smith 1961).
double perimeterPerAreaGrowth(const glm::mat4& placement) {
    const glm::dmat3 linear{glm::mat3(placement)};
    const glm::dmat3 a = glm::transpose(linear) * linear;
    const double offDiagonal = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
    const double q = (a[0][0] + a[1][1] + a[2][2]) / 3.0;
    const double spread = (a[0][0] - q) * (a[0][0] - q) + (a[1][1] - q) * (a[1][1] - q) +
                          (a[2][2] - q) * (a[2][2] - q) + 2.0 * offDiagonal;
    const double p = std::sqrt(spread / 6.0);
    double largestEigenvalue = q;
    if (p > 0.0) {
        const double r = std::clamp(glm::determinant((a - glm::dmat3(q)) / p) / 2.0, -1.0, 1.0);
        largestEigenvalue = q + 2.0 * p * std::cos(std::acos(r) / 3.0);
    }
    return largestEigenvalue / std::abs(glm::determinant(linear));
}

}  // namespace

double roundingGapShare(const MeshData& mesh) {
    const auto [lower, upper] = worldBounds(mesh);
    double largestCoordinate = 0.0;
    if (!mesh.positions.empty()) {
        for (int axis = 0; axis < 3; ++axis) {
            largestCoordinate = std::max({largestCoordinate, double(std::abs(lower[axis])), double(std::abs(upper[axis]))});
        }
    }
    // The world's triangles as they are, a shared mesh's as its placements can stretch them.
    size_t worldFirst = 0;
    double largest = 0.0;
    for (const SharedMesh& shared : mesh.sharedMeshes) {
        largest = std::max(largest, largestPerimeterPerArea(mesh, worldFirst, shared.firstTriangle));
        double growth = 0.0;
        for (const glm::mat4& placement : shared.placements) growth = std::max(growth, perimeterPerAreaGrowth(placement));
        const size_t end = shared.firstTriangle + size_t{shared.triangleCount};
        largest = std::max(largest, growth * largestPerimeterPerArea(mesh, shared.firstTriangle, end));
        worldFirst = end;
    }
    largest = std::max(largest, largestPerimeterPerArea(mesh, worldFirst, mesh.triangles.size()));
    return 0x1p-24 * largestCoordinate * largest;
}

bool usesWatertightTest(Traversal requested, double gapShare) {
    switch (requested) {
        case Traversal::Watertight: return true;
        case Traversal::Fast: return false;
        case Traversal::Automatic: break;
    }
    // Written so that a share that is not a number (an infinite coordinate) is watertight too.
    return !(gapShare <= kTolerableGapShare);
}

}  // namespace strata
