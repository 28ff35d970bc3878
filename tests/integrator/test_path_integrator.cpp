#include <doctest/doctest.h>

#include <cmath>
#include <vector>
#include <glm/geometric.hpp>

#include "film/accumulation_buffer.h"
#include "scene/camera.h"
#include "integrator/path_integrator.h"
#include "integrator/progressive_renderer.h"
#include "lights/area_light.h"
#include "scene/scene.h"
#include "scene/scene_loader.h"
#include "test_support.h"

using namespace strata;

namespace {

// Furnace (notes 5.1): rho = 0.5, Le = 1, the exact truncated value at depth K.
double furnaceValue(int depth) { return (1.0 - std::pow(0.5, depth + 1)) / 0.5; }

// Lambert (notes 5.2): irradiance at the origin (normal +z) from the unit square [-1/2,1/2]^2 at
// height 1, emitting radiance 1 downwards: E/L = 0.752274688454; from the 2 x 2 square
// [-1,1]^2 at height 1 (2 pi / 3 sr): E/L = 1.740839502734.
constexpr double kLambertLargeSquareIrradiance = 1.740839502734;
constexpr float kReceiverAlbedo = 0.8f;

Scene lambertScene(float halfSide = 0.5f) {
    MeshData mesh;
    mesh.materials = {Material{"receiver", glm::vec3(kReceiverAlbedo), glm::vec3(0.0f)},
                      Material{"emitter", glm::vec3(0.0f), glm::vec3(1.0f)}};
    // Receiver: large, facing up. Emitter: counter-clockwise seen from below, so it faces down.
    test::addQuad(mesh, {-50, -50, 0}, {50, -50, 0}, {50, 50, 0}, {-50, 50, 0}, 0);
    const float h = halfSide;
    test::addQuad(mesh, {-h, -h, 1}, {-h, h, 1}, {h, h, 1}, {h, -h, 1}, 1);
    // The emitter is the only light (of radiance 1, the default sky would light the scene too).
    mesh.environment.kind = Environment::Kind::None;
    return Scene(std::move(mesh));
}

// Pass means (each the average of 24 paths) of the radiance leaving the receiver's origin
// upwards: i.i.d. across passes and pixel keys, so their spread gives an honest standard error
// for either sampler.
std::vector<double> lambertPassMeans(SamplerKind sampler, int passes, bool nee = false,
                                     float halfSide = 0.5f) {
    const Scene scene = lambertScene(halfSide);
    const PathIntegrator integrator(scene, {1, sampler, nee});
    const Ray ray{{0.0f, 0.0f, 0.5f}, {0.0f, 0.0f, -1.0f}};
    std::vector<double> means;
    uint64_t rays = 0;
    for (int pass = 0; pass < passes; ++pass) {
        double sum = 0.0;
        for (int step = 0; step < kPathsPerPass; ++step) {
            // A different "pixel" per pass: fresh, independent strata permutations.
            const PathSamples samples(7, static_cast<uint64_t>(pass), 0, step);
            sum += integrator.radiance(ray, samples, rays).x;
        }
        means.push_back(sum / kPathsPerPass);
    }
    return means;
}

std::vector<double> furnacePixelMeans(SamplerKind sampler, int depth, int passes) {
    const LoadedScene loaded = loadScene(test::sourceDir() / "assets/furnace/furnace.obj");
    const Camera camera(loaded.settings.pose, 16, 16);
    AccumulationBuffer buffer(camera.width(), camera.height());
    ProgressiveRenderer renderer(loaded.scene, camera, {{depth, sampler, false}, 99, 0});
    for (int pass = 0; pass < passes; ++pass) renderer.renderPass(buffer, pass);
    std::vector<double> means;
    for (size_t i = 0; i < buffer.pixelCount(); ++i) means.push_back(buffer.mean(i).x);
    return means;
}

}  // namespace

