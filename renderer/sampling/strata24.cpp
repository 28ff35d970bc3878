#include "sampling/strata24.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace strata {
namespace {

constexpr float kSqrt2 = 1.41421356237309504880f;

}  // namespace

glm::vec3 placeInStratum(int id, float a, float b, float c) {
    // Table lookups rather than a switch: the id is random from sample to sample, so a branch on
    // it would be mispredicted most of the time on the path tracer's hot path.
    // kSlots[order] says which of (a, b, c) goes to x, y and z (the orderings in strata24.h).
    static constexpr std::array<std::array<uint8_t, 3>, 6> kSlots{
        {{1, 2, 0}, {2, 1, 0}, {0, 2, 1}, {2, 0, 1}, {0, 1, 2}, {1, 0, 2}}};
    static constexpr std::array<float, 4> kSignX{1.0f, -1.0f, -1.0f, 1.0f};
    static constexpr std::array<float, 4> kSignY{1.0f, 1.0f, -1.0f, -1.0f};
    const std::array<float, 3> sorted{a, b, c};
    const auto& slot = kSlots[static_cast<size_t>(id % 6)];
    const auto quadrant = static_cast<size_t>(id / 6);
    return {kSignX[quadrant] * sorted[slot[0]], kSignY[quadrant] * sorted[slot[1]], sorted[slot[2]]};
}

glm::vec3 sampleStratum(int id, glm::vec2 u) {
    // Azimuth about the pi/4 vertex P: the marginal CDF G(phi) = phi - asin(sin(phi)/sqrt 2)
    // inverts to phi = A + atan2(sin A, sqrt 2 - cos A) with A = u pi/12 (notes section 2.3).
    // Written out with s = sin(A/2), k = cos(A/2), that angle's cosine and sine are
    //   cos phi = N / R,  sin phi = 2 sqrt2 s k / R,  N = (sqrt2 - 1) - 2 sqrt2 s^2,
    //   R^2 = 3 - 2 sqrt2 cos A = (3 - 2 sqrt2) + 4 sqrt2 s^2.
    // A/2 lies in [0, pi/24], where these Taylor polynomials are exact to 2e-10 (the first omitted
    // terms, x^7/7! and x^8/8!), far under float's ulp, and cheaper than a sincos call.
    const float x = u.x * (kStratumSolidAngle * 0.5f);
    const float x2 = x * x;
    const float s = x * (1.0f - x2 * (1.0f / 6.0f) * (1.0f - x2 * (1.0f / 20.0f)));
    const float k = 1.0f - x2 * 0.5f * (1.0f - x2 * (1.0f / 12.0f) * (1.0f - x2 * (1.0f / 30.0f)));
    const float s2 = s * s;
    const float n = (kSqrt2 - 1.0f) - 2.0f * kSqrt2 * s2;
    const float rSquared = (3.0f - 2.0f * kSqrt2) + 4.0f * kSqrt2 * s2;
    // Polar angle: 1 - cos(theta) is uniform on [0, h], h = 1 - cos(theta_max(phi)) with
    // tan(theta_max) = 1 / cos(phi). Since R^2 + N^2 = 2 (sqrt2 - 1 + 2 s^2)^2 exactly,
    //   h = 1 - N / sqrt(R^2 + N^2) = R^2 / D,  D = (2 - sqrt2) + 2 sqrt2 s^2,
    // and with w = 1 - cos(theta) = u_y h,
    //   sin(theta) / R = sqrt(w (2 - w)) / R = sqrt(u_y (2 - w) / D),
    // so the direction costs one division and one square root, every term a sum of positives or
    // a mild difference: the map stays within a few ulp everywhere, edges and corners included.
    const float invD = 1.0f / ((2.0f - kSqrt2) + 2.0f * kSqrt2 * s2);
    const float w = u.y * rSquared * invD;
    const float sinThetaOverR = std::sqrt(u.y * invD * (2.0f - w));
    const float a = 1.0f - w;
    // Rounding can push a coordinate one ulp across a boundary plane; clamping restores the
    // ordering a >= b >= c >= 0 without moving the point measurably.
    const float b = std::min(sinThetaOverR * n, a);
    const float c = std::min(sinThetaOverR * (2.0f * kSqrt2) * s * k, b);
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
