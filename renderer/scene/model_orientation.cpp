#include "scene/model_orientation.h"

#include <cmath>
#include <limits>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace strata {
namespace {

// A plane the bounding box rests on, and a front offset that counts: fractions of extents.
constexpr double kGroundTolerance = 0.01;
constexpr double kFrontOffset = 0.05;

// The area-weighted centroid and the plain mean of the triangles' centroids.
struct Centroids {
    glm::dvec3 byArea{0.0};
    glm::dvec3 byTriangle{0.0};
};

Centroids centroidsOf(const MeshData& mesh) {
    Centroids c;
    double area = 0.0;
    for (const auto& t : mesh.triangles) {
        const glm::dvec3 p0(mesh.positions[t[0]]), p1(mesh.positions[t[1]]), p2(mesh.positions[t[2]]);
        const glm::dvec3 centroid = (p0 + p1 + p2) / 3.0;
        const double a = 0.5 * glm::length(glm::cross(p1 - p0, p2 - p0));
        c.byArea += a * centroid;
        c.byTriangle += centroid;
        area += a;
    }
    c.byArea = area > 0.0 ? c.byArea / area : c.byTriangle / static_cast<double>(mesh.triangles.size());
    c.byTriangle /= static_cast<double>(mesh.triangles.size());
    return c;
}

glm::vec3 axis(int index, double sign) {
    glm::vec3 a(0.0f);
    a[index] = sign < 0.0 ? -1.0f : 1.0f;
    return a;
}

}  // namespace

ModelOrientation objOrientation(const MeshData& mesh) {
    if (mesh.triangles.empty()) return {};
    glm::dvec3 lower(std::numeric_limits<double>::infinity());
    glm::dvec3 upper = -lower;
    for (const glm::vec3& p : mesh.positions) {
        lower = glm::min(lower, glm::dvec3(p));
        upper = glm::max(upper, glm::dvec3(p));
    }
    const glm::dvec3 extent = upper - lower;
    const double tolerance = kGroundTolerance * glm::max(glm::max(extent.x, extent.y), extent.z);
    const bool zUp = std::abs(lower.z) <= tolerance && std::abs(lower.y) > tolerance;
    ModelOrientation orientation;
    orientation.up = zUp ? glm::vec3(0.0f, 0.0f, 1.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
    orientation.front = zUp ? glm::vec3(0.0f, -1.0f, 0.0f) : glm::vec3(0.0f, 0.0f, 1.0f);

    const Centroids centroids = centroidsOf(mesh);
    double strongest = kFrontOffset;
    for (int a : {0, zUp ? 1 : 2}) {
        if (!(extent[a] > 0.0)) continue;
        const double offset = (centroids.byTriangle[a] - centroids.byArea[a]) / extent[a];
        if (std::abs(offset) >= strongest) {
            strongest = std::abs(offset);
            orientation.front = axis(a, offset);
        }
    }
    return orientation;
}

}  // namespace strata
