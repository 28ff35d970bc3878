// The traced scene's surface records (scene.h): the shading normal interpolated from the vertex
// normals, the geometric one otherwise, and triangles turned over to agree with their normals.
#include <doctest/doctest.h>

#include <glm/geometric.hpp>

#include "scene/scene.h"
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
    const LightHit fromAbove{scene.triangle(0).normal, 1.0f};
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
