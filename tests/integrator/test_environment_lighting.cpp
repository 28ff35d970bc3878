// The path tracer under an environment (notes section 5.3): a convex diffuse object reads its
// albedo exactly under a uniform sky of radiance 1, and the sky reads 1; a tilted plane over a
// black ground receives pi (1 + cos beta) / 2; next-event estimation of a map with one small
// bright region gives the exact mean with less variance; the default white environment of a
// scene with no light, and Le_max with the environment in it.
#include <doctest/doctest.h>

#include <cmath>
#include <memory>
#include <vector>
#include <glm/geometric.hpp>

#include "film/accumulation_buffer.h"
#include "integrator/path_integrator.h"
#include "integrator/progressive_renderer.h"
#include "integrator/truncation.h"
#include "io/image_io.h"
#include "scene/camera.h"
#include "scene/scene.h"
#include "test_support.h"
#include "render_support.h"

using namespace strata;

namespace {

Material diffuse(const glm::vec3& albedo) {
    Material m;
    m.diffuse = albedo;
    return m;
}

// The cube [-1,1]^3 (the furnace's faces; reflection is two-sided, so seen from outside it is a
// convex diffuse object).
MeshData convexCube(const glm::vec3& albedo, const Environment& environment) {
    MeshData mesh = test::furnaceMesh(diffuse(albedo));
    mesh.environment = environment;
    return mesh;
}

// Rays from outside the cube onto the interiors of its faces, and rays that miss it.
Ray rayOntoCube(int k) {
    const glm::vec3 target(-0.7f + 0.13f * (k % 11), -0.6f + 0.11f * (k % 7), 0.0f);
    const glm::vec3 origin(0.4f * (k % 3) - 0.4f, 2.5f - 0.3f * (k % 5), 6.0f);
    return Ray{origin, glm::normalize(target - origin)};
}

}  // namespace

TEST_CASE("environment: a convex diffuse object under a sky of 1 reads rho, exactly when sampled by cosine") {
    const glm::vec3 rho(0.2f, 0.5f, 0.8f);
    for (const Environment& sky : {test::uniformSky(1.0f), Environment{}}) {  // explicit, and the default
        const Scene scene(convexCube(rho, sky));
        for (SamplerKind sampler : {SamplerKind::Cosine, SamplerKind::Bsdf}) {
            for (int depth : {1, 2, 6}) {
                CAPTURE(samplerName(sampler));
                CAPTURE(depth);
                const PathIntegrator integrator(scene, {depth, sampler, false});
                uint64_t rays = 0;
                float largestError = 0.0f;
                for (int k = 0; k < 40; ++k) {
                    for (int step = 0; step < 24; ++step) {
                        const glm::vec3 value =
                            integrator.radiance(rayOntoCube(k), PathSamples(3, k, 0, step), rays);
                        largestError = std::max(largestError, glm::length(value - rho));
                    }
                }
                // Zero variance: f cos / pdf = rho for every direction, and every direction sees
                // the sky.
                CHECK(largestError < 1e-6f);
                const Ray miss{{0.0f, 3.0f, 6.0f}, {0.0f, 0.0f, -1.0f}};
                CHECK(integrator.radiance(miss, PathSamples(3, 0, 0, 0), rays) == glm::vec3(1.0f));
            }
        }
    }
}

