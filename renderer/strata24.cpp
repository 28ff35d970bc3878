#include "strata24.h"

#include <algorithm>
#include <cmath>

namespace strata {
namespace {

constexpr float kSqrt2 = 1.41421356237309504880f;

}  // namespace

glm::vec3 placeInStratum(int id, float a, float b, float c) {
    glm::vec3 d;
    switch (id % 6) {
        case 0: d = {b, c, a}; break;
        case 1: d = {c, b, a}; break;
        case 2: d = {a, c, b}; break;
        case 3: d = {c, a, b}; break;
        case 4: d = {a, b, c}; break;
        default: d = {b, a, c}; break;
    }
    const int quadrant = id / 6;
    if (quadrant == 1 || quadrant == 2) d.x = -d.x;
    if (quadrant == 2 || quadrant == 3) d.y = -d.y;
    return d;
}

glm::vec3 sampleStratum(int id, glm::vec2 u) {
    // Azimuth about the pi/4 vertex P: the marginal CDF G(phi) = phi - asin(sin(phi)/sqrt 2)
    // inverts to phi = A + atan2(sin A, sqrt 2 - cos A) with A = u pi/12 (notes section 2.3).
    // Written out with s = sin(A/2), k = cos(A/2), that angle's cosine and sine are
    //   cos phi = (sqrt2 cos A - 1) / R,  sin phi = sqrt2 sin A / R,  R^2 = 3 - 2 sqrt2 cos A,
    // and with cos A = 1 - 2 s^2 every term is a sum of positives or a mild difference, so the
    // map stays within a few ulp everywhere (no atan2, one sincos).
    const float halfA = u.x * (kStratumSolidAngle * 0.5f);
    const float s = std::sin(halfA);
    const float k = std::cos(halfA);
    const float s2 = s * s;
    const float rSquared = (3.0f - 2.0f * kSqrt2) + 4.0f * kSqrt2 * s2;
    const float invR = 1.0f / std::sqrt(rSquared);
    const float cosPhi = ((kSqrt2 - 1.0f) - 2.0f * kSqrt2 * s2) * invR;
    const float sinPhi = 2.0f * kSqrt2 * s * k * invR;

    // Polar angle: 1 - cos(theta) is uniform on [0, h], h = 1 - cos(theta_max(phi)) with
    // tan(theta_max) = 1 / cos(phi). sin(theta) from w(2 - w) avoids 1 - cos^2 cancellation.
    const float h = 1.0f - cosPhi / std::sqrt(1.0f + cosPhi * cosPhi);
    const float w = u.y * h;
    const float sinTheta = std::sqrt(w * (2.0f - w));
    const float a = 1.0f - w;
    // Rounding can push a coordinate one ulp across a boundary plane; clamping restores the
    // ordering a >= b >= c >= 0 without moving the point measurably.
    const float b = std::min(sinTheta * cosPhi, a);
    const float c = std::min(sinTheta * sinPhi, b);
    return placeInStratum(id, a, b, c);
}

int classifyStratum(const glm::vec3& d) {
    const int quadrant = d.x >= 0.0f ? (d.y >= 0.0f ? 0 : 3) : (d.y >= 0.0f ? 1 : 2);
    const float ax = std::abs(d.x);
    const float ay = std::abs(d.y);
    int order;
    if (d.z >= std::max(ax, ay)) {
        order = ax >= ay ? 0 : 1;
    } else if (std::min(ax, ay) >= d.z) {
        order = ax >= ay ? 4 : 5;
    } else {
        order = ax >= ay ? 2 : 3;
    }
    return 6 * quadrant + order;
}

bool stratumContains(int id, const glm::vec3& d) {
    const int quadrant = id / 6;
    const bool negativeX = quadrant == 1 || quadrant == 2;
    const bool negativeY = quadrant == 2 || quadrant == 3;
    if ((negativeX ? d.x > 0.0f : d.x < 0.0f) || (negativeY ? d.y > 0.0f : d.y < 0.0f) ||
        d.z < 0.0f) {
        return false;
    }
    const float ax = std::abs(d.x);
    const float ay = std::abs(d.y);
    switch (id % 6) {
        case 0: return d.z >= ax && ax >= ay;
        case 1: return d.z >= ay && ay >= ax;
        case 2: return ax >= d.z && d.z >= ay;
        case 3: return ay >= d.z && d.z >= ax;
        case 4: return ax >= ay && ay >= d.z;
        default: return ay >= ax && ax >= d.z;
    }
}

std::array<glm::vec3, 3> stratumVertices(int id) {
    const float invSqrt2 = 1.0f / kSqrt2;
    const float invSqrt3 = 1.0f / std::sqrt(3.0f);
    return {placeInStratum(id, 1.0f, 0.0f, 0.0f), placeInStratum(id, invSqrt2, invSqrt2, 0.0f),
            placeInStratum(id, invSqrt3, invSqrt3, invSqrt3)};
}

}  // namespace strata
