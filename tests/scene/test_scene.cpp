// The traced scene's surface records (scene.h): the shading normal interpolated from the vertex
// normals, the geometric one otherwise, and triangles turned over to agree with their normals.
#include <doctest/doctest.h>

#include <memory>
#include <span>
#include <vector>
#include <glm/geometric.hpp>

#include "sampling/random.h"
#include "scene/scene.h"
#include "textures/texture.h"
#include "util/error.h"
#include "test_support.h"

using namespace strata;

namespace {
MeshData oneTriangle(bool counterClockwise) {
    MeshData mesh;
    Material lamp;
    lamp.emission = glm::vec3(1.0f);
    mesh.materials = {lamp};
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    mesh.triangles = {counterClockwise ? std::array<uint32_t, 3>{0, 1, 2} : std::array<uint32_t, 3>{0, 2, 1}};
    mesh.triangleMaterials = {0};
    return mesh;
}
}  // namespace

TEST_CASE("scene: the shading normal interpolates the vertex normals by the hit's barycentrics") {
    MeshData mesh = oneTriangle(true);
    mesh.normals = {glm::normalize(glm::vec3(-1, 0, 1)), glm::normalize(glm::vec3(1, 0, 1)), {0, 0, 1}};
    mesh.triangleNormals = {{0, 1, 2}};
    const Scene scene(std::move(mesh));
    const auto hit = scene.intersect(Ray{{0.25f, 0.25f, 1.0f}, {0.0f, 0.0f, -1.0f}});
    REQUIRE(hit);
    const SurfaceHit surface = scene.surface(*hit);
    CHECK(surface.normal.z == doctest::Approx(1.0f));
    const glm::vec3 expected = glm::normalize(0.5f * glm::normalize(glm::vec3(-1, 0, 1)) +
                                              0.25f * glm::normalize(glm::vec3(1, 0, 1)) +
                                              0.25f * glm::vec3(0, 0, 1));
    CHECK(glm::length(surface.shadingNormal - expected) < 1e-5f);
}

TEST_CASE("scene: a flat triangle's shading normal is its geometric normal") {
    const Scene scene(oneTriangle(true));
    const auto hit = scene.intersect(Ray{{0.25f, 0.25f, 1.0f}, {0.0f, 0.0f, -1.0f}});
    REQUIRE(hit);
    const SurfaceHit surface = scene.surface(*hit);
    CHECK(surface.shadingNormal == surface.normal);
}

TEST_CASE("scene: a triangle wound against its vertex normals is turned over, and emits on their side") {
    MeshData mesh = oneTriangle(false);  // clockwise seen from +z: its winding faces -z
    mesh.normals = {{0, 0, 1}};
    mesh.triangleNormals = {{0, 0, 0}};
    const Scene scene(std::move(mesh));
    CHECK(scene.triangle(0).normal.z == doctest::Approx(1.0f));
    const int32_t light = scene.triangle(0).light;
    REQUIRE(light >= 0);
    const LightHit fromAbove{scene.triangle(0).normal};
    CHECK(scene.lights().light(static_cast<uint32_t>(light)).emitted({0, 0, -1}, fromAbove).x == 1.0f);
    // Without normals the winding decides: the same triangle faces -z.
    CHECK(Scene(oneTriangle(false)).triangle(0).normal.z == doctest::Approx(-1.0f));
}

TEST_CASE("scene: normal indices out of range, or for some triangles only, are refused") {
    MeshData mesh = oneTriangle(true);
    mesh.normals = {{0, 0, 1}};
    mesh.triangleNormals = {{0, 0, 3}};
    CHECK_THROWS_AS(Scene(std::move(mesh)), Error);
    MeshData partial = oneTriangle(true);
    test::addQuad(partial, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}, 0);
    partial.normals = {{0, 0, 1}};
    partial.triangleNormals = {{0, 0, 0}};
    CHECK_THROWS_AS(Scene(std::move(partial)), Error);
}

