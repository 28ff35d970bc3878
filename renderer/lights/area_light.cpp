#include "lights/area_light.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "geometry/rounding.h"
#include "util/constants.h"

namespace strata {

AreaLight::AreaLight(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2,
                     const glm::vec3& radiance, double minSphericalSolidAngle)
    : p0_(p0), p1_(p1), p2_(p2), radiance_(radiance), minSphericalSolidAngle_(minSphericalSolidAngle) {
    const glm::vec3 cross = glm::cross(p1 - p0, p2 - p0);
    normal_ = glm::normalize(cross);
    area_ = static_cast<float>(0.5 * glm::length(glm::dvec3(cross)));
    centroid_ = (glm::dvec3(p0) + glm::dvec3(p1) + glm::dvec3(p2)) / 3.0;
    radius_ = std::max({glm::distance(centroid_, glm::dvec3(p0)), glm::distance(centroid_, glm::dvec3(p1)),
                        glm::distance(centroid_, glm::dvec3(p2))});
    // One bound covers the points both samplers compute: p0 + b1 e1 + b2 e2 in float with
    // barycentrics at most 1 (a few operations on terms up to |p0| + |e1| + |e2|), and a point of
    // the triangle found in double and rounded once; plus Embree's rounding.
    const float largest = maxComponent(glm::max(glm::max(magnitudes(p0), magnitudes(p1)), magnitudes(p2)));
    pointError_ = gammaBound(5) * (magnitudes(p0) + magnitudes(p1 - p0) + magnitudes(p2 - p0)) + traversalError(largest);
    normalError_ = 2.0f * glm::dot(magnitudes(normal_), pointError_);
}

AreaLight::AreaLight(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2, const Material& material,
                     const std::array<glm::vec2, 3>& uvs, double minSphericalSolidAngle)
    : AreaLight(p0, p1, p2, material.meanEmission(), minSphericalSolidAngle) {
    textured_ = &material;
    uvs_ = uvs;
}

glm::vec3 AreaLight::sampledRadianceAlong(const glm::dvec3& point, const glm::dvec3& direction, double distance) const {
    if (!textured_) return radiance_;
    // The barycentrics of the point reached, from the sub-triangles' areas.
    const glm::dvec3 a(p0_), e1 = glm::dvec3(p1_) - a, e2 = glm::dvec3(p2_) - a;
    const glm::dvec3 q = point + distance * direction - a;
    const glm::dvec3 n = glm::cross(e1, e2);
    const double twiceArea = glm::dot(n, n);
    const double b1 = glm::dot(glm::cross(q, e2), n) / twiceArea;
    const double b2 = glm::dot(glm::cross(e1, q), n) / twiceArea;
    return sampledRadianceAt(static_cast<float>(b1), static_cast<float>(b2));
}

std::optional<SphericalTriangle> AreaLight::spherical(const glm::vec3& point) const {
    // Only a point in front sees the emitting side; behind, area sampling finds nothing either.
    const glm::dvec3 x(point);
    const double height = glm::dot(glm::dvec3(normal_), x - glm::dvec3(p0_));
    if (!(height > 0.0)) return std::nullopt;
    // Omega = integral of cos / r^2 over the triangle <= A / r_min^2, and r_min is at least the
    // height and the distance to the triangle's bounding sphere: a far point is told apart
    // without the exact solid angle (this bound is part of the choice, so it stays consistent).
    const double reach = std::max(height, glm::distance(x, centroid_) - radius_);
    if (area_ < minSphericalSolidAngle_ * reach * reach) return std::nullopt;
    return SphericalTriangle::make(point, p0_, p1_, p2_, minSphericalSolidAngle_);
}

double AreaLight::sphericalSolidAngle(const glm::vec3& point) const {
    const auto triangle = spherical(point);
    return triangle ? triangle->solidAngle() : 0.0;
}

std::optional<LightSample> AreaLight::sample(const glm::vec3& point, glm::vec2 u) const {
    const auto triangle = spherical(point);
    if (!triangle) return sampleArea(point, u);
    const glm::dvec3 direction = triangle->sample(u);
    // Where the direction meets the triangle's plane.
    const double cosLight = -glm::dot(glm::dvec3(normal_), direction);
    if (!(cosLight > 0.0)) return std::nullopt;
    const double distance = glm::dot(glm::dvec3(normal_), glm::dvec3(point) - glm::dvec3(p0_)) / cosLight;
    // The point, found in double, is rounded once to float.
    const glm::vec3 onLight(glm::dvec3(point) + distance * direction);
    return sampleAt(onLight, glm::vec3(direction), static_cast<float>(distance),
                    sampledRadianceAlong(glm::dvec3(point), direction, distance),
                    static_cast<float>(1.0 / triangle->solidAngle()));
}

std::optional<LightSample> AreaLight::sampleArea(const glm::vec3& point, glm::vec2 u) const {
    // Uniform by area: barycentrics (1 - sqrt(u), sqrt(u)(1 - v), sqrt(u) v).
    const float s = std::sqrt(u.x);
    const float b1 = s * (1.0f - u.y);
    const float b2 = s * u.y;
    const glm::vec3 onLight = p0_ + b1 * (p1_ - p0_) + b2 * (p2_ - p0_);
    const glm::vec3 toLight = onLight - point;
    const float distanceSquared = glm::dot(toLight, toLight);
    if (!(distanceSquared > 0.0f)) return std::nullopt;
    const float distance = std::sqrt(distanceSquared);
    const glm::vec3 direction = toLight / distance;
    const float cosLight = -glm::dot(normal_, direction);
    if (!(cosLight > 0.0f)) return std::nullopt;  // the point sees its back (one-sided)
    return sampleAt(onLight, direction, distance, sampledRadianceAt(b1, b2), distanceSquared / (area_ * cosLight));
}

// The shortened segment ends off the surface by shortening x distance x cos along the normal.
// Where that does not clear the sampled point's error, the shadow ray runs to the point offset
// by that error instead (pbrt-v4's SpawnRayTo between two offset points).
std::optional<LightSample> AreaLight::sampleAt(const glm::vec3& onLight, const glm::vec3& direction, float distance,
                                               const glm::vec3& radiance, float pdf) const {
    // Written field by field into the one object returned: a LightSample copied into an
    // optional goes through the stack in 16-byte words over its fields' narrower stores, a
    // store-to-load forwarding stall on every light sample.
    std::optional<LightSample> sample(std::in_place);
    sample->direction = direction;
    sample->distance = distance;
    sample->radiance = radiance;
    sample->pdf = pdf;
    sample->onSurface = true;
    const float cosLight = -glm::dot(normal_, direction);
    if (!(kShadowRayShortening * distance * cosLight > normalError_)) {
        sample->endsOffSurface = true;
        sample->offSurfaceEnd = offsetRayOrigin(onLight, pointError_, normal_, -direction);
    }
    return sample;
}

float AreaLight::pdf(const glm::vec3& point, const glm::vec3& direction, const LightHit& hit) const {
    const float cosLight = -glm::dot(hit.normal, direction);
    if (!(cosLight > 0.0f)) return 0.0f;
    if (const auto triangle = spherical(point)) return static_cast<float>(1.0 / triangle->solidAngle());
    // The distance from `point`, as sampleArea measures it, rather than the hit's from the ray's
    // origin, which is off the surface by a margin that grows with the coordinates: the two
    // strategies' densities must agree for their MIS weights to sum to one.
    const double height = glm::dot(glm::dvec3(normal_), glm::dvec3(point) - glm::dvec3(p0_));
    const double distance = height / cosLight;
    return static_cast<float>(distance * distance / (area_ * cosLight));
}

glm::vec3 AreaLight::emitted(const glm::vec3& direction, const LightHit& hit) const {
    return glm::dot(hit.normal, direction) < 0.0f ? radianceAt(hit.barycentrics.x, hit.barycentrics.y)
                                                : glm::vec3(0.0f);
}

// Lambertian emission into one hemisphere: pi Le A (Le's texture mean for a textured emitter).
glm::vec3 AreaLight::power() const { return kPi * area_ * radiance_; }

// One normal, and emission into its front hemisphere only.
std::optional<LightBounds> AreaLight::bounds() const {
    LightBounds bounds;
    bounds.lower = glm::min(glm::min(p0_, p1_), p2_);
    bounds.upper = glm::max(glm::max(p0_, p1_), p2_);
    bounds.axis = normal_;
    bounds.cosSpread = 1.0f;
    bounds.cosEmission = 0.0f;
    return bounds;
}

}  // namespace strata
