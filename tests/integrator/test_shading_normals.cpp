// The path tracer on interpolated vertex normals (path_integrator.cpp, orientToward): a plane whose
// vertex normals tilt 60 degrees from its face normal, under a uniform sky of radiance 1. Seen from
// above the shading frame holds, and the plane receives the tilted-plane irradiance of notes
// section 5.3, pi (1 + cos 60) / 2, since no direction below the surface itself counts; it leaks
// nothing from below; seen at a grazing angle from the side its normals tilt away from, it falls
// back to the geometric normal and reads rho exactly instead of black; and the 24 strata are those
// of the shading frame. With the terminator offset (geometry/smooth_surface.h), a point light just
// below a dome-normalled facet's plane but above its shading horizon lights it as the shading
// normal says, and nowhere else does the offset change a bit.
#include <doctest/doctest.h>

#include <cmath>
#include <vector>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "integrator/path_integrator.h"
#include "scene/scene.h"
#include "render_support.h"
#include "test_support.h"

using namespace strata;

namespace {

constexpr float kAlbedo = 0.5f;
const glm::vec3 kTiltedNormal(std::sin(glm::radians(60.0f)), 0.0f, std::cos(glm::radians(60.0f)));

// The plane z = 0, facing +z, its four vertex normals tilted 60 degrees toward +x; lit by `sky`
// and, when `lightBelow`, by a bright quad under it facing up.
MeshData tiltedPlane(const Environment& sky, bool lightBelow = false) {
    MeshData mesh;
    Material plane;
    plane.diffuse = glm::vec3(kAlbedo);
    Material lamp;
    lamp.emission = glm::vec3(10.0f);
    mesh.materials = {plane, lamp};
    constexpr float s = 1000.0f;
    test::addQuad(mesh, {-s, -s, 0}, {s, -s, 0}, {s, s, 0}, {-s, s, 0}, 0);
    mesh.normals = {kTiltedNormal};
    mesh.triangleNormals = {{0, 0, 0}, {0, 0, 0}};
    if (lightBelow) {
        test::addQuad(mesh, {-5, -5, -1}, {5, -5, -1}, {5, 5, -1}, {-5, 5, -1}, 1);
        mesh.triangleNormals.resize(mesh.triangles.size(), kNoNormals);
    }
    mesh.environment = sky;
    return mesh;
}

Environment noSky() {
    Environment none;
    none.kind = Environment::Kind::None;
    return none;
}

const Ray kFromAbove{{0.0f, 0.0f, 1.0f}, {0.0f, 0.0f, -1.0f}};

}  // namespace

TEST_CASE("shading normals: a plane with tilted normals receives pi (1 + cos 60) / 2 from the sky, every sampler") {
    const Scene scene(tiltedPlane(test::uniformSky(1.0f)));
    const double exact = kAlbedo * (1.0 + 0.5) / 2.0;  // rho / pi * pi (1 + cos beta) / 2
    for (SamplerKind sampler : kSamplerKinds) {
        for (bool nee : {false, true}) {
            CAPTURE(samplerName(sampler));
            CAPTURE(nee);
            const PathIntegrator integrator(scene, {2, sampler, nee});
            const auto estimate = test::estimateMean(test::pixelEstimates(integrator, kFromAbove, 400, 2, 5));
            CHECK(estimate.standardError > 0.0);
            CHECK(std::abs(estimate.mean - exact) < 4.0 * estimate.standardError);
        }
    }
}

TEST_CASE("shading normals: nothing leaks through the surface from a light below it") {
    const Scene scene(tiltedPlane(noSky(), true));
    uint64_t rays = 0;
    for (SamplerKind sampler : {SamplerKind::Uniform, SamplerKind::Strata24, SamplerKind::Cosine,
                                SamplerKind::Strata24Bsdf, SamplerKind::Bsdf}) {
        for (bool nee : {false, true}) {
            const PathIntegrator integrator(scene, {3, sampler, nee});
            double total = 0.0;
            for (uint64_t pixel = 0; pixel < 200; ++pixel) {
                for (int step = 0; step < 24; ++step) {
                    total += integrator.radiance(kFromAbove, PathSamples(9, pixel, 0, step), rays).x;
                }
            }
            CAPTURE(samplerName(sampler));
            CAPTURE(nee);
            CHECK(total == 0.0);
        }
    }
    // The light is there: from below, the plane's underside is lit.
    const Ray fromBelow{{0.0f, 0.0f, -0.5f}, {0.0f, 0.0f, 1.0f}};
    const PathIntegrator integrator(scene, {1, SamplerKind::Cosine, true});
    double lit = 0.0;
    for (int step = 0; step < 24; ++step) lit += integrator.radiance(fromBelow, PathSamples(9, 0, 0, step), rays).x;
    CHECK(lit > 0.0);
}

TEST_CASE("shading normals: seen at a grazing angle against their tilt, the plane reads rho, not black") {
    const Scene scene(tiltedPlane(test::uniformSky(1.0f)));
    // 10 degrees above the plane, from -x: below the shading hemisphere, above the surface.
    const glm::vec3 toViewer = glm::normalize(glm::vec3(-std::cos(glm::radians(10.0f)), 0.0f,
                                                        std::sin(glm::radians(10.0f))));
    REQUIRE(glm::dot(toViewer, kTiltedNormal) < 0.0f);
    const Ray grazing{3.0f * toViewer, -toViewer};
    const PathIntegrator integrator(scene, {2, SamplerKind::Cosine, false});
    uint64_t rays = 0;
    for (int step = 0; step < 24; ++step) {
        // Cosine sampling about the geometric normal: every direction sees the sky, weight rho.
        CHECK(integrator.radiance(grazing, PathSamples(4, 0, 0, step), rays).x ==
              doctest::Approx(kAlbedo).epsilon(1e-6));
    }
}

