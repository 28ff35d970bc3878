#pragma once
// What next-event estimation and multiple importance sampling need from a light, whatever its
// kind: a direction sampled toward it with its density, the density of a given direction, the
// radiance a ray receives from it (a ray that found it, or one that left the scene), its total
// power, and the power of what its samples draw, by which LightSampler (light_sampler.h) chooses
// among the scene's lights.
//
// Densities are per unit solid angle at the receiving point and do not include the probability of
// choosing the light. A delta light (a point light) is reached by sampling only: its pdf is 0 and
// its sample carries the radiance already divided by its (singular) density.
#include <optional>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "lights/light_bounds.h"

namespace strata {

// A shadow ray toward a point on a surface stops this fraction of its length short of it (pbrt-v4's
// ShadowEpsilon), so that the surface cannot occlude its own point.
inline constexpr float kShadowRayShortening = 1e-4f;

struct LightSample {
    glm::vec3 direction;  // unit, from the receiving point toward the light
    float distance;       // to the sampled point; infinity for a light at infinity
    glm::vec3 radiance;   // arriving along -direction (for a delta light: intensity / distance^2)
    float pdf;            // solid-angle density of `direction`; 0 for a delta light
    bool onSurface;       // the point lies on scene geometry, which a shadow ray must stop short of
    // For a point on a surface where the shortening does not clear the point's rounding error,
    // which grows with the distance from the origin of the coordinates (geometry/rounding.h): the
    // point moved off the surface toward the receiver by that error, for the shadow ray to end
    // at instead.
    bool endsOffSurface = false;
    glm::vec3 offSurfaceEnd{0.0f};
};

// Where a ray reached a light: for a light on the scene's triangles, the triangle's unit
// geometric normal and the hit's barycentrics of vertices 1 and 2 (where a textured emitter looks
// up its radiance); a ray that left the scene has no normal.
struct LightHit {
    glm::vec3 normal{0.0f};
    glm::vec2 barycentrics{0.0f};
};

class Light {
public:
    virtual ~Light() = default;

    // A direction toward the light from `point`, `u` uniform in [0,1)^2; nullopt when the sample
    // carries nothing to `point` (it faces away, say).
    virtual std::optional<LightSample> sample(const glm::vec3& point, glm::vec2 u) const = 0;
    // The solid-angle density with which sample() at `point` gives `direction`, which reached the
    // light at `hit`.
    virtual float pdf(const glm::vec3& point, const glm::vec3& direction, const LightHit& hit) const = 0;
    // Radiance arriving along -direction from the light, reached at `hit`.
    virtual glm::vec3 emitted(const glm::vec3& direction, const LightHit& hit) const = 0;
    // Total emitted power (W), per colour channel.
    virtual glm::vec3 power() const = 0;
    // The power of the part of the light that sample() draws. All of it, but for a light at
    // infinity that leaves the part every direction receives alike to the BSDF's samples (MIS
    // compensation, environment_map.h); 0 for one that gives sample() nothing to draw.
    virtual glm::vec3 sampledPower() const { return power(); }
    // Reached only by sampling (no ray can find it). A delta light has one direction toward
    // each point, so its sample() does not read `u`.
    virtual bool isDelta() const { return false; }
    // Where the light is and which way it emits, for a light tree (light_tree.h) to cluster it;
    // nullopt for a light without extent in the scene (delta lights, lights at infinity), which
    // stays outside the tree. The bounds' power is the tree's to fill in.
    virtual std::optional<LightBounds> bounds() const { return std::nullopt; }
};

}  // namespace strata
