#include "geometry/polygon_triangulation.h"

#include <cmath>
#include <optional>
#include <utility>
#include <glm/common.hpp>
#include <glm/vec2.hpp>

namespace strata {
namespace {

using Point = glm::dvec2;
using Triangle = std::array<uint32_t, 3>;

// Twice the signed area of (a, b, c): positive when the three turn counter-clockwise.
double orientation(const Point& a, const Point& b, const Point& c) {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// The corners in the plane across the largest component of the polygon's Newell normal, mirrored
// if need be so that the polygon turns counter-clockwise there; empty when the polygon has no
// area or a corner is not finite. In double precision: a face far from the origin keeps the
// orientation of its narrow corners.
std::vector<Point> projectCounterClockwise(std::span<const glm::vec3> corners) {
    glm::dvec3 normal(0.0);
    for (size_t i = 0; i < corners.size(); ++i) {
        const glm::dvec3 a(corners[i]);
        const glm::dvec3 b(corners[(i + 1) % corners.size()]);
        normal += glm::dvec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
    }
    if (!std::isfinite(normal.x + normal.y + normal.z)) return {};
    const glm::dvec3 magnitude = glm::abs(normal);
    const int axis = magnitude.x > magnitude.y ? (magnitude.x > magnitude.z ? 0 : 2)
                                               : (magnitude.y > magnitude.z ? 1 : 2);
    if (!(magnitude[axis] > 0.0)) return {};
    // The other two axes in cyclic order (x: y, z; y: z, x; z: x, y) see a polygon that turns
    // counter-clockwise about +axis turn counter-clockwise.
    const int u = (axis + 1) % 3;
    const int v = (axis + 2) % 3;
    const double mirror = normal[axis] > 0.0 ? 1.0 : -1.0;
    std::vector<Point> points;
    points.reserve(corners.size());
    for (const glm::vec3& corner : corners) points.emplace_back(mirror * corner[u], corner[v]);
    return points;
}

bool isConvex(const std::vector<Point>& points) {
    const size_t n = points.size();
    for (size_t i = 0; i < n; ++i) {
        if (orientation(points[(i + n - 1) % n], points[i], points[(i + 1) % n]) < 0.0) return false;
    }
    return true;
}

void addFan(const std::vector<uint32_t>& ring, std::vector<Triangle>& triangles) {
    for (size_t i = 1; i + 1 < ring.size(); ++i) triangles.push_back({ring[0], ring[i], ring[i + 1]});
}

// The corners still to be cut, as a doubly linked ring.
class EarClipper {
public:
    explicit EarClipper(std::vector<Point> points) : points_(std::move(points)) {
        const auto n = static_cast<uint32_t>(points_.size());
        for (uint32_t i = 0; i < n; ++i) {
            previous_.push_back((i + n - 1) % n);
            next_.push_back((i + 1) % n);
        }
        for (uint32_t i = 0; i < n; ++i) reflex_.push_back(turnsInward(i));
    }

    bool clip(TriangulationBudget& budget, std::vector<Triangle>& triangles) {
        uint32_t corner = 1;
        size_t left = points_.size();
        size_t misses = 0;  // corners tried since the last cut
        while (left > 3) {
            const std::optional<bool> ear = isEar(corner, budget);
            if (!ear) {
                std::vector<uint32_t> ring{corner};
                for (uint32_t i = next_[corner]; i != corner; i = next_[i]) ring.push_back(i);
                addFan(ring, triangles);
                return false;
            }
            // All the way round without an ear: the polygon crosses itself. Cutting the corner
            // anyway still ends with n - 2 triangles over it.
            if (!*ear && ++misses < left) {
                corner = next_[corner];
                continue;
            }
            const uint32_t before = previous_[corner];
            const uint32_t after = next_[corner];
            triangles.push_back({before, corner, after});
            next_[before] = after;
            previous_[after] = before;
            reflex_[before] = turnsInward(before);
            reflex_[after] = turnsInward(after);
            corner = after;
            --left;
            misses = 0;
        }
        triangles.push_back({previous_[corner], corner, next_[corner]});
        return true;
    }

private:
    // Not a convex corner of the polygon as it now is (a straight one counts as turning inward:
    // its triangle would have no area).
    bool turnsInward(uint32_t i) const {
        return !(orientation(points_[previous_[i]], points_[i], points_[next_[i]]) > 0.0);
    }

    // Whether the triangle at `corner` lies inside the polygon: the corner is convex and no
    // other corner lies in the triangle or on its edges; only a corner that turns inward can.
    // A corner at the place of one of the triangle's own (the two sides of a slit) does not
    // count. Nullopt when the budget runs out.
    std::optional<bool> isEar(uint32_t corner, TriangulationBudget& budget) const {
        if (reflex_[corner]) return false;
        const Point& a = points_[previous_[corner]];
        const Point& b = points_[corner];
        const Point& c = points_[next_[corner]];
        for (uint32_t i = next_[next_[corner]]; i != previous_[corner]; i = next_[i]) {
            if (budget.visits == 0) return std::nullopt;
            --budget.visits;
            if (!reflex_[i]) continue;
            const Point& p = points_[i];
            if (p == a || p == b || p == c) continue;
            if (orientation(a, b, p) >= 0.0 && orientation(b, c, p) >= 0.0 && orientation(c, a, p) >= 0.0) {
                return false;
            }
        }
        return true;
    }

    std::vector<Point> points_;
    std::vector<uint32_t> previous_;
    std::vector<uint32_t> next_;
    std::vector<bool> reflex_;
};

}  // namespace

bool triangulatePolygon(std::span<const glm::vec3> corners, TriangulationBudget& budget,
                        std::vector<Triangle>& triangles) {
    const size_t n = corners.size();
    if (n < 3) return true;
    if (n == 3) {
        triangles.push_back({0, 1, 2});
        return true;
    }
    std::vector<Point> points = projectCounterClockwise(corners);
    if (points.empty() || isConvex(points)) {
        if (n == 4) {
            // tinyobjloader's choice, in its arithmetic, so that quads split as they always were.
            const glm::vec3 e02 = corners[2] - corners[0];
            const glm::vec3 e13 = corners[3] - corners[1];
            const float squared02 = e02.x * e02.x + e02.y * e02.y + e02.z * e02.z;
            const float squared13 = e13.x * e13.x + e13.y * e13.y + e13.z * e13.z;
            if (squared02 < squared13) {
                triangles.push_back({0, 1, 2});
                triangles.push_back({0, 2, 3});
            } else {
                triangles.push_back({0, 1, 3});
                triangles.push_back({1, 2, 3});
            }
            return true;
        }
        std::vector<uint32_t> ring(n);
        for (uint32_t i = 0; i < n; ++i) ring[i] = i;
        addFan(ring, triangles);
        return true;
    }
    return EarClipper(std::move(points)).clip(budget, triangles);
}

}  // namespace strata
