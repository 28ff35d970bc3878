// Scale and translation invariance, and ray re-intersection: the image must not depend on where the
// scene sits or how big it is, and a ray leaving a surface must never find that surface again
// (scene.cpp's offsetRayOrigin and its error bound).
#include <doctest/doctest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>
#include <glm/geometric.hpp>

#include "render_support.h"
#include "scene/scene_loader.h"
#include "test_support.h"

using namespace strata;

namespace {

struct Placement {
    double scale;
    glm::dvec3 offset;
};

// Placements far from the unit scene: translated by 1e3 to 1e6 (along a diagonal, so every axis is
// far from the origin), scaled by 1e-3 and 1e4.
const Placement kPlacements[] = {{1.0, glm::dvec3(1e3, 1e3, -1e3)},  {1.0, glm::dvec3(1e4, -1e4, 1e4)},
                                 {1.0, glm::dvec3(1e5, -1e5, 1e5)},  {1.0, glm::dvec3(1e6, 1e6, -1e6)},
                                 {1e-3, glm::dvec3(0.0)},            {1e4, glm::dvec3(0.0)}};

// The estimators the checks hold to: the programs' defaults, and every sampler with and without
// next-event estimation (whose shadow rays must end just short of the emitter they aim at, wherever
// it is).
std::vector<PathIntegratorSettings> estimators(int depth) {
    PathIntegratorSettings defaults = kProgramDefaults;
    defaults.depth = depth;
    std::vector<PathIntegratorSettings> all{defaults};
    for (SamplerKind sampler : kSamplerKinds) {
        for (bool nee : {false, true}) all.push_back({depth, sampler, nee, -1});
    }
    return all;
}

std::string describe(const PathIntegratorSettings& s) {
    return std::string(samplerName(s.sampler)) + (s.nextEventEstimation ? " --nee" : " --no-nee") +
           (s.rouletteDepth >= 0 ? " --roulette-depth " + std::to_string(s.rouletteDepth) : "");
}

}  // namespace

TEST_CASE("scene robustness: the closed furnace gives its exact value wherever it is placed, every estimator") {
    const LoadedScene furnace = loadScene(test::sourceDir() / "assets/furnace/furnace.obj");
    // Le (1 - rho^(K+1)) / (1 - rho) with rho = 0.5, Le = 1 (path_integrator.h).
    const double exact = (1.0 - std::pow(0.5, 4)) / 0.5;
    for (const Placement& placement : kPlacements) {
        const Scene scene(test::transformMesh(furnace.scene.mesh(), placement.scale, placement.offset));
        const Camera camera(test::transformPose(furnace.settings.pose, placement.scale, placement.offset),
                            12, 12);
        for (const PathIntegratorSettings& estimator : estimators(3)) {
            CAPTURE(placement.scale);
            CAPTURE(placement.offset.x);
            const RenderSettings settings{estimator, 11, 0};
            const AccumulationBuffer buffer = test::renderPasses(scene, camera, settings, 4);
            CHECK(buffer.droppedSamples() == 0);
            const test::MeanEstimate estimate = test::estimateMean(test::pixelLuminances(buffer));
            INFO(describe(estimator) << ": " << estimate.mean << " +- " << estimate.standardError
                                     << ", exact " << exact);
            // A light leak (a path escaping), self-intersection (re-hitting the surface from behind,
            // which neither emits nor continues the path correctly) and a shadow ray blocked by the
            // emitter it aims at all bias the mean low. Cosine sampling of the furnace has no
            // variance at all (notes section 5.1).
            CHECK(std::abs(estimate.mean - exact) < 4.0 * estimate.standardError + 1e-5 * exact);
        }
    }
}

TEST_CASE("scene robustness: the Cornell box renders the same image wherever it is placed, every estimator") {
    const LoadedScene cornell = loadScene(test::cornellScene());
    constexpr int kSize = 12;
    constexpr uint32_t kPasses = 16;
    const Camera camera(cornell.settings.pose, kSize, kSize);
    for (const PathIntegratorSettings& estimator : estimators(3)) {
        const AccumulationBuffer original = test::renderPasses(cornell.scene, camera, {estimator, 1, 0}, kPasses);
        for (const Placement& placement : kPlacements) {
            CAPTURE(placement.scale);
            CAPTURE(placement.offset.x);
            INFO(describe(estimator));
            const Scene scene(test::transformMesh(cornell.scene.mesh(), placement.scale, placement.offset));
            const Camera moved(test::transformPose(cornell.settings.pose, placement.scale, placement.offset),
                               kSize, kSize);
            // Independent samples (another seed), so the comparison is a fair statistical test.
            const AccumulationBuffer buffer = test::renderPasses(scene, moved, {estimator, 2, 0}, kPasses);
            CHECK(buffer.droppedSamples() == 0);
            // Per pixel z-scores between two unbiased estimates of one image: E[z^2] = 1, and the mean
            // of 144 of them has a standard deviation near 0.12, so 1.75 is over 6 of those.
            const double z2 = test::meanSquaredZ(original, buffer);
            CAPTURE(z2);
            CHECK(z2 < 1.75);
            // And the image means agree within 4 standard errors from the spread of the pixels.
            const auto a = test::estimateMean(test::pixelLuminances(original));
            const auto b = test::estimateMean(test::pixelLuminances(buffer));
            CAPTURE(a.mean);
            CAPTURE(b.mean);
            // Pixels are not identically distributed, so compare through the per-pass errors summed.
            double variance = 0.0;
            for (size_t i = 0; i < original.pixelCount(); ++i) {
                variance += std::pow(original.passStandardError(i), 2) + std::pow(buffer.passStandardError(i), 2);
            }
            const double seDifference = std::sqrt(variance) / static_cast<double>(original.pixelCount());
            CHECK(std::abs(a.mean - b.mean) < 4.0 * seDifference);
        }
    }
}

