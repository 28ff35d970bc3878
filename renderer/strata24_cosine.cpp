#include "strata24_cosine.h"

#include <algorithm>
#include <cmath>

#include "strata24.h"

namespace strata {
namespace {

constexpr double kPiD = 3.14159265358979323846;
constexpr double kSqrt2D = 1.41421356237309504880;
constexpr double kQuarterPi = kPiD / 4.0;
// Notes section 3; tests/test_strata24_cosine.cpp recomputes them from the closed forms.
constexpr double kPolePsa = 0.2176049378417758;     // asin(1/sqrt 3) / (2 sqrt 2)
constexpr double kMiddlePsa = 0.1201504915862442;   // asin(1/3) / (2 sqrt 2)
constexpr double kEquatorPsa = 0.0549436522707042;  // pi/8 - acos(1/sqrt 3) / (2 sqrt 2)
constexpr double kAsinInvSqrt3 = 0.61547970867038734;  // asin(1/sqrt 3)
constexpr double kAsinThird = 0.33983690945412194;     // asin(1/3)

int strataClass(int id) { return (id % 6) / 2; }  // 0 pole, 1 middle, 2 equator

// The equator class's azimuth CDF (projected area swept up to phi, canonical triangle
// {x >= y >= z}): F(phi) = (phi - atan(sqrt2 tan phi) / sqrt2) / 2. The direct formula cancels
// for small phi, where the series phi^3/6 - 2 phi^5/15 + 11 phi^7/90 - 347 phi^9/2835 is used.
double equatorCdf(double phi) {
    if (phi < 0.02) {
        const double p2 = phi * phi;
        return phi * p2 * (1.0 / 6.0 + p2 * (-2.0 / 15.0 + p2 * (11.0 / 90.0 - p2 * (347.0 / 2835.0))));
    }
    return 0.5 * (phi - std::atan(kSqrt2D * std::tan(phi)) / kSqrt2D);
}

// Solves F(phi) = target on [0, pi/4] by Newton's method on F^(1/3), which is nearly linear
// (F ~ phi^3 / 6 near 0), started at (6 target)^(1/3) (notes section 3). A bracket keeps every
// iterate inside the interval where F brackets the target, so the iteration cannot escape.
double invertEquatorCdf(double target) {
    if (target <= 0.0) return 0.0;
    const double root = std::cbrt(target);
    double lo = 0.0;
    double hi = kQuarterPi;
    double phi = std::min(std::cbrt(6.0 * target), kQuarterPi);
    for (int iteration = 0; iteration < 40; ++iteration) {
        const double f = equatorCdf(phi);
        if (f < target) lo = phi; else hi = phi;
        const double s2 = std::sin(phi) * std::sin(phi);
        const double derivative = 0.5 * s2 / (1.0 + s2);  // F'(phi)
        const double cbrtF = std::cbrt(f);
        // d(F^(1/3))/dphi = F' / (3 F^(2/3)).
        double next = phi - (cbrtF - root) * 3.0 * cbrtF * cbrtF / derivative;
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
        if (std::abs(next - phi) <= 1e-15 * kQuarterPi) return next;
        phi = next;
    }
    return phi;
}

}  // namespace

double stratumProjectedSolidAngle(int id) {
    switch (strataClass(id)) {
        case 0: return kPolePsa;
        case 1: return kMiddlePsa;
        default: return kEquatorPsa;
    }
}

glm::vec3 sampleStratumCosine(int id, glm::vec2 u) {
    // In the canonical stratum of the class (quadrant 0, even order) the azimuth phi runs over
    // [0, pi/4] and the stratum projects onto {r^2 in [lo(phi), hi(phi)]} of the unit disk, with
    // the bounds from z >= x (r^2 <= 1/(1+cos^2)), x >= z, z >= y (r^2 <= 1/(1+sin^2)), y >= z.
    // phi follows the CDF of the region's area, then r^2 is uniform on [lo, hi] (Malley).
    const int cls = strataClass(id);
    double tanPhi;
    if (cls == 0) {
        // F(phi) = atan(tan(phi) / sqrt2) / (2 sqrt2)  =>  tan phi = sqrt2 tan(u asin(1/sqrt3)).
        tanPhi = kSqrt2D * std::tan(u.x * kAsinInvSqrt3);
    } else if (cls == 1) {
        // F(phi) = atan(t / (sqrt2 (1 + t^2))) / (2 sqrt2), t = tan phi: with
        // kappa = tan(u asin(1/3)) the smaller root of sqrt2 kappa t^2 - t + sqrt2 kappa = 0.
        const double kappa = std::tan(u.x * kAsinThird);
        tanPhi = 2.0 * kSqrt2D * kappa / (1.0 + std::sqrt(std::max(0.0, 1.0 - 8.0 * kappa * kappa)));
    } else {
        tanPhi = std::tan(invertEquatorCdf(u.x * kEquatorPsa));
    }
    tanPhi = std::clamp(tanPhi, 0.0, 1.0);
    const double cos2 = 1.0 / (1.0 + tanPhi * tanPhi);
    const double sin2 = 1.0 - cos2;
    double lo = 0.0;
    double hi = 1.0;
    if (cls == 0) hi = 1.0 / (1.0 + cos2);
    if (cls == 1) { lo = 1.0 / (1.0 + cos2); hi = 1.0 / (1.0 + sin2); }
    if (cls == 2) lo = 1.0 / (1.0 + sin2);
    const double r2 = lo + u.y * (hi - lo);
    // 1 - r^2 as (1 - hi) + (1 - v)(hi - lo): no cancellation near the horizon.
    const double z2 = (1.0 - hi) + (1.0 - u.y) * (hi - lo);
    const double r = std::sqrt(r2);
    const double cosPhi = std::sqrt(cos2);
    const double x = r * cosPhi;
    const double y = r * cosPhi * tanPhi;
    const double z = std::sqrt(std::max(0.0, z2));
    // Sorted coordinates of the canonical triangle for the class, clamped so that rounding cannot
    // break the ordering a >= b >= c >= 0 (as sampleStratum does).
    double a, b, c;
    if (cls == 0) { a = z; b = x; c = y; }
    else if (cls == 1) { a = x; b = z; c = y; }
    else { a = x; b = y; c = z; }
    b = std::min(b, a);
    c = std::min(c, b);
    return placeInStratum(id, static_cast<float>(a), static_cast<float>(b), static_cast<float>(c));
}

}  // namespace strata
