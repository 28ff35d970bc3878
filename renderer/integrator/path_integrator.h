#pragma once
// The path tracer: the Neumann series of the rendering equation truncated at recursion depth K
// (paper, section 4). The camera ray finds x_1; bounce j samples a direction around x_j (sampler:
// sampling/direction_sampler.h; the BSDF built at the hit from its material:
// materials/material_table.h), traces it with Embree and adds the emitted radiance found at
// x_{j+1} times the path weight, the product of f_r cos(theta) / pdf. K counts bounces: K = 0
// shows only directly visible emission, and a furnace of albedo rho and emission Le gives
// Le (1 - rho^(K+1)) / (1 - rho).
//
// With next-event estimation each scattering vertex x_j (j < K) also connects to one point on
// one light, chosen by power or by a light tree that weighs the lights by what they can send to
// the vertex (lights/scene_lights.h). Light that is not a delta light is then
// reached two ways, by the light sample and by the next bounce's direction; the two are combined
// by multiple importance sampling with the power heuristic (Veach & Guibas 1995), whose weights
// sum to 1 for every direction, so the estimate stays unbiased for every sampler. The integrator
// knows lights only through the interface of lights/light.h.
//
// Paths go in batches: every live path of the batch traces its ray, then every shadow ray of the
// bounce is traced, and so on, bounce by bounce. Embree traces a packet of 8 rays faster than 8
// single rays, even incoherent ones, and a pixel's camera rays, which start together, faster
// still. Each path's arithmetic is what it would be alone, so a batch changes no bit of any
// path's radiance.
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <glm/vec3.hpp>

#include "geometry/frame.h"
#include "geometry/ray.h"
#include "materials/bsdf.h"
#include "sampling/direction_sampler.h"
#include "sampling/path_samples.h"
#include "scene/scene.h"

namespace strata {

struct PathIntegratorSettings {
    int depth = 5;  // K, number of bounces
    SamplerKind sampler = SamplerKind::Strata24;
    // Next-event estimation: at each scattering vertex, a shadow ray toward one light sample
    // (combined with the bounce's own direction by MIS; delta lights are reached no other way).
    bool nextEventEstimation = false;
    // Russian roulette from this many bounces on (-1: off): the path goes on with probability
    // q = min(1, sqrt(max component of its weight)) and its weight is divided by q. Unbiased; it
    // trades a little variance for not tracing paths whose weight has become small.
    int rouletteDepth = -1;
    // How next-event estimation chooses its light (lights/scene_lights.h): by power, by the
    // light tree, or by the tree in scenes with many emitters.
    LightSamplerKind lightSampler = LightSamplerKind::Auto;
    // The shadow terminator of coarse meshes with vertex normals (geometry/smooth_surface.h): a
    // shadow ray toward a light less than this cosine above a facet's plane, or below it but
    // above the shading normal's horizon, leaves from the curved surface the vertex normals
    // describe rather than the facet (Cycles' "geometry offset", 0.1 there by default). 0: off,
    // every shadow ray leaves the facet and the estimate is that of the triangles as they are.
    float terminatorOffset = 0.0f;
};

// Russian roulette from this bounce on, as the programs do by default.
inline constexpr int kRouletteDepthDefault = 4;

// The programs' defaults (strata render, view and bench): the flagship sampler, next-event
// estimation and Russian roulette. The settings' own defaults above keep the paper's plain
// estimator; the exact tests check both.
inline constexpr PathIntegratorSettings kProgramDefaults{5, SamplerKind::Strata24Bsdf, true, kRouletteDepthDefault};

// Why every path of this scene carries zero radiance, or nullopt when light can reach the camera:
// no light at all, or only delta lights that next-event estimation would have to reach.
std::optional<std::string> whyBlack(const Scene& scene, const PathIntegratorSettings& settings);

class PathIntegrator {
public:
    PathIntegrator(const Scene& scene, const PathIntegratorSettings& settings);

    // Radiance arriving along -ray.direction at ray.origin. `rays` counts the rays traced.
    glm::vec3 radiance(const Ray& ray, const PathSamples& samples, uint64_t& rays) const;
    // The same for many paths, each camera ray with its path's samples: radiance[i] is exactly
    // what the one-path call gives path i. The paths are traced together, bounce by bounce, so
    // that Embree takes each bounce's rays, and then its shadow rays, in packets. When given,
    // onSurface[i] tells whether camera ray i found a surface (for the backdrop and the
    // coverage, film/backdrop.h).
    void radiance(std::span<const Ray> cameraRays, std::span<const PathSamples> samples,
                  std::span<glm::vec3> radiance, uint64_t& rays, std::span<bool> onSurface = {}) const;