TEST_CASE("scene robustness: rays spawned from a hit never hit the same triangle again") {
    std::mt19937_64 rng(20261122);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    auto magnitude = [&] { return std::pow(10.0, -8.0 + 16.0 * uniform(rng)); };
    auto signedMagnitude = [&] { return (uniform(rng) < 0.5 ? -1.0 : 1.0) * magnitude(); };
    auto unitVector = [&] { return test::uniformUnitVector(rng); };

    int triangles = 0;
    int spawned = 0;
    int reHits = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        // Half the triangles have every coordinate drawn over 1e-8..1e8 independently (wild,
        // skinny shapes); half sit at such a point with a size drawn over the same range.
        MeshData mesh;
        if (trial % 2 == 0) {
            for (int v = 0; v < 3; ++v) {
                mesh.positions.emplace_back(signedMagnitude(), signedMagnitude(), signedMagnitude());
            }
        } else {
            const glm::dvec3 base(signedMagnitude(), signedMagnitude(), signedMagnitude());
            const double size = magnitude();
            mesh.positions.emplace_back(base);
            mesh.positions.emplace_back(base + size * unitVector());
            mesh.positions.emplace_back(base + size * unitVector());
        }
        const glm::vec3 n = glm::cross(mesh.positions[1] - mesh.positions[0],
                                       mesh.positions[2] - mesh.positions[0]);
        // What the loader would drop (obj_loader.cpp): no area left in float.
        if (!(glm::dot(n, n) > 0.0f) || !std::isfinite(glm::dot(n, n))) continue;
        mesh.triangles.push_back({0, 1, 2});
        mesh.triangleMaterials.push_back(0);
        mesh.materials.push_back({"grey", glm::vec3(0.5f), glm::vec3(0.0f)});
        const Scene scene(mesh);

        // Aim at a random point of the triangle from a random direction and distance.
        const glm::dvec3 p0(mesh.positions[0]), p1(mesh.positions[1]), p2(mesh.positions[2]);
        double b1 = uniform(rng), b2 = uniform(rng);
        if (b1 + b2 > 1.0) b1 = 1.0 - b1, b2 = 1.0 - b2;
        const glm::dvec3 target = p0 + b1 * (p1 - p0) + b2 * (p2 - p0);
        const double extent = glm::length(p1 - p0) + glm::length(p2 - p0);
        const glm::dvec3 origin = target + (0.1 + uniform(rng)) * extent * unitVector();
        const Ray ray{glm::vec3(origin), glm::vec3(glm::normalize(target - origin))};
        const auto rayHit = scene.intersect(ray);
        if (!rayHit) continue;  // an edge-on or rounding miss: nothing to spawn from
        const SurfaceHit surface = scene.surface(*rayHit);
        const SurfaceHit* hit = &surface;
        ++triangles;
        for (int i = 0; i < 8; ++i) {
            // Any direction, either side: half of them graze the surface within 1e-3 of its plane.
            glm::dvec3 d = unitVector();
            if (i % 2 == 1) {
                const glm::dvec3 normal(hit->normal);
                d = glm::normalize(d - glm::dot(d, normal) * normal + 1e-3 * uniform(rng) *
                                   (i % 4 == 1 ? 1.0 : -1.0) * normal);
            }
            const glm::vec3 direction(d);
            if (std::abs(glm::dot(direction, hit->normal)) == 0.0f) continue;
            const Ray spawnedRay{offsetRayOrigin(*hit, direction), direction};
            ++spawned;
            if (scene.intersect(spawnedRay)) ++reHits;
        }
    }
    CAPTURE(triangles);
    CAPTURE(spawned);
    CHECK(triangles > 1000);
    CHECK(reHits == 0);
}
