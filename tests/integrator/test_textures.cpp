// Textures in the path tracer: a textured emitter lights as its texture says, by light samples and
// by bounces alike (unbiased, lights/area_light.h); cut-outs let camera, bounce and shadow rays
// through (scene/cutout_filter.h), blended layers in the share their opacity leaves, and a
// blended emitter lights by its opacity; a flat normal map changes nothing (materials/normal_map.h).
// Vertex colours multiply the albedo as a colour texture does.
// On Lambert's polygon case (test_support.h): receiver radiance rho E / pi at depth 1.
#include <doctest/doctest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "integrator/path_integrator.h"
#include "scene/scene.h"
#include "test_support.h"
#include "util/constants.h"
#include "util/luminance.h"

using namespace strata;

namespace {

constexpr float kRho = 0.5f;

Material receiver() {
    Material m;
    m.diffuse = glm::vec3(kRho);
    return m;
}

// The square's corners (4 to 7) mapped onto the unit UV square, u = x + 1/2, v = y + 1/2.
void mapSquareUvs(MeshData& mesh) {
    mesh.uvs = {{0, 0}, {0, 1}, {1, 1}, {1, 0}};
    mesh.triangleUvs = {kNoUvs, kNoUvs, {0, 1, 2}, {0, 2, 3}};
}

// A blocker at height `z` over [-1, 1]^2 between receiver and square (z = 1), facing down, of
// `coverage`: its UVs u = (x + 1) / 2, v = (y + 1) / 2. Blended, the coverage is an opacity.
void addBlocker(MeshData& mesh, std::shared_ptr<const Texture> coverage, bool blended = false, float z = 0.5f) {
    Material blocker;
    blocker.diffuse = glm::vec3(0.5f);
    blocker.textures.coverage = std::move(coverage);
    blocker.textures.blended = blended;
    mesh.materials.push_back(blocker);
    const auto material = static_cast<uint32_t>(mesh.materials.size() - 1);
    test::addQuad(mesh, {-1, -1, z}, {-1, 1, z}, {1, 1, z}, {1, -1, z}, material);
    const auto base = static_cast<uint32_t>(mesh.uvs.size());
    mesh.uvs.insert(mesh.uvs.end(), {{0, 0}, {0, 1}, {1, 1}, {1, 0}});
    mesh.triangleUvs.push_back({base, base + 1, base + 2});
    mesh.triangleUvs.push_back({base, base + 2, base + 3});
}

test::MeanEstimate receiverRadiance(const Scene& scene, bool nee) {
    PathIntegratorSettings settings;
    settings.depth = 1;
    settings.nextEventEstimation = nee;
    const PathIntegrator integrator(scene, settings);
    return test::estimateMean(test::pixelEstimates(integrator, test::rayToOrigin({0.3f, 0.2f, 0.4f}), 64, 40, 11));
}

void checkRadiance(const test::MeanEstimate& estimate, double expected) {
    INFO("estimate " << estimate.mean << " +- " << estimate.standardError << ", expected " << expected);
    CHECK(std::abs(estimate.mean - expected) < 5.0 * estimate.standardError + 1e-9);
}

}  // namespace

TEST_CASE("a textured emitter lights by its texture, with and without light sampling") {
    MeshData mesh = test::lambertSquareMesh(receiver());
    mapSquareUvs(mesh);
    // Two texels 0 and 1 across u: bilinear with repeat makes f(u) + f(1 - u) = 1, so by the
    // square's symmetry about x = 0 the irradiance is half the untextured one.
    mesh.materials[1].textures.emission = std::make_shared<Texture>(2, 1, 1, std::vector<float>{0.0f, 1.0f});
    const Scene scene(std::move(mesh));
    const double expected = kRho * 0.5 * test::kLambertSquareIrradiance / kPi;
    checkRadiance(receiverRadiance(scene, true), expected);
    checkRadiance(receiverRadiance(scene, false), expected);
}

TEST_CASE("cut-out geometry lets shadow and bounce rays through, opaque texels block them") {
    const double unblocked = kRho * test::kLambertSquareIrradiance / kPi;
    for (const bool nee : {true, false}) {
        MeshData open = test::lambertSquareMesh(receiver());
        mapSquareUvs(open);
        addBlocker(open, std::make_shared<Texture>(1, 1, 1, std::vector<float>{0.0f}));
        const Scene openScene(std::move(open));
        checkRadiance(receiverRadiance(openScene, nee), unblocked);

        MeshData closed = test::lambertSquareMesh(receiver());
        mapSquareUvs(closed);
        addBlocker(closed, std::make_shared<Texture>(1, 1, 1, std::vector<float>{1.0f}));
        const Scene closedScene(std::move(closed));
        CHECK(receiverRadiance(closedScene, nee).mean == 0.0);
    }
}