    const PathIntegratorSettings& settings() const { return settings_; }

    // Paths traced together: enough to keep Embree's packets of 8 full as paths end, few
    // enough for their state to stay on the stack. Callers do best to hand over this many.
    static constexpr size_t kBatch = 64;

private:
    // Where the path's previous direction was sampled, for the MIS weight of the light it finds.
    struct PreviousVertex {
        glm::vec3 point;  // the vertex's light reference point (extend)
        glm::vec3 normal;  // the normal its light choice was given (choiceNormal)
        float directionPdf;  // 0: no light sample could have found this direction (camera ray)
    };
    struct PathState {
        Ray ray;           // the ray the path traces next
        glm::vec3 weight;  // product of f_r cos / pdf along the path so far
        PreviousVertex previous;
        glm::vec3 absorption{0.0f};  // of the volume the ray travels through (0: none)
    };
    // A light sample's shadow ray and what it adds to the path's radiance when nothing blocks it.
    struct ShadowRay {
        Ray ray;
        float reach;  // how far the segment goes along the ray
        glm::vec3 contribution;
    };

    // At most kBatch paths, bounce by bounce.
    void traceBatch(std::span<const Ray> cameraRays, std::span<const PathSamples> samples,
                    std::span<glm::vec3> radiance, uint64_t& rays, std::span<bool> onSurface) const;
    // One bounce of one path that has traced its ray to `hit`: adds the emission found there to
    // `radiance`, asks for a light sample's shadow ray (next-event estimation), and turns the
    // path to its next ray. False when the path ends here.
    bool extend(PathState& path, const std::optional<RayHit>& hit, const PathSamples& samples, int bounce,
                glm::vec3& radiance, std::optional<ShadowRay>& shadow) const;
    // The MIS-weighted radiance from light `light`, reached at `hit` along `direction`.
    glm::vec3 emittedAlong(uint32_t light, const glm::vec3& direction, const LightHit& hit,
                           const PreviousVertex& previous) const;
    // One light sample at `surface` (normal facing the viewer) toward wo, from the numbers `u`
    // (lightNumbers), the light chosen for `reference` and `choiceNormal`: sets `shadow` to its
    // shadow ray and the reflected radiance it brings to a path of throughput `weight`,
    // MIS-weighted against the direction sampler; leaves it empty when the sample brings nothing
    // whatever the shadow ray finds.
    // `hit` and `front` (the side of the triangle the viewer is on) place the shadow ray's origin
    // near the shadow terminator (PathIntegratorSettings::terminatorOffset).
    void lightSample(const RayHit& hit, bool front, const SurfaceHit& surface, const glm::vec3& reference,
                     const glm::vec3& choiceNormal, const Frame& frame, const glm::vec3& wo, const Bsdf& bsdf,
                     const glm::vec3& u, const glm::vec3& weight, std::optional<ShadowRay>& shadow) const;
    // The light chosen for a sample at `point`, whose surface has normal `normal` (zero: light
    // from either side counts), and the probability of that choice for `light`.
    LightChoice chooseLight(float u, const glm::vec3& point, const glm::vec3& normal) const;
    float choiceProbability(uint32_t light, const glm::vec3& point, const glm::vec3& normal) const;

    // The random numbers a light sample draws (PathSamples::lightSample): the choice and the
    // point when the scene has more than one light, the point alone for a single light with
    // extent (an emitting triangle, the environment), none for a single delta light.
    enum class LightNumbers { None, Point, ChoiceAndPoint };
    static LightNumbers lightNumbersFor(const SceneLights& lights);
    // lightSample's numbers as PathSamples::lightSample lays them out, the unused ones 0.
    glm::vec3 lightNumbers(const PathSamples& samples, int bounce) const;

    const Scene& scene_;
    PathIntegratorSettings settings_;
    DiffuseWarp warp_;   // the sampler's, for the density of a light sample's direction (MIS)
                         // and the diffuse numbers of a material that reads none
    bool sampleLights_;  // next-event estimation on and something to sample
    bool lightTree_;     // the choice by the light tree, not by power
    bool raysFindRadiance_;  // a ray can find a light, or an unlit surface
    LightNumbers lightNumbers_;
};

}  // namespace strata
