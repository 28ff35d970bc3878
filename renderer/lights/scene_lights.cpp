#include "lights/scene_lights.h"

#include <limits>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "lights/area_light.h"
#include "lights/directional_light.h"
#include "lights/point_light.h"

namespace strata {
namespace {

double meanPower(const Light& light) {
    const glm::vec3 p = light.power();
    return (static_cast<double>(p.x) + p.y + p.z) / 3.0;
}

bool isBlack(const glm::vec3& v) { return !(v.x > 0.0f || v.y > 0.0f || v.z > 0.0f); }

// The radius of the sphere about the centre of the vertices' bounding box that holds them all.
float boundingSphereRadius(const std::vector<glm::vec3>& positions) {
    glm::vec3 lower(std::numeric_limits<float>::infinity());
    glm::vec3 upper = -lower;
    for (const glm::vec3& p : positions) {
        lower = glm::min(lower, p);
        upper = glm::max(upper, p);
    }
    return positions.empty() ? 0.0f : 0.5f * glm::length(upper - lower);
}

std::vector<double> powersOf(const std::vector<std::unique_ptr<Light>>& lights) {
    std::vector<double> powers;
    powers.reserve(lights.size());
    for (const auto& light : lights) powers.push_back(meanPower(*light));
    return powers;
}

}  // namespace

SceneLights::SceneLights(const MeshData& mesh)
    : triangleLight_(mesh.triangles.size(), -1), sampler_({}) {
    for (size_t i = 0; i < mesh.triangles.size(); ++i) {
        const Material& material = mesh.materials[mesh.triangleMaterials[i]];
        if (isBlack(material.emission)) continue;
        const auto& t = mesh.triangles[i];
        const glm::vec3 &p0 = mesh.positions[t[0]], &p1 = mesh.positions[t[1]], &p2 = mesh.positions[t[2]];
        auto light = material.textures.emission || material.textures.coverage
                         ? std::make_unique<AreaLight>(p0, p1, p2, material, cornerUvs(mesh, i))
                         : std::make_unique<AreaLight>(p0, p1, p2, material.emission);
        if (!(light->area() > 0.0f)) continue;
        triangleLight_[i] = static_cast<int32_t>(add(std::move(light)));
    }
    for (const PointLight& light : mesh.pointLights) add(std::make_unique<PointLight>(light));
    // Lights at infinity weigh their power by the area of the scene they can reach.
    sceneRadius_ = boundingSphereRadius(mesh.positions);
    for (const DirectionalLight& light : mesh.directionalLights) {
        add(std::make_unique<DirectionalLight>(light.direction, light.irradiance, sceneRadius_));
    }
    sceneOwnLights_ = lights_.size();
    setEnvironment(mesh.environment);
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
