#include "lights/scene_lights.h"

#include <glm/geometric.hpp>

#include "lights/area_light.h"
#include "lights/directional_light.h"
#include "lights/point_light.h"
#include "util/components.h"

namespace strata {
namespace {

// Emitting triangles that make up this share of the scene's area outshine the default sky
// whatever their radiance.
constexpr double kEmittingShare = 0.5;

double areaOf(const std::array<glm::vec3, 3>& corners) {
    const glm::dvec3 p0(corners[0]);
    return 0.5 * glm::length(glm::cross(glm::dvec3(corners[1]) - p0, glm::dvec3(corners[2]) - p0));
}

// The rule of scene_lights.h: whether the scene's own lights outshine the default sky.
bool outshineSky(const LightDescriptions& descriptions) {
    if (!descriptions.pointLights.empty() || !descriptions.spotLights.empty() ||
        !descriptions.directionalLights.empty()) {
        return true;
    }
    double emitting = 0.0;
    for (const EmittingTriangle& emitter : descriptions.emitters) {
        const double area = areaOf(emitter.corners);
        if (!(area > 0.0)) continue;  // no light (the constructor's rule)
        if (emitter.material->maxEmission() > kDefaultSkyRadiance) return true;
        emitting += area;
    }
    return emitting > 0.0 && emitting >= kEmittingShare * descriptions.surfaceArea;
}

std::vector<double> sampledPowersOf(const std::vector<std::unique_ptr<Light>>& lights) {
    std::vector<double> powers;
    powers.reserve(lights.size());
    for (const auto& light : lights) powers.push_back(meanComponent(light->sampledPower()));
    return powers;
}

}  // namespace

SceneLights::SceneLights(const LightDescriptions& descriptions)
    : sceneRadius_(descriptions.sceneRadius), triangleLight_(descriptions.triangles, -1), sampler_({}), tree_({}) {
    for (const EmittingTriangle& emitter : descriptions.emitters) {
        const Material& material = *emitter.material;
        const auto& [p0, p1, p2] = emitter.corners;
        auto light = material.textures.emission || material.textures.coverage
                         ? std::make_unique<AreaLight>(p0, p1, p2, material, emitter.uvs)
                         : std::make_unique<AreaLight>(p0, p1, p2, material.emission);
        if (!(light->area() > 0.0f)) continue;
        triangleLight_[emitter.triangle] = static_cast<int32_t>(add(std::move(light)));
    }
    for (const PointLight& light : descriptions.pointLights) add(std::make_unique<PointLight>(light));
    for (const SpotLight& light : descriptions.spotLights) add(std::make_unique<SpotLight>(light));
    // Lights at infinity weigh their power by the area of the scene they can reach.
    for (const DirectionalLight& light : descriptions.directionalLights) {
        add(std::make_unique<DirectionalLight>(light.direction, light.irradiance, sceneRadius_));
    }
    sceneOwnLights_ = lights_.size();
    outshineSky_ = outshineSky(descriptions);
    setEnvironment(descriptions.environment);
}

void SceneLights::setEnvironment(const Environment& given) {
    lights_.resize(sceneOwnLights_);
    atInfinity_.clear();
    environment_ = resolveEnvironment(given, outshineSky_);
    maxRadianceAtInfinity_ = maxRadiance(environment_);
    litByDefault_ = given.kind == Environment::Kind::Default && environment_.kind != Environment::Kind::None;
    if (auto light = makeEnvironmentLight(environment_, sceneRadius_)) atInfinity_.push_back(add(std::move(light)));
    sampler_ = LightSampler(sampledPowersOf(lights_));
    tree_ = LightTree(lights_);
}

// The tree costs at every choice a walk of its depth, two importance estimates per step, against
// the power sampler's one lookup; it pays where a point's few nearby or facing emitters are a
// small part of many. Measured (docs/method.md, next-event estimation; one thread, 48 spp,
// medians of 3 alternated runs): on the bundled Cornell box (2 emitting triangles, one panel,
// which the tree cannot tell apart) the same error in 1.24x the time; on the many-light hall
// (assets/many-lights, 606 emitting triangles) 3.2x less error in 1.9x the time, 0.61x the
// relMSE x seconds. Counts between the two were not measured; 8 leaves the Cornell-like scenes
// (a lamp or two of a few triangles each) to the power sampler.
constexpr size_t kAutoTreeLights = 8;

bool SceneLights::usesTree(LightSamplerKind kind) const {
    switch (kind) {
        case LightSamplerKind::Power: return false;
        case LightSamplerKind::Tree: return true;
        case LightSamplerKind::Auto: break;
    }
    return tree_.treeLights() >= kAutoTreeLights;
}

std::string_view lightSamplerName(LightSamplerKind kind) {
    switch (kind) {
        case LightSamplerKind::Power: return "power";
        case LightSamplerKind::Tree: return "tree";
        case LightSamplerKind::Auto: break;
    }
    return "auto";
}

std::optional<LightSamplerKind> parseLightSamplerKind(std::string_view name) {
    for (LightSamplerKind kind : kLightSamplerKinds) {
        if (name == lightSamplerName(kind)) return kind;
    }
    return std::nullopt;
}

std::string lightSamplerNames() {
    std::string names;
    for (LightSamplerKind kind : kLightSamplerKinds) {
        if (!names.empty()) names += '|';
        names += lightSamplerName(kind);
    }
    return names;
}

std::string_view SceneLights::defaultSkyReason() const {
    if (!litByDefault_) return {};
    return sceneOwnLights_ == 0 ? "the scene has no light"
                                : "the scene's only lights are emitters no brighter than a white sky of radiance 1";
}

std::string defaultEnvironmentNote(const SceneLights& lights) {
    return std::string(lights.defaultSkyReason()) +
           "; lighting it with a uniform white environment (--env none for black)";
}

uint32_t SceneLights::add(std::unique_ptr<Light> light) {
    if (light->isDelta()) ++deltaLights_;
    lights_.push_back(std::move(light));
    return static_cast<uint32_t>(lights_.size() - 1);
}

}  // namespace strata