TEST_CASE("integrator: the furnace gives Le (1 - rho^(K+1)) / (1 - rho) for K = 0..5") {
    for (SamplerKind sampler : {SamplerKind::Uniform, SamplerKind::Strata24}) {
        for (int depth = 0; depth <= 5; ++depth) {
            const auto estimate = test::estimateMean(furnacePixelMeans(sampler, depth, 4));
            INFO(samplerName(sampler) << " K=" << depth << " mean " << estimate.mean << " +- "
                                      << estimate.standardError);
            if (depth == 0) {
                CHECK(estimate.mean == 1.0);  // only emission: no randomness at all
                continue;
            }
            CHECK(std::abs(estimate.mean - furnaceValue(depth)) < 4.0 * estimate.standardError);
            CHECK(estimate.standardError < 0.01);  // the test has power
        }
    }
}

TEST_CASE("integrator: Lambert's polygon irradiance for both samplers, strata24 with less variance") {
    const double exact = kReceiverAlbedo * test::kLambertSquareIrradiance / M_PI;
    constexpr int kPasses = 20000;
    const auto uniform = test::estimateMean(lambertPassMeans(SamplerKind::Uniform, kPasses));
    const auto strata = test::estimateMean(lambertPassMeans(SamplerKind::Strata24, kPasses));
    INFO("exact " << exact << ", uniform " << uniform.mean << " +- " << uniform.standardError
                  << ", strata24 " << strata.mean << " +- " << strata.standardError);
    CHECK(std::abs(uniform.mean - exact) < 4.0 * uniform.standardError);
    CHECK(std::abs(strata.mean - exact) < 4.0 * strata.standardError);
    // Equal sample counts (24 paths per pass each): the ratio of variances of the pass means.
    const double ratio = (strata.standardError * strata.standardError) /
                         (uniform.standardError * uniform.standardError);
    MESSAGE("Lambert square, 24 paths per estimate: Var(strata24)/Var(uniform) = " << ratio
            << " (the paper claims 1/24 = 0.0417)");
    // With 20000 passes each variance is known to about 1%: a ratio below 0.9 is significant.
    CHECK(ratio < 0.9);
}

TEST_CASE("integrator: a large close emitter sampled by solid angle gives Lambert's irradiance, with MIS") {
    // The 2 x 2 square at height 1: each of its triangles subtends pi / 3 sr from the origin, so
    // next-event estimation samples them by solid angle there (area_light.h). With NEE (light
    // samples and BSDF samples combined by MIS) and without it (BSDF samples alone), both equal
    // rho E / pi.
    const Scene scene = lambertScene(1.0f);
    for (uint32_t i = 0; i < scene.lights().size(); ++i) {
        const auto* light = dynamic_cast<const AreaLight*>(&scene.lights().light(i));
        REQUIRE(light);
        CHECK(light->sphericalSolidAngle({0, 0, 0}) == doctest::Approx(M_PI / 3).epsilon(1e-6));
    }
    const double exact = kReceiverAlbedo * kLambertLargeSquareIrradiance / M_PI;
    constexpr int kPasses = 4000;
    for (SamplerKind sampler : {SamplerKind::Bsdf, SamplerKind::Strata24}) {
        const auto withNee = test::estimateMean(lambertPassMeans(sampler, kPasses, true, 1.0f));
        const auto withoutNee = test::estimateMean(lambertPassMeans(sampler, kPasses, false, 1.0f));
        INFO(samplerName(sampler) << ": exact " << exact << ", NEE " << withNee.mean << " +- "
                                  << withNee.standardError << ", no NEE " << withoutNee.mean << " +- "
                                  << withoutNee.standardError);
        CHECK(std::abs(withNee.mean - exact) < 4.0 * withNee.standardError);
        CHECK(std::abs(withoutNee.mean - exact) < 4.0 * withoutNee.standardError);
        CHECK(withNee.standardError < 2e-3 * exact);  // the test has power
    }
}

