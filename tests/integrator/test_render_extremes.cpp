// The renderer at its extremes: emission up to 1e30, albedo 0 and 1, depth 0 and 10000, images of
// one pixel and of 8192 pixels a side, more threads than cores. Furnace values are exact
// (path_integrator.h): Le (1 - rho^(K+1)) / (1 - rho), and Le (K + 1) when rho = 1.
#include <doctest/doctest.h>

#include <cmath>
#include <thread>
#include <glm/geometric.hpp>

#include "render_support.h"
#include "scene/scene_loader.h"
#include "test_support.h"

using namespace strata;

namespace {

// The bundled furnace with its one material replaced.
Scene furnaceWith(const glm::vec3& albedo, const glm::vec3& emission) {
    const LoadedScene furnace = loadScene(test::sourceDir() / "assets/furnace/furnace.obj");
    MeshData mesh = furnace.scene.mesh();
    for (Material& m : mesh.materials) {
        m.diffuse = albedo;
        m.emission = emission;
    }
    return Scene(std::move(mesh));
}

Camera furnaceCamera(int width, int height) {
    return Camera(loadScene(test::sourceDir() / "assets/furnace/furnace.obj").settings.pose, width, height);
}

RenderSettings withDepth(int depth, uint64_t seed = 5) {
    RenderSettings settings;
    settings.integrator.depth = depth;
    settings.seed = seed;
    return settings;
}

// Checks the image mean against `exact` within 4 standard errors from the spread of the pixels.
void checkFurnaceMean(const AccumulationBuffer& buffer, double exact) {
    REQUIRE(test::allFinite(buffer));
    CHECK(buffer.droppedSamples() == 0);
    const test::MeanEstimate estimate = test::estimateMean(test::pixelLuminances(buffer));
    CAPTURE(estimate.mean);
    CAPTURE(estimate.standardError);
    CHECK(std::abs(estimate.mean - exact) < 4.0 * estimate.standardError);
}

}  // namespace

TEST_CASE("render extremes: emission of 1e30 scales the image exactly, with nothing non-finite") {
    const Camera camera = furnaceCamera(8, 8);
    const Scene unit = furnaceWith(glm::vec3(0.5f), glm::vec3(1.0f));
    const Scene huge = furnaceWith(glm::vec3(0.5f), glm::vec3(1e30f));
    // Same seed: the same paths, so the two images differ only by the factor 1e30 and rounding.
    const AccumulationBuffer a = test::renderPasses(unit, camera, withDepth(5), 2);
    const AccumulationBuffer b = test::renderPasses(huge, camera, withDepth(5), 2);
    REQUIRE(test::allFinite(b));
    CHECK(b.droppedSamples() == 0);
    for (size_t i = 0; i < a.pixelCount(); ++i) {
        CAPTURE(i);
        CHECK(std::abs(b.mean(i).x / (1e30 * a.mean(i).x) - 1.0) < 1e-5);
        CHECK(std::isfinite(b.passStandardError(i)));
    }
}

TEST_CASE("render extremes: albedo 0 gives exactly the emission, albedo 1 gives Le (K + 1)") {
    const Camera camera = furnaceCamera(8, 8);
    const AccumulationBuffer black =
        test::renderPasses(furnaceWith(glm::vec3(0.0f), glm::vec3(1.0f)), camera, withDepth(5), 2);
    for (size_t i = 0; i < black.pixelCount(); ++i) CHECK(black.mean(i) == glm::dvec3(1.0));

    constexpr int kDepth = 4;
    checkFurnaceMean(test::renderPasses(furnaceWith(glm::vec3(1.0f), glm::vec3(1.0f)), camera,
                                        withDepth(kDepth), 8),
                     kDepth + 1.0);
}

