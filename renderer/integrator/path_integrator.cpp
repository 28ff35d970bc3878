#include "integrator/path_integrator.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <glm/exponential.hpp>
#include <glm/geometric.hpp>

#include "geometry/rounding.h"
#include "geometry/smooth_surface.h"
#include "util/components.h"

namespace strata {
namespace {

// Veach's power heuristic (exponent 2): the weight of the technique with density `own`.
float powerHeuristic(float own, float other) {
    const float a = own * own;
    const float b = other * other;
    return a > 0.0f ? a / (a + b) : 0.0f;
}

// The unit direction and the length of the segment from `origin` to `end` (length 0 where the two
// coincide). Out of line: the bounce loop rarely needs it, and inlined into it (the loop is
// flattened) it cost every bounce registers, 1.6% more instructions on the Cornell box; its
// arguments and result travel in registers, not through memory.
struct Segment {
    glm::vec3 direction;
    float length;
};
[[gnu::noinline]] Segment segmentBetween(glm::vec3 origin, glm::vec3 end) {
    const glm::vec3 segment = end - origin;
    const float length = glm::length(segment);
    if (!(length > 0.0f)) return {glm::vec3(0.0f), 0.0f};
    return {segment / length, length};
}

// The origin of a ray leaving `surface` (its normal turned toward the viewer) along `direction`:
// `reference`, the origin on the viewer's side, unless the ray crosses to the other side.
glm::vec3 spawnOrigin(const SurfaceHit& surface, const glm::vec3& reference, const glm::vec3& direction) {
    return glm::dot(direction, surface.normal) < 0.0f ? offsetRayOrigin(surface, direction) : reference;
}

// Turns the geometric normal toward the viewer direction `toViewer`, and the shading normal onto
// the geometric normal's side; returns the cosine between the viewer and the geometric normal and
// whether the viewer is on the surface's front (counter-clockwise) side, which tells a dielectric
// whether the path enters or leaves it. When the viewer is below the shading hemisphere although
// above the surface (vertex normals tilted away from it, seen at a grazing angle), the shading
// normal gives way to the geometric one: its hemisphere would hold no direction toward the
// viewer, and the surface would show a black rim. A flat surface's two normals are one, and all
// but the first test are skipped.
struct ViewerSide {
    float cosine;
    bool front;
};
ViewerSide orientToward(SurfaceHit& surface, const glm::vec3& toViewer) {
    float cosine = glm::dot(surface.normal, toViewer);
    const bool front = cosine >= 0.0f;
    if (!front) {
        surface.normal = -surface.normal;
        surface.shadingNormal = -surface.shadingNormal;
        cosine = -cosine;
    }
    if (surface.smooth) {
        if (glm::dot(surface.shadingNormal, surface.normal) < 0.0f) surface.shadingNormal = -surface.shadingNormal;
        if (!(glm::dot(surface.shadingNormal, toViewer) > 0.0f)) surface.shadingNormal = surface.normal;
    }
    return {cosine, front};
}

// A clear coat's own normal (Scene::coatNormal) turned as orientToward turned the surface's: to the
// viewer's side of the triangle and onto the geometric normal's side. The shading normal takes its
// place where the viewer is below the coat's hemisphere, or the coat's normal below the shading
// one's (a coat is tilted within the hemisphere of the surface it covers).
glm::vec3 coatNormalToward(glm::vec3 coat, const SurfaceHit& surface, bool front, const glm::vec3& toViewer) {
    if (!front) coat = -coat;
    if (glm::dot(coat, surface.normal) < 0.0f) coat = -coat;
    const bool seen = glm::dot(coat, toViewer) > 0.0f && glm::dot(coat, surface.shadingNormal) > 0.0f;
    return seen ? coat : surface.shadingNormal;
}

// The BSDF at a hit whose clear coat has a normal of its own, the coat turned to it in `frame`.
// Out of line, as segmentBetween is: few surfaces have such a coat, and inlined, with the hit's
// BSDF made mutable for it, it cost every bounce of the point-lit Cornell box 0.6% more
// instructions.
[[gnu::noinline]] Bsdf bsdfWithCoatNormal(const Scene& scene, const RayHit& hit, const SurfaceHit& surface,
                                          bool front, const Frame& frame, const glm::vec3& toViewer) {
    const uint32_t material = scene.triangle(hit.triangle).material;
    Bsdf bsdf = scene.materials().bsdf(material, surface.uv, front, surface.colour);
    bsdf.tiltCoat(frame.toLocal(coatNormalToward(scene.coatNormal(hit, surface.uv), surface, front, toViewer)));
    return bsdf;
}

// Whether a world direction leaves the surface on the side its lobe sends light to: a reflection
// on the viewer's side of the geometric normal (oriented toward the viewer), a transmission on the
// other. A shading normal can tilt a lobe's direction across the surface itself; such a direction
// counts, with weight zero. On a flat surface the shading and geometric sides are one.
bool onLobeSide(const SurfaceHit& surface, const glm::vec3& direction, BsdfFlags lobe) {
    if (!surface.smooth) return true;
    const float side = glm::dot(direction, surface.normal);
    return isTransmission(lobe) ? side < 0.0f : side > 0.0f;
}

// The numbers of a BSDF's lobe choice and of its lobes other than the diffuse one, which a
// Lambertian surface does not read: drawn out of line, as segmentBetween is.
[[gnu::noinline]] void addLobeNumbers(BsdfNumbers& numbers, const PathSamples& samples, int bounce) {
    const glm::vec3 lobe = samples.lobeSample(bounce);
    numbers.lobeChoice = lobe.x;
    numbers.lobePoint = {lobe.y, lobe.z};
}

// Russian roulette's survival probability for a path of weight `weight` (the 1/survival of
// earlier bounces included): min(1, sqrt(max component)), as Cycles does, from bounce
// kRouletteDepthDefault on. Measured at 256x256, depth 9, next-event estimation, medians of 3
// alternated runs of 24 spp, against no roulette (variance per path relMSE x spp; relMSE x CPU
// seconds, lower is better):
//   Cornell box, bsdf sampler:        0.154 -> 0.168;  0.0112 -> 0.0083 (0.69 of the rays)
//   Cornell box, strata24-qmc:        0.204 -> 0.215;  0.0179 -> 0.0132
//   furnace (albedo 0.5), strata24-qmc: 0.018 -> 0.031; 0.0022 -> 0.0019
// min(1, max component) from bounce 2 raises the Cornell variance per path to 0.261 and gains
// less (0.0093, 0.0118), and in the furnace it loses (0.0043). Where the estimate without
// roulette has almost no variance (the furnace with bsdf or cosine sampling: every path carries
// the same light to its end) any roulette costs: 0.00003 -> 0.00067 here, the least of the rules
// tried. The bare product of f cos / pdf (without the 1/survival divisions) stops far too many
// paths: 11x the variance per path on the Cornell box.
float rouletteSurvival(const glm::vec3& weight) {
    return std::min(1.0f, std::sqrt(maxComponent(weight)));
}

}  // namespace

PathIntegrator::PathIntegrator(const Scene& scene, const PathIntegratorSettings& settings)
    : scene_(scene),
      settings_(settings),
      warp_(samplerChoice(settings.sampler).warp),
      sampleLights_(settings.nextEventEstimation && !scene.lights().sampler().empty()),
      lightTree_(scene.lights().usesTree(settings.lightSampler)),
      raysFindRadiance_(scene.lights().raysFindLight() || scene.summary().unlitTriangles > 0),
      lightNumbers_(lightNumbersFor(scene.lights())) {}

PathIntegrator::LightNumbers PathIntegrator::lightNumbersFor(const SceneLights& lights) {
    if (lights.size() > 1) return LightNumbers::ChoiceAndPoint;
    return lights.raysFindLight() ? LightNumbers::Point : LightNumbers::None;
}

std::optional<std::string> whyBlack(const Scene& scene, const PathIntegratorSettings& settings) {
    const SceneLights& lights = scene.lights();
    if (scene.summary().unlitTriangles > 0) return std::nullopt;  // seen whatever lights it
    if (lights.size() == 0) return "the scene has no emitter (no Ke > 0, no point lights, no environment)";
    if (lights.raysFindLight()) return std::nullopt;
    if (!settings.nextEventEstimation) return "its only lights are point, spot or directional lights, which need next-event estimation (not --no-nee)";
    if (settings.depth == 0) return "its only lights are point, spot or directional lights, which depth 0 never reaches";
    return std::nullopt;
}

glm::vec3 PathIntegrator::radiance(const Ray& ray, const PathSamples& samples, uint64_t& rays) const {
    glm::vec3 result;
    radiance(std::span(&ray, 1), std::span(&samples, 1), std::span(&result, 1), rays);
    return result;
}

void PathIntegrator::radiance(std::span<const Ray> cameraRays, std::span<const PathSamples> samples,
                              std::span<glm::vec3> radiance, uint64_t& rays,
                              std::span<bool> onSurface) const {
    for (size_t first = 0; first < cameraRays.size(); first += kBatch) {
        const size_t count = std::min(kBatch, cameraRays.size() - first);
        traceBatch(cameraRays.subspan(first, count), samples.subspan(first, count),
                   radiance.subspan(first, count), rays,
                   onSurface.empty() ? onSurface : onSurface.subspan(first, count));
    }
}

// Flattened: every call below it, samplers, random streams and BSDFs included, is inlined into
// the bounce loop (Embree's and the lights' virtual calls stay calls). Left to its own heuristics
// GCC kept the stratum map and the stratum schedule as calls, and strata24 rendered 8% slower
// than with them inlined (bundled Cornell box, one thread, medians of 3 alternated runs; images
// bit-identical), most likely from their vec3 returns and the loop state saved around them.
[[gnu::flatten]] void PathIntegrator::traceBatch(std::span<const Ray> cameraRays,
                                                 std::span<const PathSamples> samples,
                                                 std::span<glm::vec3> radiance, uint64_t& rays,
                                                 std::span<bool> onSurface) const {
    std::array<PathState, kBatch> paths;
    std::array<size_t, kBatch> live;  // the paths still going, by index into `paths`
    size_t liveCount = cameraRays.size();
    for (size_t i = 0; i < liveCount; ++i) {
        paths[i] = PathState{cameraRays[i], glm::vec3(1.0f), PreviousVertex{glm::vec3(0.0f), glm::vec3(0.0f), 0.0f}};
        radiance[i] = glm::vec3(0.0f);
        live[i] = i;
    }
    std::array<Ray, kBatch> traced;
    std::array<std::optional<RayHit>, kBatch> hits;
    // The bounce's shadow rays: what each brings, and to which path, if nothing blocks it.
    std::array<Ray, kBatch> shadowRays;
    std::array<float, kBatch> shadowReach;
    std::array<glm::vec3, kBatch> shadowContribution;
    std::array<size_t, kBatch> shadowPath;
    std::array<bool, kBatch> blocked;
    // A loop, not recursion: depth 10000 costs no stack.
    for (int bounce = 0; liveCount > 0; ++bounce) {
        for (size_t k = 0; k < liveCount; ++k) traced[k] = paths[live[k]].ray;
        // Camera rays start together; after the first bounce the paths part ways.
        scene_.intersect(std::span(traced.data(), liveCount), std::span(hits.data(), liveCount),
                         bounce == 0 ? Scene::Coherence::Coherent : Scene::Coherence::Incoherent);
        rays += liveCount;
        if (bounce == 0 && !onSurface.empty()) {
            for (size_t k = 0; k < liveCount; ++k) onSurface[k] = hits[k].has_value();
        }
        size_t goingOn = 0;
        size_t shadowCount = 0;
        for (size_t k = 0; k < liveCount; ++k) {
            const size_t i = live[k];
            std::optional<ShadowRay> shadow;
            if (extend(paths[i], hits[k], samples[i], bounce, radiance[i], shadow)) live[goingOn++] = i;
            if (shadow) {
                shadowRays[shadowCount] = shadow->ray;
                shadowReach[shadowCount] = shadow->reach;
                shadowContribution[shadowCount] = shadow->contribution;
                shadowPath[shadowCount++] = i;
            }
        }
        if (shadowCount > 0) {
            scene_.occluded(std::span(shadowRays.data(), shadowCount), std::span(shadowReach.data(), shadowCount),
                            std::span(blocked.data(), shadowCount));
            rays += shadowCount;
            for (size_t s = 0; s < shadowCount; ++s) {
                if (!blocked[s]) radiance[shadowPath[s]] += shadowContribution[s];
            }
        }
        liveCount = goingOn;
    }
}

bool PathIntegrator::extend(PathState& path, const std::optional<RayHit>& hit, const PathSamples& samples,
                            int bounce, glm::vec3& radiance, std::optional<ShadowRay>& shadow) const {
    const SceneLights& lights = scene_.lights();
    const Ray& ray = path.ray;
    if (!hit) {
        // The path left the scene: what arrives along it comes from the lights at infinity.
        const LightHit miss{};
        for (uint32_t light : lights.lightsAtInfinity()) {
            radiance += path.weight * emittedAlong(light, ray.direction, miss, path.previous);
        }
        return false;
    }
    // Inside an absorbing volume the segment just traced keeps exp(-sigma t) (Beer-Lambert).
    if (!isZero(path.absorption)) path.weight *= glm::exp(-path.absorption * hit->t);
    const Scene::Triangle& triangle = scene_.triangle(hit->triangle);
    if (triangle.light >= 0) {
        const LightHit onLight{triangle.normal, {hit->u, hit->v}};
        radiance += path.weight * emittedAlong(static_cast<uint32_t>(triangle.light), ray.direction,
                                               onLight, path.previous);
    }
    if (bounce == settings_.depth || scene_.materials().isBlack(triangle.material)) {
        // An unlit surface (a black one) shows its colour to whatever ray finds it: no light
        // sample could, so at full weight.
        if (scene_.materials().isUnlit(triangle.material)) {
            const SurfaceHit surface = scene_.surface(*hit);
            radiance += path.weight * scene_.materials().unlitColour(triangle.material, surface.uv, surface.colour);
        }
        return false;
    }
    // The bounce's random numbers depend on the path, not on the surface: drawn first, their
    // arithmetic overlaps the surface's rather than lengthening the chain from the hit to the
    // next ray (cornell_point, defaults: 5% of the CPU time). A material with no diffuse lobe
    // (a metal, glass) never reads the diffuse lobe's stratum and point, and they are not drawn.
    const DiffuseSampling diffuseU = scene_.materials().readsDiffuseNumbers(triangle.material)
                                         ? diffuseNumbers(settings_.sampler, samples, bounce)
                                         : DiffuseSampling{warp_, -1, glm::vec2(0.0f)};
    const glm::vec3 lightU = sampleLights_ ? lightNumbers(samples, bounce) : glm::vec3(0.0f);

    // The frame is turned to the side the ray came from: reflection is two-sided, and a
    // dielectric is told which of its sides that is.
    SurfaceHit surface = scene_.surface(*hit);
    const ViewerSide viewer = orientToward(surface, -ray.direction);
    if (!(viewer.cosine > 0.0f)) return false;  // along the surface: nothing seen
    // The strata, the BSDF's cosines and wo live in the shading frame.
    const Frame frame = Frame::fromNormal(surface.shadingNormal);
    const glm::vec3 wo = frame.toLocal(-ray.direction);
    const Bsdf bsdf = scene_.materials().coatHasOwnNormal(triangle.material)
                          ? bsdfWithCoatNormal(scene_, *hit, surface, viewer.front, frame, -ray.direction)
                          : scene_.materials().bsdf(triangle.material, surface.uv, viewer.front, surface.colour);
    // Lights are sampled from, and their densities for MIS measured from, the origin that a
    // reflected ray leaves from rather than the hit point: far from the origin of the coordinates
    // the two are apart by a margin the scene's size does not bound, and the light sample and the
    // reflected ray it is weighed against must see the emitters from one point for their MIS
    // weights to sum to one.
    const glm::vec3 reference = offsetRayOrigin(surface, surface.normal);
    // The light tree may pass over lights below a reflecting surface, whose light sample
    // reflects nothing (lightSample); a transmitting one receives from both sides.
    const glm::vec3 choiceNormal = isTransmission(bsdf.flags()) ? glm::vec3(0.0f) : surface.normal;
    // Light that reaches the camera after this vertex's reflection counts as bounce + 1
    // bounces, which the depth allows here. A delta lobe reflects nothing a light sample finds.
    if (sampleLights_ && bsdf.hasNonSpecularLobe()) {
        lightSample(*hit, viewer.front, surface, reference, choiceNormal, frame, wo, bsdf, lightU, path.weight,
                    shadow);
    }
    // The next ray could add only the emission it finds (bounce + 1 == depth): where every light
    // is a delta light and no surface is unlit, none, and it is not traced.
    if (bounce + 1 == settings_.depth && !raysFindRadiance_) return false;
    BsdfNumbers numbers{diffuseU};
    if (bsdf.readsLobeNumbers()) addLobeNumbers(numbers, samples, bounce);
    const std::optional<BsdfSample> sampled = bsdf.sample(wo, numbers);
    if (!sampled) return false;  // the sample is lost: it counts, with weight zero
    const glm::vec3 direction = frame.toWorld(sampled->wi);
    if (!onLobeSide(surface, direction, sampled->flags)) return false;
    path.weight *= sampled->weight;
    if (isZero(path.weight)) return false;
    if (settings_.rouletteDepth >= 0 && bounce + 1 >= settings_.rouletteDepth) {
        const float survival = rouletteSurvival(path.weight);
        if (samples.roulette(bounce) >= survival) return false;
        path.weight /= survival;
    }
    // A transmission through the front enters the volume the surface bounds; through the back it
    // leaves it (volumes are not nested).
    if (isTransmission(sampled->flags)) {
        path.absorption = viewer.front ? scene_.materials().absorption(triangle.material) : glm::vec3(0.0f);
    }
    // Emission found after a delta lobe could not have been found by a light sample: it counts
    // at full weight (directionPdf 0).
    path.previous = PreviousVertex{reference, choiceNormal, isSpecular(sampled->flags) ? 0.0f : sampled->pdf};
    path.ray = Ray{spawnOrigin(surface, reference, direction), direction};
    return true;
}

glm::vec3 PathIntegrator::emittedAlong(uint32_t index, const glm::vec3& direction,
                                       const LightHit& hit, const PreviousVertex& previous) const {
    const Light& light = scene_.lights().light(index);
    const glm::vec3 emitted = light.emitted(direction, hit);
    if (isZero(emitted)) return emitted;
    if (!sampleLights_ || previous.directionPdf == 0.0f) return emitted;
    const float lightPdf = choiceProbability(index, previous.point, previous.normal) *
                           light.pdf(previous.point, direction, hit);
    return emitted * powerHeuristic(previous.directionPdf, lightPdf);
}

glm::vec3 PathIntegrator::lightNumbers(const PathSamples& samples, int bounce) const {
    // A single light is chosen whatever the number (light_sampler.h), and a delta light's
    // sample does not read its point (light.h): the numbers left out would change no bit.
    switch (lightNumbers_) {
        case LightNumbers::None: return glm::vec3(0.0f);
        case LightNumbers::Point: {
            const glm::vec2 point = samples.lightPoint(bounce);
            return {0.0f, point.x, point.y};
        }
        case LightNumbers::ChoiceAndPoint: break;
    }
    return samples.lightSample(bounce);
}

LightChoice PathIntegrator::chooseLight(float u, const glm::vec3& point, const glm::vec3& normal) const {
    return lightTree_ ? scene_.lights().tree().choose(u, point, normal) : scene_.lights().sampler().choose(u);
}

float PathIntegrator::choiceProbability(uint32_t light, const glm::vec3& point, const glm::vec3& normal) const {
    return lightTree_ ? scene_.lights().tree().probability(light, point, normal)
                      : scene_.lights().sampler().probability(light);
}

void PathIntegrator::lightSample(const RayHit& hit, bool front, const SurfaceHit& surface,
                                 const glm::vec3& reference, const glm::vec3& choiceNormal, const Frame& frame,
                                 const glm::vec3& wo, const Bsdf& bsdf, const glm::vec3& u,
                                 const glm::vec3& weight, std::optional<ShadowRay>& shadow) const {
    const LightChoice choice = chooseLight(u.x, reference, choiceNormal);
    const Light& light = scene_.lights().light(choice.light);
    const auto sample = light.sample(reference, {u.y, u.z});
    if (!sample) return;
    const glm::vec3 wi = frame.toLocal(sample->direction);
    const float geometricCosine = glm::dot(sample->direction, surface.normal);
    // A smooth surface's shadow ray near the terminator leaves from the curved surface its vertex
    // normals describe, `lift` off the facet (geometry/smooth_surface.h); zero: from the facet.
    glm::vec3 lift(0.0f);
    if (isTransmission(bsdf.flags())) {
        // Light from either side: the shading and geometric sides of its direction must agree.
        if (!(geometricCosine * wi.z > 0.0f)) return;
    } else {
        // Light from below the shading hemisphere reflects nothing; nor does light from behind
        // the facet itself, unless the shadow ray leaves from above it.
        if (!(wi.z > 0.0f)) return;
        if (surface.smooth && settings_.terminatorOffset > 0.0f) {
            const float share = terminatorLiftShare(geometricCosine, settings_.terminatorOffset);
            if (share > 0.0f) lift = share * scene_.smoothSurfaceLift(hit, front);
            if (!(glm::dot(lift, surface.normal) > 0.0f)) lift = glm::vec3(0.0f);
        }
        if (surface.smooth && !(geometricCosine > 0.0f) && lift == glm::vec3(0.0f)) return;
    }
    const bool lifted = lift != glm::vec3(0.0f);
    const glm::vec3 f = bsdf.evaluate(wo, wi);
    if (isZero(f)) return;
    const float cosine = std::abs(wi.z);
    glm::vec3 origin = spawnOrigin(surface, reference, sample->direction);
    glm::vec3 direction = sample->direction;
    float reach = sample->distance;
    if (lifted) {
        // The lifted point, off the facet on its viewer's side by its own rounding too.
        const glm::vec3 lifted = surface.point + lift;
        origin = offsetRayOrigin(lifted, surface.pointError + gammaBound(1) * magnitudes(lifted), surface.normal,
                                 surface.normal);
    }
    // A segment to a point on a surface ends short of it: shortened, or at the point moved off
    // the surface where shortening would not clear its rounding error (light.h). From a lifted
    // origin, the segment to a light's point is drawn again from there.
    if (sample->endsOffSurface) {
        const Segment segment = segmentBetween(origin, sample->offSurfaceEnd);
        if (!(segment.length > 0.0f)) return;
        direction = segment.direction;
        reach = segment.length * (1.0f - kShadowRayShortening);
    } else {
        if (lifted && std::isfinite(reach)) {
            const Segment segment = segmentBetween(origin, reference + direction * reach);
            if (!(segment.length > 0.0f)) return;
            direction = segment.direction;
            reach = segment.length;
        }
        if (sample->onSurface) reach *= 1.0f - kShadowRayShortening;
    }
    float scale = cosine / choice.probability;
    // Below a reflecting facet's plane the direction sampler's rays do not go (onLobeSide): a
    // lifted light sample there is the only technique, at full weight.
    if (!light.isDelta() && !(lifted && !(geometricCosine > 0.0f))) {
        const float lightPdf = choice.probability * sample->pdf;
        scale = cosine * powerHeuristic(lightPdf, bsdf.pdf(wo, wi, warp_)) / lightPdf;
    }
    // Written field by field into `shadow`: a ShadowRay made first and then copied in goes
    // through the stack in 16-byte words over its fields' narrower stores, a store-to-load
    // forwarding stall.
    shadow.emplace();
    shadow->ray = Ray{origin, direction};
    shadow->reach = reach;
    shadow->contribution = weight * (f * sample->radiance * scale);
}

}  // namespace strata