TEST_CASE("integrator: depth caps the bounces, and emission is one-sided") {
    const Scene scene = lambertScene();
    uint64_t rays = 0;
    const PathSamples samples(1, 0, 0, 0);
    // Looking up at the emitter's front (it faces down): radiance 1 at any depth.
    const Ray up{{0.0f, 0.0f, 0.5f}, {0.0f, 0.0f, 1.0f}};
    CHECK(PathIntegrator(scene, {0, SamplerKind::Uniform, false}).radiance(up, samples, rays).x == 1.0f);
    // Looking down at its back: nothing, it emits only forwards and its albedo is 0.
    const Ray down{{0.0f, 0.0f, 2.0f}, {0.0f, 0.0f, -1.0f}};
    CHECK(PathIntegrator(scene, {3, SamplerKind::Uniform, false}).radiance(down, samples, rays).x == 0.0f);
    // The receiver at depth 0 shows no reflected light.
    const Ray receiver{{0.0f, 0.0f, 0.5f}, {0.0f, 0.0f, -1.0f}};
    CHECK(PathIntegrator(scene, {0, SamplerKind::Strata24, false}).radiance(receiver, samples, rays).x == 0.0f);
    // A ray into the void.
    const Ray away{{0.0f, 0.0f, 2.0f}, {0.0f, 0.0f, 1.0f}};
    CHECK(PathIntegrator(scene, {5, SamplerKind::Strata24, false}).radiance(away, samples, rays).x == 0.0f);
}

TEST_CASE("integrator: a point light through next-event estimation gives rho/pi I cos / r^2, and no ray after it") {
    MeshData mesh;
    mesh.materials = {Material{"receiver", glm::vec3(0.6f), glm::vec3(0.0f)}};
    test::addQuad(mesh, {-50, -50, 0}, {50, -50, 0}, {50, 50, 0}, {-50, 50, 0}, 0);
    mesh.pointLights = {PointLight{{3.0f, 0.0f, 4.0f}, glm::vec3(10.0f)}};
    const Scene scene(std::move(mesh));
    const Ray ray{{0.0f, 0.0f, 1.0f}, {0.0f, 0.0f, -1.0f}};
    uint64_t rays = 0;
    // The plane sees nothing else, so the estimate is exact for every sample.
    const double exact = 0.6 / M_PI * 10.0 * (4.0 / 5.0) / 25.0;
    for (int step = 0; step < 24; ++step) {
        const PathSamples samples(3, 0, 0, step);
        const float value = PathIntegrator(scene, {1, SamplerKind::Strata24, true}).radiance(ray, samples, rays).x;
        CHECK(value == doctest::Approx(exact).epsilon(1e-5));
    }
    // A ray finds no point light, so after its last light sample a path traces nothing more: the
    // camera ray and one shadow ray each.
    CHECK(rays == 2 * 24);
    // Without --nee, a point light is dark; at depth 0 it is not reached either.
    const PathSamples samples(3, 0, 0, 0);
    CHECK(PathIntegrator(scene, {1, SamplerKind::Strata24, false}).radiance(ray, samples, rays).x == 0.0f);
    CHECK(PathIntegrator(scene, {0, SamplerKind::Strata24, true}).radiance(ray, samples, rays).x == 0.0f);
}

TEST_CASE("integrator: an unlit surface shows its colour to every ray and lights as an emitter, found by rays alone") {
    MeshData mesh = test::lambertSquareMesh(Material{"receiver", glm::vec3(kReceiverAlbedo), glm::vec3(0.0f)});
    Material unlit;
    unlit.name = "unlit";
    unlit.unlit = true;
    unlit.diffuse = glm::vec3(0.25f, 0.5f, 0.75f);
    mesh.materials[1] = unlit;
    const Scene scene(std::move(mesh));
    uint64_t rays = 0;
    // Seen directly it is its colour, at any depth, from either side, with or without light samples.
    for (int depth : {0, 3}) {
        for (bool nee : {false, true}) {
            const PathIntegrator integrator(scene, {depth, SamplerKind::Strata24, nee});
            const PathSamples samples(3, 0, 0, 5);
            CHECK(integrator.radiance(Ray{{0.1f, 0.1f, 0.5f}, {0.0f, 0.0f, 1.0f}}, samples, rays) == unlit.diffuse);
            CHECK(integrator.radiance(Ray{{0.1f, 0.1f, 2.0f}, {0.0f, 0.0f, -1.0f}}, samples, rays) == unlit.diffuse);
        }
    }
    CHECK_FALSE(whyBlack(scene, {1, SamplerKind::Strata24, true}));
    // The receiver's origin at depth 1: rho / pi times the square's colour times Lambert's
    // irradiance, with next-event estimation on (which cannot sample it) and off.
    const double exact = kReceiverAlbedo / M_PI * 0.25 * test::kLambertSquareIrradiance;
    for (bool nee : {false, true}) {
        const PathIntegrator integrator(scene, {1, SamplerKind::Strata24, nee});
        std::vector<double> means;
        for (int pass = 0; pass < 1600; ++pass) {
            double sum = 0.0;
            for (int step = 0; step < kPathsPerPass; ++step) {
                const PathSamples samples(7, static_cast<uint64_t>(pass), 0, step);
                sum += integrator.radiance(Ray{{0.0f, 0.0f, 0.5f}, {0.0f, 0.0f, -1.0f}}, samples, rays).x;
            }
            means.push_back(sum / kPathsPerPass);
        }
        const auto estimate = test::estimateMean(means);
        CAPTURE(nee);
        CHECK(std::abs(estimate.mean - exact) <= test::kSigmas * estimate.standardError);
        CHECK(estimate.standardError < 0.02 * exact);
    }
}