TEST_CASE("shading normals: the 24 strata are built on the shading frame") {
    // A third of the shading hemisphere lies below the surface (the lune between two hemispheres
    // 60 degrees apart), so with the strata on the shading frame some strata's directions always
    // leave through the surface and read 0, the rest always reach the sky; on the geometric frame
    // none would.
    const Scene scene(tiltedPlane(test::uniformSky(1.0f)));
    const PathIntegrator integrator(scene, {1, SamplerKind::Strata24, false});
    std::vector<int> zeros(24, 0), paths(24, 0);
    uint64_t rays = 0;
    for (uint64_t pixel = 0; pixel < 300; ++pixel) {
        for (int step = 0; step < 24; ++step) {
            const PathSamples samples(2, pixel, 0, step);
            const int stratum = samples.stratum(0);
            ++paths[stratum];
            if (integrator.radiance(kFromAbove, samples, rays).x == 0.0f) ++zeros[stratum];
        }
    }
    int alwaysDark = 0, neverDark = 0, total = 0;
    for (int i = 0; i < 24; ++i) {
        alwaysDark += zeros[i] == paths[i];
        neverDark += zeros[i] == 0;
        total += zeros[i];
    }
    CHECK(alwaysDark >= 4);
    CHECK(neverDark >= 12);
    // Uniform directions: the lune's share of the hemisphere is 60/180.
    const double n = 300.0 * 24.0;
    CHECK(std::abs(total / n - 1.0 / 3.0) < 4.0 * std::sqrt((1.0 / 3.0) * (2.0 / 3.0) / n));
}

namespace {

// A lone triangle in z = 0 facing +z whose vertex normals lean out as a dome's would, lit by a
// point light far along +x and `height` above its plane; the hit under the camera is at
// (0.3, -0.2, 0), 0.3 from the edge the light lies beyond.
Scene domeFacet(float height, bool smooth) {
    MeshData mesh;
    Material facet;
    facet.diffuse = glm::vec3(kAlbedo);
    mesh.materials = {facet};
    mesh.positions = {{-1.0f, -1.0f, 0.0f}, {1.0f, -1.0f, 0.0f}, {0.0f, 1.0f, 0.0f}};
    mesh.triangles = {{0, 1, 2}};
    mesh.triangleMaterials = {0};
    if (smooth) {
        for (const glm::vec3& p : mesh.positions) mesh.normals.push_back(glm::normalize(glm::vec3(0.5f * p.x, 0.5f * p.y, 1.0f)));
        mesh.triangleNormals = {{0, 1, 2}};
    }
    mesh.pointLights = {PointLight{{50.0f, -0.2f, height}, glm::vec3(2500.0f)}};
    mesh.environment = noSky();
    return Scene(std::move(mesh));
}

const Ray kOntoFacet{{0.3f, -0.2f, 1.0f}, {0.0f, 0.0f, -1.0f}};

float directLight(const Scene& scene, float terminatorOffset) {
    PathIntegratorSettings settings{1, SamplerKind::Strata24Bsdf, true};
    settings.terminatorOffset = terminatorOffset;
    uint64_t rays = 0;
    return PathIntegrator(scene, settings).radiance(kOntoFacet, PathSamples(5, 0, 0, 0), rays).x;
}

}  // namespace

TEST_CASE("shading normals: with the terminator offset a light just below a smooth facet lights it by its shading normal") {
    const Scene scene = domeFacet(-0.5f, true);
    // The light is 0.57 degrees below the facet's plane: without the offset nothing reaches it.
    CHECK(directLight(scene, 0.0f) == 0.0f);
    // Lifted onto the dome, the shadow ray passes over the facet's edge before it could cross
    // its plane, and nothing else is there: rho / pi I cos_s / r^2, cos_s with the shading normal.
    const auto hit = scene.intersect(kOntoFacet);
    REQUIRE(hit);
    const SurfaceHit surface = scene.surface(*hit);
    const glm::vec3 toLight = glm::vec3(50.0f, -0.2f, -0.5f) - surface.point;
    const float cosine = glm::dot(surface.shadingNormal, glm::normalize(toLight));
    REQUIRE(cosine > 0.05f);
    const double exact = kAlbedo / M_PI * 2500.0 * cosine / glm::dot(toLight, toLight);
    for (float offset : {0.1f, 0.5f}) CHECK(directLight(scene, offset) == doctest::Approx(exact).epsilon(1e-4));
    // A flat facet has no curved surface to leave from: still nothing.
    CHECK(directLight(domeFacet(-0.5f, false), 0.1f) == 0.0f);
}

TEST_CASE("shading normals: the terminator offset changes no bit where the light stands above its cutoff") {
    // 30 degrees above the facet's plane (cosine 0.5 with its normal) the shadow ray leaves the
    // facet with or without it; 0.2 degrees above, with a cutoff of 0.1, it leaves from the dome.
    const Scene high = domeFacet(50.0f * std::tan(glm::radians(30.0f)), true);
    CHECK(directLight(high, 0.1f) == directLight(high, 0.0f));
    CHECK(directLight(high, 0.1f) > 0.0f);
    const Scene grazing = domeFacet(0.2f, true);
    CHECK(directLight(grazing, 0.1f) > 0.0f);
    CHECK(directLight(grazing, 0.1f) == doctest::Approx(directLight(grazing, 0.0f)).epsilon(1e-3));
}
