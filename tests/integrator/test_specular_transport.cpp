// Paths through mirrors and dielectrics (path_integrator.h with the models of materials/), on
// cases with exact answers: a lossless dielectric under a uniform sky sends back exactly the sky,
// a mirror of reflectance F shows F times it, a glass slab passes (1 - R)^2 / (1 - R^2) of the
// light behind it at normal incidence, and a furnace keeps its exact radiance with glass inside,
// for every sampler with and without next-event estimation.
#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <glm/geometric.hpp>

#include "integrator/path_integrator.h"
#include "render_support.h"
#include "scene/camera.h"
#include "scene/scene.h"
#include "test_support.h"

using namespace strata;

namespace {

Material glass(float roughness = 0.0f) {
    Material m;
    m.name = "glass";
    m.transmission = 1.0f;
    m.ior = 1.5f;
    m.roughness = roughness;
    return m;
}

// The programs' defaults: next-event estimation and Russian roulette on.
RenderSettings defaults(int depth, SamplerKind sampler = SamplerKind::Strata24Bsdf) {
    return {{depth, sampler, true, kRouletteDepthDefault}, 3, 1};
}

// A sphere of `material` (radius 1, vertex normals) alone under a uniform sky of 1, rendered
// 24 x 24 from 4 away, and the pixels its silhouette covers.
struct SphereRender {
    AccumulationBuffer buffer;
    int covered;
};
SphereRender renderSphere(const Material& material, const RenderSettings& settings, uint32_t passes) {
    MeshData mesh;
    mesh.materials.push_back(material);
    test::addSphere(mesh, glm::vec3(0.0f), 1.0f, 48, 0);
    mesh.environment = test::uniformSky(1.0f);
    const Scene scene(std::move(mesh));
    const Camera camera(CameraPose{{0.3f, 0.5f, 4.0f}, {0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, 36.0f}, 24, 24);
    int covered = 0;
    for (int y = 0; y < camera.height(); ++y) {
        for (int x = 0; x < camera.width(); ++x) {
            if (scene.intersect(camera.generateRay(x, y, glm::vec2(0.5f)))) ++covered;
        }
    }
    return {test::renderPasses(scene, camera, settings, passes), covered};
}

}  // namespace

TEST_CASE("specular transport: a lossless glass sphere under a uniform sky is invisible") {
    // Every path that enters a lossless dielectric leaves it again (radiance scaled by 1/eta^2 in
    // and eta^2 out), so under a sky of 1 every pixel reads 1.
    const SphereRender r = renderSphere(glass(), defaults(64), 12);
    CHECK(r.covered > 150);
    int noisy = 0;
    for (size_t i = 0; i < r.buffer.pixelCount(); ++i) {
        const double value = r.buffer.mean(i).y;
        const double error = r.buffer.passStandardError(i);
        if (error > 0.0) ++noisy;
        INFO("pixel " << i << ": " << value << " +- " << error);
        CHECK(std::abs(value - 1.0) <= 4.0 * error + 1e-5);
    }
    // Roulette inside the glass makes the estimate noisy, so the test is not of exact paths alone.
    CHECK(noisy > 50);
}

TEST_CASE("specular transport: a rough glass sphere under a uniform sky is never brighter than the sky") {
    // The microfacet model scatters once per interface and loses what would scatter again between
    // microfacets (per interaction, from outside at normal incidence 0.1% at Pr 0.3 and 3% at
    // Pr 0.7; from inside 1% and 24%, more toward grazing). The rest comes back, so no pixel is
    // brighter than the sky, and at Pr 0.3 none is far below it.
    for (float roughness : {0.3f, 0.7f}) {
        const SphereRender r = renderSphere(glass(roughness), defaults(64), 6);
        double darkest = 1.0;
        for (size_t i = 0; i < r.buffer.pixelCount(); ++i) {
            const double value = r.buffer.mean(i).y;
            INFO("roughness " << roughness << ", pixel " << i << ": " << value);
            CHECK(value <= 1.0 + 4.0 * r.buffer.passStandardError(i) + 1e-5);
            darkest = std::min(darkest, value);
        }
        INFO("roughness " << roughness << ": darkest pixel " << darkest);
        CHECK(darkest > (roughness < 0.5f ? 0.7 : 0.3));
    }
}

TEST_CASE("specular transport: a mirror under a uniform sky reads its Fresnel reflectance") {
    // A mirror of Ks 1 reflects all of the sky at every angle; one of F0 = 0.5 seen head-on reads
    // 0.5 (Schlick's F at normal incidence). The other side of the mirror is black.
    for (float f0 : {1.0f, 0.5f}) {
        Material mirror;
        mirror.name = "mirror";
        mirror.specular = glm::vec3(f0);
        mirror.roughness = 0.0f;
        MeshData mesh;
        mesh.materials.push_back(mirror);
        test::addQuad(mesh, {-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, 0);
        mesh.environment = test::uniformSky(1.0f);
        const Scene scene(std::move(mesh));
        for (SamplerKind sampler : kSamplerKinds) {
            for (bool nee : {false, true}) {
                const PathIntegrator integrator(scene, {4, sampler, nee, kRouletteDepthDefault});
                uint64_t rays = 0;
                const Ray headOn{{0.1f, 0.2f, 3.0f}, {0.0f, 0.0f, -1.0f}};
                const Ray oblique{{0.1f, -2.0f, 2.0f}, glm::normalize(glm::vec3(0.0f, 1.0f, -1.0f))};
                const float h = integrator.radiance(headOn, PathSamples(1, 0, 0, 3), rays).y;
                const float o = integrator.radiance(oblique, PathSamples(1, 0, 0, 5), rays).y;
                INFO("F0 " << f0 << ", " << samplerName(sampler) << std::string(nee ? " --nee" : ""));
                CHECK(h == doctest::Approx(f0).epsilon(1e-6));
                if (f0 == 1.0f) CHECK(o == doctest::Approx(1.0).epsilon(1e-6));
            }
        }
    }
}

TEST_CASE("specular transport: a glass slab passes (1 - R)^2 / (1 - R^2) of the light behind it, times Tf") {
    // A slab of index n seen at normal incidence in front of an emitter of radiance 1: each face
    // reflects R = ((n - 1) / (n + 1))^2, and every internal bounce summed passes
    // (1 - R)^2 / (1 - R^2). The filter Tf colours what passes through the slab once.
    const glm::vec3 filter(0.9f, 0.5f, 0.25f);
    Material slab = glass();
    slab.transmissionFilter = filter;
    Material emitter;
    emitter.name = "emitter";
    emitter.emission = glm::vec3(1.0f);
    MeshData mesh;
    mesh.materials = {slab, emitter};
    // The slab: the box [-2, 2] x [-2, 2] x [-0.5, 0], faces counter-clockwise from outside.
    const float a = 2.0f, z0 = -0.5f, z1 = 0.0f;
    test::addQuad(mesh, {-a, -a, z1}, {a, -a, z1}, {a, a, z1}, {-a, a, z1}, 0);  // top, faces +z
    test::addQuad(mesh, {-a, -a, z0}, {-a, a, z0}, {a, a, z0}, {a, -a, z0}, 0);  // bottom, faces -z
    test::addQuad(mesh, {-a, -a, z0}, {a, -a, z0}, {a, -a, z1}, {-a, -a, z1}, 0);  // faces -y
    test::addQuad(mesh, {-a, a, z0}, {-a, a, z1}, {a, a, z1}, {a, a, z0}, 0);      // faces +y
    test::addQuad(mesh, {-a, -a, z0}, {-a, -a, z1}, {-a, a, z1}, {-a, a, z0}, 0);  // faces -x
    test::addQuad(mesh, {a, -a, z0}, {a, a, z0}, {a, a, z1}, {a, -a, z1}, 0);      // faces +x
    // The emitter below, facing up toward the slab.
    test::addQuad(mesh, {-9, -9, -2}, {9, -9, -2}, {9, 9, -2}, {-9, 9, -2}, 1);
    mesh.environment.kind = Environment::Kind::None;
    const Scene scene(std::move(mesh));
    const double r = std::pow((1.5 - 1.0) / (1.5 + 1.0), 2.0);
    const double exact = (1.0 - r) * (1.0 - r) / (1.0 - r * r);
    const Ray ray{{0.3f, 0.2f, 2.0f}, {0.0f, 0.0f, -1.0f}};
    for (bool nee : {false, true}) {
        const PathIntegrator integrator(scene, {32, SamplerKind::Strata24Bsdf, nee, kRouletteDepthDefault});
        for (int channel = 0; channel < 3; ++channel) {
            std::vector<double> values;
            uint64_t rays = 0;
            for (uint32_t pass = 0; pass < 400; ++pass) {
                for (int step = 0; step < 24; ++step) {
                    values.push_back(integrator.radiance(ray, PathSamples(5, 1, pass, step), rays)[channel]);
                }
            }
            const test::MeanEstimate e = test::estimateMean(values);
            const double expected = exact * filter[channel];
            INFO(std::string(nee ? "--nee" : "--no-nee") << ", channel " << channel << ": " << e.mean << " +- "
                                              << e.standardError << ", exact " << expected);
            CHECK(std::abs(e.mean - expected) <= 4.0 * e.standardError + 1e-6);
        }
    }
}

TEST_CASE("specular transport: a furnace with smooth glass inside keeps its exact radiance, every sampler and NEE") {
    // The furnace of albedo 1/2 and emission 1 (notes section 5.1) at a depth where the series'
    // remainder is far below the noise: its radiance Le / (1 - rho) = 2 everywhere, which a
    // lossless glass sphere inside it leaves unchanged.
    Material walls;
    walls.name = "walls";
    walls.diffuse = glm::vec3(0.5f);
    walls.emission = glm::vec3(1.0f);
    MeshData mesh = test::furnaceMesh(walls);
    mesh.materials.push_back(glass());
    test::addSphere(mesh, glm::vec3(0.2f, 0.1f, 0.3f), 0.5f, 24, 1);
    const Scene scene(std::move(mesh));
    // Rays from inside the furnace toward the sphere.
    const Ray ray{{-0.6f, -0.5f, -0.7f}, glm::normalize(glm::vec3(0.8f, 0.6f, 1.0f))};
    for (SamplerKind sampler : kSamplerKinds) {
        for (bool nee : {false, true}) {
            const PathIntegrator integrator(scene, {48, sampler, nee, kRouletteDepthDefault});
            const test::MeanEstimate e = test::estimateMean(test::pixelEstimates(integrator, ray, 150, 2, 7));
            INFO(samplerName(sampler) << std::string(nee ? " --nee" : "") << ": " << e.mean << " +- " << e.standardError);
            CHECK(std::abs(e.mean - 2.0) <= 4.5 * e.standardError + 2.0 * std::pow(0.5, 49));
        }
    }
}

TEST_CASE("specular transport: with rough glass, every sampler with and without NEE estimates the same radiance") {
    // Rough glass loses some energy (above), so the furnace's value is not exact here; but light
    // sampling through a transmitting lobe, its MIS weights and every sampler must agree with
    // plain BSDF sampling.
    Material walls;
    walls.name = "walls";
    walls.diffuse = glm::vec3(0.5f);
    walls.emission = glm::vec3(1.0f);
    MeshData mesh = test::furnaceMesh(walls);
    mesh.materials.push_back(glass(0.4f));
    test::addSphere(mesh, glm::vec3(0.2f, 0.1f, 0.3f), 0.5f, 24, 1);
    // A small bright lamp, which light sampling finds and paths through the glass rarely do.
    Material lamp;
    lamp.name = "lamp";
    lamp.emission = glm::vec3(40.0f);
    mesh.materials.push_back(lamp);
    test::addQuad(mesh, {-0.1f, 0.99f, -0.1f}, {0.1f, 0.99f, -0.1f}, {0.1f, 0.99f, 0.1f}, {-0.1f, 0.99f, 0.1f}, 2);
    const Scene scene(std::move(mesh));
    const Ray ray{{-0.6f, -0.5f, -0.7f}, glm::normalize(glm::vec3(0.8f, 0.6f, 1.0f))};
    const PathIntegrator reference(scene, {16, SamplerKind::Bsdf, false, kRouletteDepthDefault});
    const test::MeanEstimate ref = test::estimateMean(test::pixelEstimates(reference, ray, 400, 4, 21));
    for (SamplerKind sampler : kSamplerKinds) {
        for (bool nee : {false, true}) {
            const PathIntegrator integrator(scene, {16, sampler, nee, kRouletteDepthDefault});
            const test::MeanEstimate e = test::estimateMean(test::pixelEstimates(integrator, ray, 200, 2, 23));
            INFO(samplerName(sampler) << std::string(nee ? " --nee" : "") << ": " << e.mean << " +- " << e.standardError
                                      << ", reference " << ref.mean << " +- " << ref.standardError);
            CHECK(std::abs(e.mean - ref.mean) <= 4.5 * std::hypot(e.standardError, ref.standardError));
        }
    }
}