TEST_CASE("render extremes: depth 0 shows the emission only, depth 10000 runs in bounded memory") {
    const Camera camera = furnaceCamera(8, 8);
    const Scene furnace = furnaceWith(glm::vec3(0.5f), glm::vec3(1.0f));
    const AccumulationBuffer direct = test::renderPasses(furnace, camera, withDepth(0), 1);
    for (size_t i = 0; i < direct.pixelCount(); ++i) CHECK(direct.mean(i) == glm::dvec3(1.0));

    // rho = 0.5: 2 (1 - 0.5^10001) = 2 in double. The path weight underflows to 0 after some
    // hundred bounces, which ends the path (path_integrator.cpp): no recursion, no per-bounce
    // allocation, so the peak RSS does not grow with the depth.
    const long before = test::peakRssKilobytes();
    checkFurnaceMean(test::renderPasses(furnace, camera, withDepth(10000), 8), 2.0);
    // Albedo 1 keeps the expected weight at 1, so paths run much deeper before underflowing.
    const AccumulationBuffer deep = test::renderPasses(furnaceWith(glm::vec3(1.0f), glm::vec3(1.0f)),
                                                       furnaceCamera(2, 2), withDepth(10000), 2);
    CHECK(test::allFinite(deep));
    CHECK(deep.droppedSamples() == 0);
    const long grown = test::peakRssKilobytes() - before;
    CAPTURE(grown);
    CHECK(grown < 64 * 1024);
}

TEST_CASE("render extremes: a 1x1 image and an 8192x8192 image") {
    const Scene furnace = furnaceWith(glm::vec3(0.5f), glm::vec3(1.0f));
    // One pixel: 96 passes of 24 paths estimate the exact furnace value; the error is the
    // per-pass one (strata24's paths within a pass are not independent).
    const AccumulationBuffer one = test::renderPasses(furnace, furnaceCamera(1, 1), withDepth(3), 96);
    REQUIRE(test::allFinite(one));
    const double exact = (1.0 - std::pow(0.5, 4)) / 0.5;
    CHECK(std::abs(luminance(one.mean(0)) - exact) < 4.0 * one.passStandardError(0));

    // 8192^2 at depth 0, one step of a pass (one path per pixel, as the viewer delivers passes):
    // every one of the 67M pixels, the last included, holds exactly its one sample of the
    // emission. That is indexing and tiling at the image's full extent with its 4.8 GB of
    // accumulation state (72 bytes a pixel); a whole pass would only repeat it 24 times.
    // The furnace near the origin is traced with Embree's fast triangle test, which lets a few
    // rays in 10^8 through its edges (traversal_precision.h): such a pixel holds its sample of
    // nothing, and there may be no more of them than the scene's rounding gap share predicts.
    const Camera big = furnaceCamera(8192, 8192);
    AccumulationBuffer image(8192, 8192);
    ProgressiveRenderer renderer(furnace, big, withDepth(0));
    renderer.renderStep(image, 0, 0);
    size_t wrong = 0;
    size_t escaped = 0;
    for (size_t i = 0; i < image.pixelCount(); ++i) {
        const bool sawNothing = image.mean(i) == glm::dvec3(0.0);
        escaped += sawNothing;
        wrong += image.sampleCount(i) != 1 || (image.mean(i) != glm::dvec3(1.0) && !sawNothing);
    }
    CHECK(wrong == 0);
    CAPTURE(escaped);
    CHECK(static_cast<double>(escaped) <= furnace.summary().roundingGapShare * static_cast<double>(image.pixelCount()));
    CHECK(renderer.counters().paths == image.pixelCount());
    // The camera's corner rays are finite, unit and symmetric.
    const Ray first = big.generateRay(0, 0, {0.0f, 0.0f});
    const Ray last = big.generateRay(8191, 8191, {1.0f, 1.0f});
    CHECK(std::abs(glm::length(first.direction) - 1.0f) < 1e-6f);
    CHECK(std::abs(glm::length(last.direction) - 1.0f) < 1e-6f);
    const glm::vec3 forward = glm::normalize(big.pose().lookAt - big.pose().position);
    CHECK(glm::length(first.direction + last.direction - 2.0f * glm::dot(first.direction, forward) * forward) < 1e-6f);
}

TEST_CASE("render extremes: more threads than cores give the bit-identical image") {
    const LoadedScene cornell = loadScene(test::cornellScene());
    const Camera camera(cornell.settings.pose, 24, 24);
    RenderSettings settings = withDepth(3, 9);
    settings.threads = 1;
    const AccumulationBuffer single = test::renderPasses(cornell.scene, camera, settings, 2);
    settings.threads = static_cast<int>(8 * std::max(1u, std::thread::hardware_concurrency()));
    const AccumulationBuffer many = test::renderPasses(cornell.scene, camera, settings, 2);
    for (size_t i = 0; i < single.pixelCount(); ++i) {
        CAPTURE(i);
        CHECK(many.mean(i) == single.mean(i));
        CHECK(many.passStandardError(i) == single.passStandardError(i));
    }
}