TEST_CASE("environment: a convex object under a sky of 1 reads rho within 4 standard errors for every sampler") {
    const Scene scene(convexCube(glm::vec3(0.6f), test::uniformSky(1.0f)));
    for (SamplerKind sampler : {SamplerKind::Uniform, SamplerKind::Strata24, SamplerKind::Strata24Qmc,
                                SamplerKind::Strata24Cosine, SamplerKind::Strata24CosineQmc,
                                SamplerKind::Strata24Bsdf, SamplerKind::Cosine}) {
        CAPTURE(samplerName(sampler));
        const PathIntegrator integrator(scene, {3, sampler, false});
        const std::vector<double> pixels = test::pixelEstimates(integrator, rayOntoCube(5), 64, 4, 11);
        const auto estimate = test::estimateMean(pixels);
        CHECK(std::abs(estimate.mean - 0.6) < 4.0 * estimate.standardError + 1e-6);
        // The cosine sampler is exact per path, and strata24-cosine(-qmc) per pass: its strata's
        // weights 24 PSA_i rho / pi average to rho over the 24; so is strata24-bsdf on this
        // Lambertian cube, whose warped strata weigh exactly rho.
        const bool exact = sampler == SamplerKind::Cosine || sampler == SamplerKind::Strata24Cosine ||
                           sampler == SamplerKind::Strata24CosineQmc || sampler == SamplerKind::Strata24Bsdf;
        CHECK((estimate.standardError == 0.0) == exact);
        // A uniform sky gives next-event estimation nothing to sample (uniform_environment_light.h):
        // with it on, every path is the same, bit for bit, and draws no shadow ray.
        const PathIntegrator withLightSamples(scene, {3, sampler, true});
        CHECK(test::pixelEstimates(withLightSamples, rayOntoCube(5), 64, 4, 11) == pixels);
        uint64_t rays[2] = {0, 0};
        for (int step = 0; step < 24; ++step) {
            integrator.radiance(rayOntoCube(3), PathSamples(7, 0, 0, step), rays[0]);
            withLightSamples.radiance(rayOntoCube(3), PathSamples(7, 0, 0, step), rays[1]);
        }
        CHECK(rays[1] == rays[0]);
    }
}

