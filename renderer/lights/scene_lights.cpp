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

// Emitting triangles that make up this share of the scene's area outshine the default sky
// whatever their radiance.
constexpr double kEmittingShare = 0.5;

double triangleArea(const MeshData& mesh, size_t triangle) {
    const auto& t = mesh.triangles[triangle];
    const glm::dvec3 p0(mesh.positions[t[0]]);
    return 0.5 * glm::length(glm::cross(glm::dvec3(mesh.positions[t[1]]) - p0,
                                        glm::dvec3(mesh.positions[t[2]]) - p0));
}

// The rule of scene_lights.h: whether the mesh's lights (triangleLight: each triangle's, -1 for
// none) outshine the default sky.
bool outshineSky(const MeshData& mesh, const std::vector<int32_t>& triangleLight) {
    if (!mesh.pointLights.empty() || !mesh.directionalLights.empty()) return true;
    double area = 0.0;
    double emitting = 0.0;
    for (size_t i = 0; i < mesh.triangles.size(); ++i) {
        const double a = triangleArea(mesh, i);
        area += a;
        if (triangleLight[i] < 0) continue;
        if (mesh.materials[mesh.triangleMaterials[i]].maxEmission() > kDefaultSkyRadiance) return true;
        emitting += a;
    }
    return emitting > 0.0 && emitting >= kEmittingShare * area;
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
    outshineSky_ = outshineSky(mesh, triangleLight_);
    setEnvironment(mesh.environment);
}

void SceneLights::setEnvironment(const Environment& given) {
    lights_.resize(sceneOwnLights_);
    atInfinity_.clear();
    environment_ = resolveEnvironment(given, outshineSky_);
    maxRadianceAtInfinity_ = maxRadiance(environment_);
    litByDefault_ = given.kind == Environment::Kind::Default && environment_.kind != Environment::Kind::None;
    if (auto light = makeEnvironmentLight(environment_, sceneRadius_)) atInfinity_.push_back(add(std::move(light)));
    sampler_ = LightSampler(powersOf(lights_));
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