TEST_CASE("integrator: Russian roulette is unbiased on the furnace and ends paths early") {
    const LoadedScene loaded = loadScene(test::sourceDir() / "assets/furnace/furnace.obj");
    const Camera camera(loaded.settings.pose, 16, 16);
    for (SamplerKind sampler : {SamplerKind::Uniform, SamplerKind::Strata24}) {
        AccumulationBuffer plain(16, 16), roulette(16, 16);
        ProgressiveRenderer withoutRoulette(loaded.scene, camera, {{8, sampler, false}, 5, 0});
        PathIntegratorSettings settings{8, sampler, false};
        settings.rouletteDepth = 1;
        ProgressiveRenderer withRoulette(loaded.scene, camera, {settings, 5, 0});
        for (uint32_t pass = 0; pass < 6; ++pass) {
            withoutRoulette.renderPass(plain, pass);
            withRoulette.renderPass(roulette, pass);
        }
        std::vector<double> means;
        for (size_t i = 0; i < roulette.pixelCount(); ++i) means.push_back(roulette.mean(i).x);
        const auto estimate = test::estimateMean(means);
        INFO(samplerName(sampler) << ": " << estimate.mean << " +- " << estimate.standardError);
        CHECK(std::abs(estimate.mean - furnaceValue(8)) < 4.0 * estimate.standardError);
        // Survival by weight (about rho per bounce) ends most paths well before depth 8.
        CHECK(withRoulette.counters().rays < withoutRoulette.counters().rays / 2);
    }
}

TEST_CASE("path integrator: paths traced together give bit for bit what each gives alone") {
    // The glossy scene (layered GGX, an area lamp) with next-event estimation and roulette from
    // the first bounce: paths end at every bounce, some by leaving the scene, so the batch
    // thins unevenly. 150 paths: two full batches and a part.
    const LoadedScene loaded = loadScene(test::sourceDir() / "assets/glossy/glossy.obj");
    const Camera camera(loaded.settings.pose, 10, 5);
    for (const SamplerKind sampler : {SamplerKind::Strata24Bsdf, SamplerKind::Uniform}) {
        PathIntegratorSettings settings;
        settings.depth = 7;
        settings.sampler = sampler;
        settings.nextEventEstimation = true;
        settings.rouletteDepth = 1;
        const PathIntegrator integrator(loaded.scene, settings);
        std::vector<PathSamples> samples;
        std::vector<Ray> rays;
        for (int pixel = 0; pixel < 50; ++pixel) {
            for (int step = 0; step < 3; ++step) {
                samples.emplace_back(5, pixel, 2, step);
                rays.push_back(camera.generateRay(pixel % 10, pixel / 10, samples.back().pixelJitter()));
            }
        }
        std::vector<glm::vec3> together(rays.size());
        uint64_t raysTogether = 0;
        integrator.radiance(rays, samples, together, raysTogether);
        uint64_t raysAlone = 0;
        size_t lit = 0;
        for (size_t i = 0; i < rays.size(); ++i) {
            CAPTURE(i);
            const glm::vec3 alone = integrator.radiance(rays[i], samples[i], raysAlone);
            CHECK(together[i].x == alone.x);
            CHECK(together[i].y == alone.y);
            CHECK(together[i].z == alone.z);
            lit += alone.x > 0.0f;
        }
        CHECK(raysTogether == raysAlone);
        CHECK(lit > rays.size() / 2);
    }
}