TEST_CASE("a camera ray through a cut-out texel sees what is behind it") {
    MeshData mesh = test::lambertSquareMesh(receiver());
    mapSquareUvs(mesh);
    // Coverage 0 on the blocker's left half (u < 1/2, x < 0), 1 on its right; nearest texel
    // centres are at x = -1/2 and +1/2, where bilinear filtering returns them exactly.
    addBlocker(mesh, std::make_shared<Texture>(2, 1, 1, std::vector<float>{0.0f, 1.0f}));
    const Scene scene(std::move(mesh));
    const Ray throughHole{{-0.5f, 0.0f, 0.8f}, {0.0f, 0.0f, -1.0f}};
    const auto hit = scene.intersect(throughHole);
    REQUIRE(hit);
    CHECK(scene.triangle(hit->triangle).material == 0);  // the receiver
    CHECK(hit->t == doctest::Approx(0.8));
    const Ray ontoBlocker{{0.5f, 0.0f, 0.8f}, {0.0f, 0.0f, -1.0f}};
    const auto blocked = scene.intersect(ontoBlocker);
    REQUIRE(blocked);
    CHECK(scene.triangle(blocked->triangle).material == 2);
    CHECK(blocked->t == doctest::Approx(0.3));
    // Shadow rays likewise.
    CHECK_FALSE(scene.occluded(Ray{{-0.5f, 0.0f, 0.1f}, {0.0f, 0.0f, 1.0f}}, 0.8f));
    CHECK(scene.occluded(Ray{{0.5f, 0.0f, 0.1f}, {0.0f, 0.0f, 1.0f}}, 0.8f));
}

TEST_CASE("a blended blocker lets 1 - opacity of the light through, to light samples and bounces alike") {
    // At depth 1 the receiver's radiance is what reaches it straight from the square: the share
    // of shadow rays and bounce rays that pass the blockers, 1 - opacity for each layer, the
    // layers independent.
    const double unblocked = kRho * test::kLambertSquareIrradiance / kPi;
    const auto opacity = [](float value) { return std::make_shared<Texture>(1, 1, 1, std::vector<float>{value}); };
    for (const bool nee : {true, false}) {
        MeshData one = test::lambertSquareMesh(receiver());
        mapSquareUvs(one);
        addBlocker(one, opacity(0.4f), true);
        const Scene oneLayer(std::move(one));
        checkRadiance(receiverRadiance(oneLayer, nee), 0.6 * unblocked);

        MeshData two = test::lambertSquareMesh(receiver());
        mapSquareUvs(two);
        // Both above the camera (rayToOrigin's from z = 0.4).
        addBlocker(two, opacity(0.5f), true, 0.5f);
        addBlocker(two, opacity(0.5f), true, 0.7f);
        const Scene twoLayers(std::move(two));
        checkRadiance(receiverRadiance(twoLayers, nee), 0.25 * unblocked);
    }
}

TEST_CASE("a blended emitter lights by its opacity, its light samples as the rays that meet it") {
    // Opacity 0.5 x the texels 0.2 and 1 across u: as in the textured emitter's case, by the
    // square's symmetry the mean opacity that the receiver sees is 0.5 x (0.2 + 1) / 2 = 0.3. A
    // bounce meets the square with that probability and sees Le; a light sample carries 0.3 Le.
    const double unblocked = kRho * test::kLambertSquareIrradiance / kPi;
    for (const bool nee : {true, false}) {
        MeshData mesh = test::lambertSquareMesh(receiver());
        mapSquareUvs(mesh);
        mesh.materials[1].textures.blendBy(0.5f, std::make_shared<Texture>(2, 1, 1, std::vector<float>{0.2f, 1.0f}));
        const Scene scene(std::move(mesh));
        checkRadiance(receiverRadiance(scene, nee), 0.3 * unblocked);
    }
}

