#include "scene/traversal_precision.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace strata {

double roundingGapShare(const MeshData& mesh) {
    double largestCoordinate = 0.0;
    for (const glm::vec3& p : mesh.positions) {
        largestCoordinate = std::max({largestCoordinate, double(std::abs(p.x)), double(std::abs(p.y)),
                                      double(std::abs(p.z))});
    }
    double largestPerimeterPerArea = 0.0;
    for (const auto& triangle : mesh.triangles) {
        const glm::dvec3 a(mesh.positions[triangle[0]]);
        const glm::dvec3 b(mesh.positions[triangle[1]]);
        const glm::dvec3 c(mesh.positions[triangle[2]]);
        const double area = 0.5 * glm::length(glm::cross(b - a, c - a));
        if (!(area > 0.0)) continue;
        const double perimeter = glm::length(b - a) + glm::length(c - b) + glm::length(a - c);
        largestPerimeterPerArea = std::max(largestPerimeterPerArea, perimeter / area);
    }
    return 0x1p-24 * largestCoordinate * largestPerimeterPerArea;
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
