#include "geometry/smoothing_groups.h"

#include <cmath>
#include <unordered_map>
#include <glm/geometric.hpp>

namespace strata {
namespace {

// The angle between two edges leaving a corner, from the sine and cosine both: accurate at
// every angle, where acos of the normalised dot product loses the small ones.
double angleBetween(const glm::dvec3& a, const glm::dvec3& b) {
    return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

constexpr uint32_t kNone = UINT32_MAX;

}  // namespace

GroupNormals smoothingGroupNormals(std::span<const glm::vec3> positions, std::span<const SmoothTriangle> triangles) {
    GroupNormals result;
    result.corners.reserve(triangles.size());
    // A sum per (vertex, group). Most files smooth in one group, so a vertex's first group is
    // found by index, and only a vertex in further groups goes through the hash map.
    // In double: a vertex shared by thousands of thin faces sums them without losing the small ones.
    std::vector<glm::dvec3> sums;
    std::vector<double> angles;  // the weights each sum adds up
    std::vector<uint32_t> slotGroup;
    std::vector<uint32_t> firstSlot(positions.size(), kNone);
    std::unordered_map<uint64_t, uint32_t> furtherSlots;
    const auto slotFor = [&](uint32_t vertex, uint32_t group) {
        uint32_t& first = firstSlot[vertex];
        if (first != kNone && slotGroup[first] == group) return first;
        const auto newSlot = static_cast<uint32_t>(sums.size());
        uint32_t slot = newSlot;
        if (first == kNone) {
            first = newSlot;
        } else {
            slot = furtherSlots.try_emplace(uint64_t(vertex) << 32 | group, newSlot).first->second;
        }
        if (slot == newSlot) {
            sums.emplace_back(0.0);
            angles.push_back(0.0);
            slotGroup.push_back(group);
        }
        return slot;
    };
    for (const SmoothTriangle& triangle : triangles) {
        std::array<glm::dvec3, 3> p;
        for (size_t k = 0; k < 3; ++k) p[k] = glm::dvec3(positions[triangle.vertices[k]]);
        const glm::dvec3 cross = glm::cross(p[1] - p[0], p[2] - p[0]);
        const double area = glm::length(cross);
        // Collinear corners whose float cross product rounded away from zero: no direction to add.
        std::array<uint32_t, 3> slots{kNone, kNone, kNone};
        if (!(area > 0.0)) {
            result.corners.push_back(slots);
            continue;
        }
        const glm::dvec3 normal = cross / area;
        for (size_t k = 0; k < 3; ++k) {
            slots[k] = slotFor(triangle.vertices[k], triangle.group);
            const glm::dvec3& corner = p[k];
            const double angle = angleBetween(p[(k + 1) % 3] - corner, p[(k + 2) % 3] - corner);
            sums[slots[k]] += normal * angle;
            angles[slots[k]] += angle;
        }
        result.corners.push_back(slots);
    }
    // A sum that (nearly) cancels has no direction to trust; its corners' triangles go flat.
    std::vector<uint32_t> normalOf(sums.size(), kNone);
    for (size_t s = 0; s < sums.size(); ++s) {
        const double length = glm::length(sums[s]);
        if (!(length > 1e-6 * angles[s])) continue;
        normalOf[s] = static_cast<uint32_t>(result.normals.size());
        result.normals.emplace_back(sums[s] / length);
    }
    for (std::array<uint32_t, 3>& corners : result.corners) {
        if (corners[0] == kNone) continue;
        corners = {normalOf[corners[0]], normalOf[corners[1]], normalOf[corners[2]]};
        if (corners[0] == kNone || corners[1] == kNone || corners[2] == kNone) corners = {kNone, kNone, kNone};
    }
    return result;
}

}  // namespace strata