TEST_CASE("environment: a rendered convex object shows rho where it covers a pixel and 1 where the sky is") {
    const Scene scene(convexCube(glm::vec3(0.4f), test::uniformSky(1.0f)));
    const Camera camera(CameraPose{{0.5f, 1.0f, 6.0f}, {0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, 40.0f}, 24, 24);
    const AccumulationBuffer buffer =
        test::renderPasses(scene, camera, {{2, SamplerKind::Cosine, false}, 5, 1}, 2);
    int object = 0, sky = 0;
    for (size_t i = 0; i < buffer.pixelCount(); ++i) {
        const double value = buffer.mean(i).y;
        if (std::abs(value - 0.4) < 1e-6) {
            ++object;
        } else if (value == 1.0) {
            ++sky;
        } else {
            // A pixel on the silhouette mixes the two.
            CHECK(value > 0.4);
            CHECK(value < 1.0);
        }
    }
    CHECK(object > 100);
    CHECK(sky > 100);
}

TEST_CASE("environment: a plane tilted by beta over a black ground receives pi (1 + cos beta) / 2 (notes 5.3)") {
    const struct {
        double degrees;
        double irradiance;  // E / L_sky, the notes' table
    } rows[] = {{0, 3.1415927}, {30, 2.9311459}, {60, 2.3561945}, {90, 1.5707963}, {120, 0.7853982}};
    constexpr float kAlbedo = 0.7f;
    for (const auto& row : rows) {
        const float beta = static_cast<float>(row.degrees * M_PI / 180.0);
        // The receiver: a unit square about (0, 1, 0) whose normal is +y tilted toward +x by beta.
        const glm::vec3 normal(std::sin(beta), std::cos(beta), 0.0f);
        const glm::vec3 along(std::cos(beta), -std::sin(beta), 0.0f);
        const glm::vec3 side(0.0f, 0.0f, 1.0f);
        const glm::vec3 centre(0.0f, 1.0f, 0.0f);
        MeshData mesh;
        mesh.materials = {diffuse(glm::vec3(kAlbedo)), diffuse(glm::vec3(0.0f))};
        test::addQuad(mesh, centre - 0.5f * along - 0.5f * side, centre - 0.5f * along + 0.5f * side,
                      centre + 0.5f * along + 0.5f * side, centre + 0.5f * along - 0.5f * side, 0);
        // The ground: black, wide enough that it hides all but 1e-5 rad below the horizon.
        const float g = 1e5f;
        test::addQuad(mesh, {-g, 0, -g}, {-g, 0, g}, {g, 0, g}, {g, 0, -g}, 1);
        mesh.environment = test::uniformSky(1.0f);
        const Scene scene(std::move(mesh));
        const Ray ray{centre + 0.5f * normal, -normal};
        for (SamplerKind sampler : {SamplerKind::Cosine, SamplerKind::Strata24}) {
            for (bool nee : {false, true}) {
                CAPTURE(row.degrees);
                CAPTURE(samplerName(sampler));
                CAPTURE(nee);
                const PathIntegrator integrator(scene, {2, sampler, nee});
                const auto estimate = test::estimateMean(test::pixelEstimates(integrator, ray, 64, 8, 5));
                const double expected = kAlbedo * row.irradiance / M_PI;
                CHECK(std::abs(estimate.mean - expected) < 4.0 * estimate.standardError + 1e-6);
            }
        }
    }
}

TEST_CASE("environment: a map with one small bright region, with and without next-event estimation") {
    // A 32 x 16 map of radiance 0.05 with a 2 x 2 patch of 2000 at about 40 degrees from the
    // zenith, over a diffuse plane y = 0 facing up.
    constexpr int kWidth = 32, kHeight = 16;
    Image map{kWidth, kHeight, std::vector<glm::vec3>(kWidth * kHeight, glm::vec3(0.05f))};
    for (int y : {3, 4}) {
        for (int x : {20, 21}) map.pixels[y * kWidth + x] = glm::vec3(2000.0f);
    }
    // Exact radiance leaving the plane: rho / pi times the irradiance, the texels of the upper
    // hemisphere each giving L (2 pi / W) (sin^2 theta_1 - sin^2 theta_0) / 2.
    constexpr double kAlbedo = 0.5;
    double irradiance = 0.0;
    for (int y = 0; y < kHeight / 2; ++y) {
        const double s0 = std::sin(M_PI * y / kHeight), s1 = std::sin(M_PI * (y + 1) / kHeight);
        for (int x = 0; x < kWidth; ++x) {
            irradiance += map.pixels[y * kWidth + x].x * (2.0 * M_PI / kWidth) * (s1 * s1 - s0 * s0) / 2.0;
        }
    }
    const double expected = kAlbedo / M_PI * irradiance;

    const auto dir = test::scratchDir("environment-bright");
    writeImage(dir / "bright.exr", map);
    MeshData mesh;
    mesh.materials = {diffuse(glm::vec3(kAlbedo))};
    test::addQuad(mesh, {-1, 0, -1}, {-1, 0, 1}, {1, 0, 1}, {1, 0, -1}, 0);
    mesh.environment.kind = Environment::Kind::Map;
    mesh.environment.map = readEnvironmentMap(dir / "bright.exr").map;
    mesh.environment.rotationDegrees = 70.0f;  // the irradiance of a horizontal plane ignores it
    const Scene scene(std::move(mesh));
    const Ray ray{{0.2f, 1.0f, 0.1f}, glm::normalize(glm::vec3(-0.2f, -1.0f, -0.1f))};
    double variance[2] = {0.0, 0.0};
    test::MeanEstimate estimates[2]{};
    for (int nee = 0; nee < 2; ++nee) {
        CAPTURE(nee);
        const PathIntegrator integrator(scene, {1, SamplerKind::Cosine, nee == 1});
        const std::vector<double> pixels = test::pixelEstimates(integrator, ray, 128, 8, 21);
        estimates[nee] = test::estimateMean(pixels);
        variance[nee] = estimates[nee].standardError * estimates[nee].standardError;
        CHECK(std::abs(estimates[nee].mean - expected) < 4.0 * estimates[nee].standardError);
    }
    const double z = (estimates[1].mean - estimates[0].mean) / std::sqrt(variance[0] + variance[1]);
    CHECK(std::abs(z) < 4.0);
    MESSAGE("bright environment patch: variance without / with next-event estimation = "
            << variance[0] / variance[1]);
    CHECK(variance[1] < variance[0]);
    // Le_max for the truncation bound is the map's brightest texel.
    CHECK(maxEmittedRadiance(scene) == doctest::Approx(2000.0));
}

TEST_CASE("environment: a scene with no light is lit white by default, and --env none keeps it black") {
    MeshData mesh;
    mesh.materials = {diffuse(glm::vec3(0.5f))};
    test::addQuad(mesh, {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, 0);
    Scene scene(mesh);
    CHECK(scene.lights().litByDefault());
    CHECK_FALSE(whyBlack(scene, {3, SamplerKind::Strata24, true}).has_value());
    CHECK(maxEmittedRadiance(scene) == 1.0);
    Environment none;
    none.kind = Environment::Kind::None;
    scene.setEnvironment(none);
    CHECK_FALSE(scene.lights().litByDefault());
    CHECK(whyBlack(scene, {3, SamplerKind::Strata24, true}).has_value());
    // A scene with a light of its own keeps a black outside.
    mesh.pointLights = {PointLight{{0.5f, 0.5f, 1.0f}, glm::vec3(1.0f)}};
    const Scene pointLit(mesh);
    CHECK_FALSE(pointLit.lights().litByDefault());
    CHECK(pointLit.lights().lightsAtInfinity().empty());
}

TEST_CASE("environment: relit from a sky of 1 to a sky of 2, a scene renders exactly twice as bright, same BVH") {
    // The environment is the only light: doubling its radiance doubles every path's contribution
    // exactly (a power of two), with the same samples, light choices and rays, seed for seed.
    MeshData mesh = convexCube(glm::vec3(0.6f), test::uniformSky(1.0f));
    mesh.materials.push_back(diffuse(glm::vec3(0.3f)));
    test::addQuad(mesh, {-3, -1, -3}, {3, -1, -3}, {3, -1, 3}, {-3, -1, 3}, 1);  // a floor for shadows
    Scene scene(std::move(mesh));
    const Camera camera(CameraPose{{0.5f, 2.0f, 6.0f}, {0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, 50.0f}, 16, 12);
    for (bool nee : {false, true}) {
        CAPTURE(nee);
        const RenderSettings settings{{3, SamplerKind::Strata24, nee}, 7, 1};
        scene.setEnvironment(test::uniformSky(1.0f));
        const AccumulationBuffer once = test::renderPasses(scene, camera, settings, 2);
        const RTCScene bvh = scene.embreeScene();
        const size_t triangles = scene.summary().triangles;
        scene.setEnvironment(test::uniformSky(2.0f));
        CHECK(scene.embreeScene() == bvh);
        CHECK(scene.summary().triangles == triangles);
        CHECK(maxEmittedRadiance(scene) == 2.0);
        const AccumulationBuffer twice = test::renderPasses(scene, camera, settings, 2);
        size_t differing = 0, lit = 0;
        for (size_t i = 0; i < once.pixelCount(); ++i) {
            differing += twice.mean(i) != 2.0 * once.mean(i);
            lit += once.mean(i).y > 0.0;
        }
        CHECK(differing == 0);
        CHECK(lit == once.pixelCount());
    }
}

TEST_CASE("environment: a relit scene goes back to its own environment with Default") {
    Scene scene(convexCube(glm::vec3(0.5f), Environment{}));
    REQUIRE(scene.lights().litByDefault());
    scene.setEnvironment(test::uniformSky(4.0f));
    CHECK_FALSE(scene.lights().litByDefault());
    CHECK(maxEmittedRadiance(scene) == 4.0);
    scene.setEnvironment(Environment{});
    CHECK(scene.lights().litByDefault());
    CHECK(maxEmittedRadiance(scene) == 1.0);
    CHECK(scene.mesh().environment.kind == Environment::Kind::Default);  // what it was given stays
}
