#include "sampling/strata24_cosine.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "sampling/strata24.h"

namespace strata {
namespace {

constexpr double kPiD = 3.14159265358979323846;
constexpr double kSqrt2D = 1.41421356237309504880;
constexpr double kQuarterPi = kPiD / 4.0;
// Notes section 3; tests/sampling/test_strata24_cosine.cpp recomputes them from the closed forms.
constexpr double kPolePsa = 0.2176049378417758;     // asin(1/sqrt 3) / (2 sqrt 2)
constexpr double kMiddlePsa = 0.1201504915862442;   // asin(1/3) / (2 sqrt 2)
constexpr double kEquatorPsa = 0.0549436522707042;  // pi/8 - acos(1/sqrt 3) / (2 sqrt 2)
constexpr double kAsinInvSqrt3 = 0.61547970867038734;  // asin(1/sqrt 3)
constexpr double kAsinThird = 0.33983690945412194;     // asin(1/3)

int strataClass(int id) { return (id % 6) / 2; }  // 0 pole, 1 middle, 2 equator

// The equator class's azimuth CDF (projected area swept up to phi, canonical triangle
// {x >= y >= z}): F(phi) = (phi - atan(sqrt2 tan phi) / sqrt2) / 2, given sin and cos of phi.
// The direct formula cancels for small phi, where the series
// phi^3/6 - 2 phi^5/15 + 11 phi^7/90 - 347 phi^9/2835 is used.
double equatorCdf(double phi, double sinPhi, double cosPhi) {
    if (phi < 0.02) {
        const double p2 = phi * phi;
        return phi * p2 * (1.0 / 6.0 + p2 * (-2.0 / 15.0 + p2 * (11.0 / 90.0 - p2 * (347.0 / 2835.0))));
    }
    return 0.5 * (phi - std::atan2(kSqrt2D * sinPhi, cosPhi) / kSqrt2D);
}

// Solves F(phi) = target on [0, pi/4] by Newton's method, F'(phi) = sin^2 / (2 (1 + sin^2)).
// The start inverts F's first two series terms (notes section 3 iterate on F^(1/3), which is
// nearly linear; from this start plain Newton on F converges in 2 to 4 steps without a cube root
// per step). A bracket keeps every iterate inside the interval where F brackets the target, so
// the iteration cannot escape.
double invertEquatorCdf(double target) {
    if (target <= 0.0) return 0.0;
    double lo = 0.0;
    double hi = kQuarterPi;
    // phi^3/6 (1 - 4 phi^2 / 5) = target, inverted to first order: within 1% everywhere.
    const double c = std::cbrt(6.0 * target);
    double phi = std::min(c * (1.0 + 4.0 / 15.0 * c * c), kQuarterPi);
    for (int iteration = 0; iteration < 60; ++iteration) {
        const double sinPhi = std::sin(phi);
        const double cosPhi = std::cos(phi);
        const double f = equatorCdf(phi, sinPhi, cosPhi);
        if (f < target) lo = phi; else hi = phi;
        const double s2 = sinPhi * sinPhi;
        const double step = (f - target) * 2.0 * (1.0 + s2) / s2;
        // A step below 1e-7 relative leaves an error of order its square, ~1e-14, after it is
        // taken (quadratic convergence). Tested before the bracket: a step that rounds to
        // nothing would otherwise look like an escape and trigger a bisection.
        if (std::abs(step) <= 1e-7 * phi) return phi - step;
        phi -= step;
        if (!(phi > lo && phi < hi)) phi = 0.5 * (lo + hi);
    }
    return phi;
}

// tan(phi) of the equator class's azimuth as a function of c = u^(1/3), where F(phi) = u PSA:
// smooth on [0, 1] (phi ~ (6 PSA)^(1/3) c near 0), so a cubic Hermite interpolant through 128
// intervals, with the exact values (Newton above) and slopes at the nodes, is within 2e-9 of it
// everywhere (tests/sampling/test_strata24_cosine.cpp checks 1e-8): below float precision, at one
// cube root per sample instead of a Newton iteration's sines, cosines and arctangents.
class EquatorAzimuthTable {
public:
    static constexpr int kIntervals = 128;

    EquatorAzimuthTable() {
        for (int i = 0; i <= kIntervals; ++i) {
            const double c = static_cast<double>(i) / kIntervals;
            if (i == 0) {
                nodes_[0] = {0.0, std::cbrt(6.0 * kEquatorPsa) / kIntervals};
                continue;
            }
            const double phi = invertEquatorCdf(kEquatorPsa * c * c * c);
            const double s2 = std::sin(phi) * std::sin(phi);
            const double sec2 = 1.0 / (std::cos(phi) * std::cos(phi));
            // dt/dc = sec^2(phi) dphi/dF dF/dc, with dphi/dF = 2 (1 + s^2) / s^2, dF/dc = 3 PSA c^2.
            const double slope = sec2 * 2.0 * (1.0 + s2) / s2 * 3.0 * kEquatorPsa * c * c;
            nodes_[static_cast<size_t>(i)] = {std::tan(phi), slope / kIntervals};
        }
    }

    double tanPhi(double u) const {
        const double x = std::cbrt(u) * kIntervals;
        const int i = std::min(static_cast<int>(x), kIntervals - 1);
        const double s = x - i;
        const Node& a = nodes_[static_cast<size_t>(i)];
        const Node& b = nodes_[static_cast<size_t>(i) + 1];
        const double s2 = s * s;
        const double s3 = s2 * s;
        return (2.0 * s3 - 3.0 * s2 + 1.0) * a.value + (s3 - 2.0 * s2 + s) * a.intervalSlope +
               (3.0 * s2 - 2.0 * s3) * b.value + (s3 - s2) * b.intervalSlope;
    }

private:
    struct Node {
        double value;
        double intervalSlope;  // dt/dc times the interval's width, as the Hermite basis takes it
    };
    std::array<Node, kIntervals + 1> nodes_{};
};

}  // namespace

double equatorTanPhi(double u) {
    static const EquatorAzimuthTable table;
    return table.tanPhi(u);
}

double equatorTanPhiExact(double u) { return std::tan(invertEquatorCdf(u * kEquatorPsa)); }

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
        tanPhi = equatorTanPhi(u.x);
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