TEST_CASE("a camera ray meets a blended layer with its opacity's probability, the same in a packet or alone") {
    MeshData mesh = test::lambertSquareMesh(receiver());
    mapSquareUvs(mesh);
    addBlocker(mesh, std::make_shared<Texture>(1, 1, 1, std::vector<float>{0.8f}), true);
    mesh.materials.back().textures.opacity = 0.5f;  // times the texel: 0.4
    const Scene scene(std::move(mesh));
    std::vector<Ray> rays;
    for (uint64_t i = 0; i < 4000; ++i) {
        const glm::vec2 p = test::hashedPoint(i);
        rays.push_back({{p.x - 0.5f, p.y - 0.5f, 0.8f}, {0.0f, 0.0f, -1.0f}});
    }
    std::vector<std::optional<RayHit>> hits(rays.size());
    scene.intersect(rays, hits, Scene::Coherence::Incoherent);
    std::vector<double> met;
    for (size_t i = 0; i < rays.size(); ++i) {
        REQUIRE(hits[i]);
        const auto alone = scene.intersect(rays[i]);
        REQUIRE(alone);
        CHECK(alone->triangle == hits[i]->triangle);
        met.push_back(scene.triangle(hits[i]->triangle).material == 2 ? 1.0 : 0.0);
    }
    const test::MeanEstimate share = test::estimateMean(met);
    INFO("share met " << share.mean << " +- " << share.standardError);
    CHECK(std::abs(share.mean - 0.4) < 5.0 * share.standardError);
}

TEST_CASE("a flat normal map (0.5, 0.5, 1) renders the same as none") {
    const auto render = [](bool mapped) {
        MeshData mesh = test::lambertSquareMesh(receiver());
        mesh.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
        mesh.triangleUvs = {{0, 1, 2}, {0, 2, 3}, kNoUvs, kNoUvs};
        if (mapped) {
            mesh.materials[0].textures.normal =
                std::make_shared<Texture>(1, 1, 3, std::vector<float>{0.5f, 0.5f, 1.0f});
        }
        const Scene scene(std::move(mesh));
        PathIntegratorSettings settings;
        settings.depth = 2;
        settings.nextEventEstimation = true;
        return test::pixelEstimates(PathIntegrator(scene, settings), test::rayToOrigin({0.3f, 0.2f, 0.4f}), 8, 4, 3);
    };
    CHECK(render(true) == render(false));
}

TEST_CASE("a tilted normal map tilts the shading normal toward +u") {
    MeshData mesh = test::lambertSquareMesh(receiver());
    mesh.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    mesh.triangleUvs = {{0, 1, 2}, {0, 2, 3}, kNoUvs, kNoUvs};
    // (x, y, z) = (0.6, 0, 0.8) encoded as * 0.5 + 0.5.
    mesh.materials[0].textures.normal = std::make_shared<Texture>(1, 1, 3, std::vector<float>{0.8f, 0.5f, 0.9f});
    const Scene scene(std::move(mesh));
    const auto hit = scene.intersect(Ray{{0.1f, 0.1f, 0.5f}, {0.0f, 0.0f, -1.0f}});
    REQUIRE(hit);
    const SurfaceHit surface = scene.surface(*hit);
    CHECK(surface.smooth);
    CHECK(surface.shadingNormal.x == doctest::Approx(0.6));
    CHECK(surface.shadingNormal.y == doctest::Approx(0.0));
    CHECK(surface.shadingNormal.z == doctest::Approx(0.8));
}

TEST_CASE("vertex colours multiply the receiver's albedo by their value interpolated where the ray lands") {
    // A linear colour field over the receiver, c(x, y) = (0.5 + x / 250, 0.5 + y / 250, 0.3), given
    // at its corners: interpolated across either triangle it is exact, (0.5, 0.5, 0.3) at the origin.
    MeshData mesh = test::lambertSquareMesh(receiver());
    for (size_t v = 0; v < 4; ++v) {
        const glm::vec3& p = mesh.positions[v];
        mesh.colours.emplace_back(0.5f + p.x / 250.0f, 0.5f + p.y / 250.0f, 0.3f);
    }
    mesh.triangleColours = {{0, 1, 2}, {0, 2, 3}, kNoColours, kNoColours};
    const Scene scene(std::move(mesh));
    const double expected = luminance(glm::dvec3(0.5, 0.5, 0.3)) * kRho * test::kLambertSquareIrradiance / kPi;
    checkRadiance(receiverRadiance(scene, true), expected);
    checkRadiance(receiverRadiance(scene, false), expected);
}
