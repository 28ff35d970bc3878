#pragma once
// Every light of a scene behind the one interface of light.h, and the two choices among them: by
// power alone (light_sampler.h) and by a light tree that weighs each light by what it can send to
// the receiving point (light_tree.h). The integrator asks it for a light sample at each scattering vertex,
// for the light a ray found on a triangle, and for what arrives along a ray that left the scene;
// it knows no light by its kind. A new kind of light is a file in this folder and one line in
// SceneLights' constructor. The default environment rule (environment.h) is applied here.
//
// The default sky lights a scene given no environment unless the scene has a light that outshines
// it: a point or directional light; an emitting triangle brighter than the sky, its radiance
// above kDefaultSkyRadiance in some channel (a textured emitter's factor times its brightest
// texel): brighter than a white surface under that sky; or emitting triangles that make up at
// least half of the scene's area (a furnace, whose emission is what it shows). Emitters no brighter
// than the sky (glowing labels, screens: glTF's emissive factor, which alone stays at most 1) then
// glow in the daylight; they are lights still, found by rays and sampled.
//
// The environment comes last so that it can be replaced alone: relighting a scene rebuilds the
// environment's light and the choices among the lights, never the lights of its triangles.
//
// The lights know no scene: the scene (scene/scene.h) hands them a list of light descriptions,
// its emitting triangles in world space among them.
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "lights/directional_light.h"
#include "lights/environment.h"
#include "lights/light.h"
#include "lights/light_sampler.h"
#include "lights/light_tree.h"
#include "lights/point_light.h"
#include "lights/spot_light.h"
#include "materials/material.h"

namespace strata {

// Whether a surface of this material emits (Ke > 0 in some channel): its triangles are lights.
inline bool emitsLight(const Material& material) {
    const glm::vec3& ke = material.emission;
    return ke.x > 0.0f || ke.y > 0.0f || ke.z > 0.0f;
}

// How next-event estimation chooses its light: by power, by the light tree, or by the tree only
// where a scene has enough emitters for it to pay (SceneLights::usesTree).
enum class LightSamplerKind { Power, Tree, Auto };
// Every kind, the default first: what a front end lists.
inline constexpr std::array<LightSamplerKind, 3> kLightSamplerKinds = {
    LightSamplerKind::Auto, LightSamplerKind::Power, LightSamplerKind::Tree};
// "power", "tree", "auto", and back; nullopt for an unknown name.
std::string_view lightSamplerName(LightSamplerKind kind);
std::optional<LightSamplerKind> parseLightSamplerKind(std::string_view name);
// The names, for messages: "auto|power|tree".
std::string lightSamplerNames();

// An emitting triangle as the scene hands it over: where it is in world space, counter-clockwise
// seen from the side it emits from, and what it emits.
struct EmittingTriangle {
    uint32_t triangle;  // the scene's index of it, by which a ray's hit finds its light
    std::array<glm::vec3, 3> corners;
    const Material* material;         // emitsLight(); outlives the lights
    std::array<glm::vec2, 3> uvs{};   // the corners' texture coordinates, where `material` reads
};

// Everything a scene is lit by, as it hands it to SceneLights.
struct LightDescriptions {
    size_t triangles = 0;  // how many triangles the scene has: the range of lightOnTriangle
    std::vector<EmittingTriangle> emitters;
    std::vector<PointLight> pointLights;
    std::vector<SpotLight> spotLights;
    std::vector<DirectionalLight> directionalLights;
    Environment environment;
    // Of a sphere that holds the scene, by which lights at infinity weigh their power.
    float sceneRadius = 0.0f;
    // Of all the world's triangles (each placement of a shared mesh's), by which the default
    // sky's rule weighs the emitters' area.
    double surfaceArea = 0.0;
};

class SceneLights {
public:
    // The emitting triangles (those of positive area) as area lights, in the order given, then
    // the point lights, then the directional lights, then the environment (after the default rule).
    explicit SceneLights(const LightDescriptions& descriptions);

    // Replaces the environment (the descriptions' at construction) and the choice among the
    // lights; the other lights and their indices stay.
    void setEnvironment(const Environment& given);
    // The environment in use, after the default rule (Default becomes None or Uniform).
    const Environment& environment() const { return environment_; }

    size_t size() const { return lights_.size(); }
    const Light& light(uint32_t index) const { return *lights_[index]; }
    const LightSampler& sampler() const { return sampler_; }
    const LightTree& tree() const { return tree_; }
    // Whether next-event estimation chooses by the tree under `kind`: Auto resolved by the
    // number of lights in the tree (light_tree.h's threshold).
    bool usesTree(LightSamplerKind kind) const;

    // The light on `triangle`, or -1 when it emits nothing.
    int32_t lightOnTriangle(uint32_t triangle) const { return triangleLight_[triangle]; }
    // The lights a ray that leaves the scene receives radiance from: the environment, if any.
    const std::vector<uint32_t>& lightsAtInfinity() const { return atInfinity_; }
    // The largest radiance component arriving from outside the scene (0 without an environment).
    float maxRadianceAtInfinity() const { return maxRadianceAtInfinity_; }
    // Whether the scene, given no environment and no light that outshines the sky, is lit by
    // the default uniform white environment (the rule above).
    bool litByDefault() const { return litByDefault_; }
    // Why it is, for messages: "the scene has no light", or that its lights are emitters no
    // brighter than the sky; empty when it is not.
    std::string_view defaultSkyReason() const;
    // The delta lights (point and directional), which next-event estimation alone reaches.
    size_t deltaLights() const { return deltaLights_; }
    // Whether a ray can find a light: some light is not a delta light.
    bool raysFindLight() const { return deltaLights_ < lights_.size(); }

private:
    uint32_t add(std::unique_ptr<Light> light);

    std::vector<std::unique_ptr<Light>> lights_;
    size_t sceneOwnLights_ = 0;  // the lights before the environment's
    bool outshineSky_ = false;   // those lights, by the rule above
    float sceneRadius_ = 0.0f;   // of the bounding sphere, which lights at infinity need
    Environment environment_;
    std::vector<int32_t> triangleLight_;
    std::vector<uint32_t> atInfinity_;
    size_t deltaLights_ = 0;
    float maxRadianceAtInfinity_ = 0.0f;
    bool litByDefault_ = false;
    LightSampler sampler_;
    LightTree tree_;
};

// The note a scene lit by the default sky prints on stderr: why, and how to keep it dark.
std::string defaultEnvironmentNote(const SceneLights& lights);

}  // namespace strata
