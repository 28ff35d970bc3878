#include "lights/light_bounds.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "util/constants.h"

namespace strata {
namespace {

float safeSqrt(float x) { return std::sqrt(std::max(x, 0.0f)); }

// cos and sin of max(a - b, 0) for angles a, b in [0, pi], from their cosines and sines.
float cosOfClampedDifference(float sinA, float cosA, float sinB, float cosB) {
    return cosA > cosB ? 1.0f : cosA * cosB + sinA * sinB;
}
float sinOfClampedDifference(float sinA, float cosA, float sinB, float cosB) {
    return cosA > cosB ? 0.0f : sinA * cosB - cosA * sinB;
}

// `v` turned by `angle` about the unit `axis` (Rodrigues).
glm::vec3 rotated(const glm::vec3& v, const glm::vec3& axis, float angle) {
    const float c = std::cos(angle);
    const float s = std::sin(angle);
    return v * c + glm::cross(axis, v) * s + axis * glm::dot(axis, v) * (1.0f - c);
}

}  // namespace

LightBounds unite(const LightBounds& a, const LightBounds& b) {
    LightBounds united;
    united.lower = glm::min(a.lower, b.lower);
    united.upper = glm::max(a.upper, b.upper);
    united.power = a.power + b.power;
    united.cosEmission = std::min(a.cosEmission, b.cosEmission);
    // The cones' union: the cone from a's far edge to b's far edge, unless one holds the other.
    const float spreadA = std::acos(std::clamp(a.cosSpread, -1.0f, 1.0f));
    const float spreadB = std::acos(std::clamp(b.cosSpread, -1.0f, 1.0f));
    const float between = std::acos(std::clamp(glm::dot(a.axis, b.axis), -1.0f, 1.0f));
    if (std::min(between + spreadB, kPi) <= spreadA) {
        united.axis = a.axis;
        united.cosSpread = a.cosSpread;
        return united;
    }
    if (std::min(between + spreadA, kPi) <= spreadB) {
        united.axis = b.axis;
        united.cosSpread = b.cosSpread;
        return united;
    }
    const float spread = 0.5f * (spreadA + between + spreadB);
    const glm::vec3 turn = glm::cross(a.axis, b.axis);
    const float turnLength = glm::length(turn);
    if (spread >= kPi || !(turnLength > 1e-7f)) {
        united.axis = a.axis;  // opposite axes: every direction
        united.cosSpread = -1.0f;
        return united;
    }
    united.axis = glm::normalize(rotated(a.axis, turn / turnLength, spread - spreadA));
    // Widened by a rounding margin so that the cone still holds both.
    united.cosSpread = std::max(-1.0f, std::cos(spread) - 1e-5f);
    return united;
}

ImportanceBounds importanceBounds(const LightBounds& bounds) {
    const glm::vec3 diagonal = bounds.upper - bounds.lower;
    return {bounds.centre(),  0.5f * glm::length(diagonal),
            bounds.axis,      bounds.power,
            bounds.cosSpread, safeSqrt(1.0f - bounds.cosSpread * bounds.cosSpread),
            bounds.cosEmission};
}

float importance(const ImportanceBounds& bounds, const glm::vec3& point, const glm::vec3& normal) {
    // The box lies in its circumscribed sphere; seen from `point` that sphere subtends the cone
    // of half-angle theta_b about the direction to the centre. Inside it, every direction.
    const glm::vec3 fromCentre = point - bounds.centre;
    const float distanceSquared = glm::dot(fromCentre, fromCentre);
    const float radiusSquared = bounds.radius * bounds.radius;
    if (distanceSquared <= radiusSquared) return radiusSquared > 0.0f ? bounds.power / radiusSquared : bounds.power;
    const float inverseDistance = 1.0f / std::sqrt(distanceSquared);
    const float sinB = bounds.radius * inverseDistance;
    const float cosB = safeSqrt(1.0f - sinB * sinB);
    const glm::vec3 toPoint = fromCentre * inverseDistance;
    // The least angle theta' between a normal of the cone and the direction from the box to the
    // point: max(theta_w - theta_o - theta_b, 0). Beyond theta_e nothing is emitted that way.
    const float cosW = glm::dot(bounds.axis, toPoint);
    const float sinW = safeSqrt(1.0f - cosW * cosW);
    const float cosX = cosOfClampedDifference(sinW, cosW, bounds.sinSpread, bounds.cosSpread);
    const float sinX = sinOfClampedDifference(sinW, cosW, bounds.sinSpread, bounds.cosSpread);
    const float cosLeast = cosOfClampedDifference(sinX, cosX, sinB, cosB);
    if (!(cosLeast > bounds.cosEmission)) return 0.0f;
    float estimate = bounds.power * cosLeast * (inverseDistance * inverseDistance);
    if (normal != glm::vec3(0.0f)) {
        // The least angle between the surface's normal and a direction toward the box:
        // max(theta_i - theta_b, 0); from 90 degrees on the box lies below the surface.
        const float cosI = -glm::dot(normal, toPoint);
        const float sinI = safeSqrt(1.0f - cosI * cosI);
        const float cosLeastI = cosOfClampedDifference(sinI, cosI, sinB, cosB);
        if (!(cosLeastI > 0.0f)) return 0.0f;
        estimate *= cosLeastI;
    }
    return estimate;
}

float orientationMeasure(const LightBounds& bounds) {
    const float spread = std::acos(std::clamp(bounds.cosSpread, -1.0f, 1.0f));
    const float emission = std::acos(std::clamp(bounds.cosEmission, -1.0f, 1.0f));
    const float reach = std::min(spread + emission, kPi);
    const float sinSpread = safeSqrt(1.0f - bounds.cosSpread * bounds.cosSpread);
    return 2.0f * kPi * (1.0f - bounds.cosSpread) +
           0.5f * kPi *
               (2.0f * reach * sinSpread - std::cos(spread - 2.0f * reach) - 2.0f * spread * sinSpread +
                bounds.cosSpread);
}

}  // namespace strata