namespace {
// The Lambert square over its receiver, with a half cut-out blocker between them: both Embree
// geometries (opaque and cut-out, whose filter rejects hits on clear texels), and rays that miss.
Scene twoGeometryScene() {
    Material receiver;
    receiver.diffuse = glm::vec3(0.5f);
    MeshData mesh = test::lambertSquareMesh(receiver);
    Material blocker;
    blocker.diffuse = glm::vec3(0.5f);
    blocker.textures.coverage = std::make_shared<Texture>(2, 1, 1, std::vector<float>{0.0f, 1.0f});
    mesh.materials.push_back(blocker);
    test::addQuad(mesh, {-1, -1, 0.5f}, {-1, 1, 0.5f}, {1, 1, 0.5f}, {1, -1, 0.5f},
                  static_cast<uint32_t>(mesh.materials.size() - 1));
    mesh.uvs = {{0, 0}, {0, 1}, {1, 1}, {1, 0}};
    mesh.triangleUvs.assign(mesh.triangles.size() - 2, kNoUvs);
    mesh.triangleUvs.push_back({0, 1, 2});
    mesh.triangleUvs.push_back({0, 2, 3});
    return Scene(std::move(mesh));
}

// Rays from points around the scene in random directions: most hit, some miss.
std::vector<Ray> randomRays(size_t count, uint64_t seed) {
    std::vector<Ray> rays;
    for (size_t i = 0; i < count; ++i) {
        const auto u = [&](uint64_t d) { return uniformFloat(mixBits(hashCombine(seed, 8 * i + d))); };
        const glm::vec3 origin(3.0f * u(0) - 1.5f, 3.0f * u(1) - 1.5f, 2.0f * u(2) - 0.5f);
        const glm::vec3 toward(2.0f * u(3) - 1.0f, 2.0f * u(4) - 1.0f, 1.5f * u(5) - 0.25f);
        rays.push_back({origin, glm::normalize(toward - origin)});
    }
    return rays;
}
}  // namespace

TEST_CASE("scene: rays traced together find bit for bit what each finds alone") {
    const Scene scene = twoGeometryScene();
    // Every count from a single ray to past two packets, so that packets run partly full.
    for (size_t count = 1; count <= 20; ++count) {
        const std::vector<Ray> rays = randomRays(count, count);
        std::vector<std::optional<RayHit>> hits(count);
        for (const auto coherence : {Scene::Coherence::Coherent, Scene::Coherence::Incoherent}) {
            scene.intersect(rays, hits, coherence);
            for (size_t i = 0; i < count; ++i) {
                CAPTURE(count);
                CAPTURE(i);
                const auto alone = scene.intersect(rays[i]);
                REQUIRE(hits[i].has_value() == alone.has_value());
                if (!alone) continue;
                CHECK(hits[i]->t == alone->t);
                CHECK(hits[i]->u == alone->u);
                CHECK(hits[i]->v == alone->v);
                CHECK(hits[i]->triangle == alone->triangle);
            }
        }
        std::vector<float> distances(count);
        for (size_t i = 0; i < count; ++i) distances[i] = 0.25f + 0.5f * static_cast<float>(i % 5);
        std::unique_ptr<bool[]> answers(new bool[count]);
        scene.occluded(rays, distances, std::span(answers.get(), count));
        for (size_t i = 0; i < count; ++i) {
            CAPTURE(i);
            CHECK(answers[i] == scene.occluded(rays[i], distances[i]));
        }
    }
}

TEST_CASE("scene: the rays traced together meet both geometries, clear cut-out texels and misses") {
    // Guards the test above against a ray set that never exercises what it compares.
    const Scene scene = twoGeometryScene();
    const std::vector<Ray> rays = randomRays(400, 7);
    std::vector<std::optional<RayHit>> hits(rays.size());
    scene.intersect(rays, hits, Scene::Coherence::Incoherent);
    size_t misses = 0, blockerHits = 0, otherHits = 0;
    for (const auto& hit : hits) {
        if (!hit) ++misses;
        else if (hit->triangle >= scene.mesh().triangles.size() - 2) ++blockerHits;
        else ++otherHits;
    }
    CHECK(misses > 20);
    CHECK(blockerHits > 20);
    CHECK(otherHits > 20);
}
