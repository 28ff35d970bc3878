#pragma once
// A triangle seen from a point as a spherical triangle on the unit sphere about the point: its
// solid angle, and Arvo's (1995) area-preserving map from [0,1)^2 onto it, so that directions
// toward the triangle can be drawn uniformly by solid angle (notes section 1.2).
//
// Everything is computed in double precision: in float32 Arvo's map breaks down below about
// 3e-4 sr (notes 1.2, "Measured"), in float64 only below about 1e-8 sr, far under the solid angles
// at which AreaLight (lights/area_light.h) switches to it.
#include <optional>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace strata {

// The solid angle the triangle (p0, p1, p2) subtends from `point`, by Van Oosterom and
// Strackee's formula tan(Omega/2) = |a.(b x c)| / (1 + a.b + b.c + c.a) with a, b, c the unit
// directions toward the vertices (notes 1.2, fix 1): exact for triangles of any size, where
// Girard's alpha + beta + gamma - pi cancels catastrophically for small ones. 0 when `point` lies
// on a vertex.
double sphericalTriangleSolidAngle(const glm::dvec3& point, const glm::dvec3& p0,
                                   const glm::dvec3& p1, const glm::dvec3& p2);

class SphericalTriangle {
public:
    // The triangle seen from `point`, or nullopt when its solid angle is below `minSolidAngle`
    // or it is too thin to sample (the angle at the first vertex has a sine below 1e-7: Arvo's
    // map divides by it). `minSolidAngle` is the caller's choice; it is clamped to at least
    // 1e-7 sr, above the float64 breakdown of notes 1.2.
    static std::optional<SphericalTriangle> make(const glm::dvec3& point, const glm::dvec3& p0,
                                                 const glm::dvec3& p1, const glm::dvec3& p2,
                                                 double minSolidAngle);

    double solidAngle() const { return solidAngle_; }
    // A unit direction from the point toward the triangle, uniform by solid angle over it when
    // `u` is uniform in [0,1)^2 (density 1 / solidAngle()).
    glm::dvec3 sample(glm::vec2 u) const;

private:
    SphericalTriangle() = default;

    glm::dvec3 a_, b_, c_;  // unit directions toward the vertices
    glm::dvec3 cPerpA_;     // [c|a]: unit, orthogonal to a, in the plane of a and c
    double solidAngle_ = 0.0;
    double cosAlpha_ = 0.0, sinAlpha_ = 0.0;  // the angle at vertex a
    double oneMinusCosC_ = 0.0;               // 1 - a.b, the arc c = ab opposite vertex c
};

}  // namespace strata
