#pragma once
// Every light of a scene behind the one interface of light.h, and the power-based choice among
// them (light_sampler.h). The integrator asks it for a light sample at each scattering vertex,
// for the light a ray found on a triangle, and for what arrives along a ray that left the scene;
// it knows no light by its kind. A new kind of light is a file in this folder and one line in
// SceneLights' constructor. The default environment rule (environment.h) is applied here.
//
// The environment comes last so that it can be replaced alone: relighting a scene rebuilds the
// environment's light and the power-based choice, never the lights of its triangles.
#include <cstdint>
#include <memory>
#include <vector>

#include "lights/light.h"
#include "lights/light_sampler.h"
#include "scene/mesh.h"

namespace strata {

class SceneLights {
public:
    // The emitting triangles (Ke > 0 and positive area) as area lights, then the point lights,
    // then the directional lights, then the environment (after the default rule).
    explicit SceneLights(const MeshData& mesh);

    // Replaces the environment (mesh.environment at construction) and the choice among the
    // lights; the other lights and their indices stay.
    void setEnvironment(const Environment& given);
    // The environment in use, after the default rule (Default becomes None or Uniform).
    const Environment& environment() const { return environment_; }

    size_t size() const { return lights_.size(); }
    const Light& light(uint32_t index) const { return *lights_[index]; }
    const LightSampler& sampler() const { return sampler_; }

    // The light on `triangle`, or -1 when it emits nothing.
    int32_t lightOnTriangle(uint32_t triangle) const { return triangleLight_[triangle]; }
    // The lights a ray that leaves the scene receives radiance from: the environment, if any.
    const std::vector<uint32_t>& lightsAtInfinity() const { return atInfinity_; }
    // The largest radiance component arriving from outside the scene (0 without an environment).
    float maxRadianceAtInfinity() const { return maxRadianceAtInfinity_; }
    // Whether the scene, having no light of its own and no environment given, is lit by the
    // default uniform white environment (environment.h).
    bool litByDefault() const { return litByDefault_; }
    // The delta lights (point and directional), which next-event estimation alone reaches.
    size_t deltaLights() const { return deltaLights_; }

private:
    uint32_t add(std::unique_ptr<Light> light);

    std::vector<std::unique_ptr<Light>> lights_;
    size_t sceneOwnLights_ = 0;  // the lights before the environment's
    float sceneRadius_ = 0.0f;   // of the bounding sphere, which lights at infinity need
    Environment environment_;
    std::vector<int32_t> triangleLight_;
    std::vector<uint32_t> atInfinity_;
    size_t deltaLights_ = 0;
    float maxRadianceAtInfinity_ = 0.0f;
    bool litByDefault_ = false;
    LightSampler sampler_;
};

}  // namespace strata
