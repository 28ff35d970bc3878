#include "lights/scene_lights.h"


#include "lights/area_light.h"
#include "lights/directional_light.h"
#include "lights/point_light.h"

namespace strata {
namespace {

double meanPower(const Light& light) {
    const glm::vec3 p = light.power();
    return (static_cast<double>(p.x) + p.y + p.z) / 3.0;
}

std::vector<double> powersOf(const std::vector<std::unique_ptr<Light>>& lights) {
    std::vector<double> powers;
    powers.reserve(lights.size());
    for (const auto& light : lights) powers.push_back(meanPower(*light));
    return powers;
}

}  // namespace

SceneLights::SceneLights(const LightDescriptions& descriptions)
    : sceneRadius_(descriptions.sceneRadius), triangleLight_(descriptions.triangles, -1), sampler_({}) {
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
    // Lights at infinity weigh their power by the area of the scene they can reach.
    for (const DirectionalLight& light : descriptions.directionalLights) {
        add(std::make_unique<DirectionalLight>(light.direction, light.irradiance, sceneRadius_));
    }
    sceneOwnLights_ = lights_.size();
    setEnvironment(descriptions.environment);
}

void SceneLights::setEnvironment(const Environment& given) {
    lights_.resize(sceneOwnLights_);
    atInfinity_.clear();
    environment_ = resolveEnvironment(given, sceneOwnLights_ > 0);
    maxRadianceAtInfinity_ = maxRadiance(environment_);
    litByDefault_ = given.kind == Environment::Kind::Default && environment_.kind != Environment::Kind::None;
    if (auto light = makeEnvironmentLight(environment_, sceneRadius_)) atInfinity_.push_back(add(std::move(light)));
    sampler_ = LightSampler(powersOf(lights_));
}

uint32_t SceneLights::add(std::unique_ptr<Light> light) {
    if (light->isDelta()) ++deltaLights_;
    lights_.push_back(std::move(light));
    return static_cast<uint32_t>(lights_.size() - 1);
}

}  // namespace strata
