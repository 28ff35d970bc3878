#include "sampling/spherical_triangle.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

namespace strata {
namespace {

// Below this sine of the angle at the first vertex, Arvo's q (which divides by it) is dominated
// by rounding; such a triangle is a sliver, and area sampling serves it as well.
constexpr double kMinSinAlpha = 1e-7;
// The smallest solid angle make() accepts whatever the caller asks: two orders of magnitude
// above the float64 breakdown of Arvo's map (about 1e-8 sr, notes 1.2).
constexpr double kMinSolidAngle = 1e-7;

// The unit direction from `from` to `to`, or zero when they coincide.
glm::dvec3 unitToward(const glm::dvec3& from, const glm::dvec3& to) {
    const glm::dvec3 d = to - from;
    const double length = glm::length(d);
    return length > 0.0 ? d / length : glm::dvec3(0.0);
}

// [x|y] of notes 1.2: the unit vector along the part of x orthogonal to the unit vector y; zero
// when x is parallel to y.
glm::dvec3 orthogonalPart(const glm::dvec3& x, const glm::dvec3& y) {
    const glm::dvec3 d = x - glm::dot(x, y) * y;
    const double length = glm::length(d);
    return length > 0.0 ? d / length : glm::dvec3(0.0);
}

double solidAngleOfUnit(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
    const double determinant = std::abs(glm::dot(a, glm::cross(b, c)));
    const double denominator = 1.0 + glm::dot(a, b) + glm::dot(b, c) + glm::dot(c, a);
    // atan2, not atan: the denominator is negative when the solid angle exceeds pi.
    return 2.0 * std::atan2(determinant, denominator);
}

}  // namespace

double sphericalTriangleSolidAngle(const glm::dvec3& point, const glm::dvec3& p0,
                                   const glm::dvec3& p1, const glm::dvec3& p2) {
    return solidAngleOfUnit(unitToward(point, p0), unitToward(point, p1), unitToward(point, p2));
}

std::optional<SphericalTriangle> SphericalTriangle::make(const glm::dvec3& point, const glm::dvec3& p0,
                                                         const glm::dvec3& p1, const glm::dvec3& p2,
                                                         double minSolidAngle) {
    SphericalTriangle t;
    t.a_ = unitToward(point, p0);
    t.b_ = unitToward(point, p1);
    t.c_ = unitToward(point, p2);
    t.solidAngle_ = solidAngleOfUnit(t.a_, t.b_, t.c_);
    if (!(t.solidAngle_ >= std::max(minSolidAngle, kMinSolidAngle))) return std::nullopt;
    // The angle alpha at a, between the great circles ab and ac, from their planes' normals:
    // (a x b) x (a x c) = (a.(b x c)) a, so sin alpha needs no cancelling difference.
    const glm::dvec3 normalAB = glm::cross(t.a_, t.b_);
    const glm::dvec3 normalAC = glm::cross(t.a_, t.c_);
    const double lengths = glm::length(normalAB) * glm::length(normalAC);
    if (!(lengths > 0.0)) return std::nullopt;
    t.cosAlpha_ = glm::dot(normalAB, normalAC) / lengths;
    t.sinAlpha_ = std::abs(glm::dot(t.a_, glm::cross(t.b_, t.c_))) / lengths;
    if (!(t.sinAlpha_ >= kMinSinAlpha)) return std::nullopt;
    // 1 - cos c as |a - b|^2 / 2: no cancellation when a and b are close.
    const glm::dvec3 ab = t.a_ - t.b_;
    t.oneMinusCosC_ = 0.5 * glm::dot(ab, ab);
    t.cPerpA_ = orthogonalPart(t.c_, t.a_);
    return t;
}

// Arvo's map (notes 1.2): the first coordinate picks the sub-triangle a b c' of area u.x times
// the whole, c' on the arc ac; the second a point on the arc from b to c' so that the density is
// uniform. Rewritten where the published form cancels (notes 1.2, pitfalls 2 and 3):
//   u = cos(A' - alpha) - cos alpha        = 2 sin(A'/2) sin(alpha - A'/2),
//   v = sin(A' - alpha) + sin alpha cos c  = 2 sin(A'/2) cos(alpha - A'/2) - sin alpha (1 - cos c),
// products of accurate factors instead of differences of O(1) terms, and the point on arc b c' by
// w = u.y |c' - b|^2 / 2 = 1 - cos(arc b p), p = (1 - w) b + sqrt(w (2 - w)) [c'|b].
glm::dvec3 SphericalTriangle::sample(glm::vec2 u) const {
    const double subArea = static_cast<double>(u.x) * solidAngle_;
    const double sinHalf = std::sin(0.5 * subArea), cosHalf = std::cos(0.5 * subArea);
    const double sinArea = 2.0 * sinHalf * cosHalf;
    const double cosArea = 1.0 - 2.0 * sinHalf * sinHalf;
    const double s = sinArea * cosAlpha_ - cosArea * sinAlpha_;  // sin(A' - alpha)
    const double t = cosArea * cosAlpha_ + sinArea * sinAlpha_;  // cos(A' - alpha)
    const double uu = 2.0 * sinHalf * (sinAlpha_ * cosHalf - cosAlpha_ * sinHalf);
    const double vv = 2.0 * sinHalf * (cosAlpha_ * cosHalf + sinAlpha_ * sinHalf) - sinAlpha_ * oneMinusCosC_;
    // q = cos(arc a c').
    const double denominator = (vv * s + uu * t) * sinAlpha_;
    double q = denominator != 0.0 ? ((vv * t - uu * s) * cosAlpha_ - vv) / denominator : 1.0;
    q = std::clamp(q, -1.0, 1.0);
    const glm::dvec3 cPrime = q * a_ + std::sqrt((1.0 - q) * (1.0 + q)) * cPerpA_;

    const glm::dvec3 bc = cPrime - b_;
    const double w = static_cast<double>(u.y) * 0.5 * glm::dot(bc, bc);
    const glm::dvec3 direction = (1.0 - w) * b_ + std::sqrt(std::max(0.0, w * (2.0 - w))) * orthogonalPart(cPrime, b_);
    return glm::normalize(direction);
}

}  // namespace strata
