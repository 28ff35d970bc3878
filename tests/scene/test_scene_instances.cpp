// Shared meshes placed as Embree instances (scene.h, mesh.h): a placed mesh traces, shades and
// lights as its flattened copy does, whatever the placement (translation, rotation, non-uniform
// scale, mirror); its emitters become world lights; its cut-outs stay cut out; a malformed one is
// refused; the world's area and the default camera count every placement.
#include <doctest/doctest.h>

#include <cmath>
#include <memory>
#include <vector>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>

#include "integrator/path_integrator.h"
#include "sampling/random.h"
#include "scene/default_camera.h"
#include "scene/scene.h"
#include "scene/traversal_precision.h"
#include "textures/texture.h"
#include "util/constants.h"
#include "util/error.h"
#include "test_support.h"

using namespace strata;

namespace {

// The four kinds of placement, and all of them at once.
std::vector<glm::mat4> placements() {
    const glm::mat4 translation = glm::translate(glm::mat4(1.0f), glm::vec3(2.5f, -1.0f, 0.5f));
    const glm::mat4 rotation = glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(-2.5f, 0.0f, 0.0f)), 0.7f,
                                           glm::normalize(glm::vec3(1.0f, 2.0f, -0.5f)));
    const glm::mat4 stretch = glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 2.5f, 0.0f)),
                                         glm::vec3(1.5f, 0.4f, 2.0f));
    const glm::mat4 mirror = glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, -2.5f, 0.0f)),
                                        glm::vec3(-1.0f, 1.0f, 1.0f));
    const glm::mat4 all = glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, 3.0f)), -1.1f,
                                      glm::vec3(0.0f, 0.0f, 1.0f)) *
                          glm::scale(glm::mat4(1.0f), glm::vec3(0.7f, -1.3f, 0.9f));
    return {translation, rotation, stretch, mirror, all};
}

// A world floor, then a shared mesh: an open box (a unit cube without its top), its corners'
// normals tilted off the faces' so that shading normals differ from geometric ones, and UVs.
MeshData placedBoxScene() {
    MeshData mesh;
    Material floor;
    floor.diffuse = glm::vec3(0.6f);
    Material box;
    box.diffuse = glm::vec3(0.8f, 0.5f, 0.3f);
    mesh.materials = {floor, box};
    test::addQuad(mesh, {-6, -6, -1}, {6, -6, -1}, {6, 6, -1}, {-6, 6, -1}, 0);
    const auto first = static_cast<uint32_t>(mesh.triangles.size());
    // Each face counter-clockwise seen from outside.
    test::addQuad(mesh, {0, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}, 1);  // z = 0, faces -z
    test::addQuad(mesh, {0, 0, 0}, {1, 0, 0}, {1, 0, 1}, {0, 0, 1}, 1);  // y = 0, faces -y
    test::addQuad(mesh, {0, 1, 0}, {0, 1, 1}, {1, 1, 1}, {1, 1, 0}, 1);  // y = 1, faces +y
    test::addQuad(mesh, {0, 0, 0}, {0, 0, 1}, {0, 1, 1}, {0, 1, 0}, 1);  // x = 0, faces -x
    test::addQuad(mesh, {1, 0, 0}, {1, 1, 0}, {1, 1, 1}, {1, 0, 1}, 1);  // x = 1, faces +x
    const auto count = static_cast<uint32_t>(mesh.triangles.size()) - first;
    mesh.triangleNormals.assign(first, kNoNormals);
    mesh.triangleUvs.assign(first, kNoUvs);
    for (uint32_t t = first; t < first + count; ++t) {
        const auto& c = mesh.triangles[t];
        const glm::vec3 face = glm::normalize(glm::cross(mesh.positions[c[1]] - mesh.positions[c[0]],
                                                         mesh.positions[c[2]] - mesh.positions[c[0]]));
        std::array<uint32_t, 3> normals{};
        std::array<uint32_t, 3> uvs{};
        for (int k = 0; k < 3; ++k) {
            const glm::vec3& p = mesh.positions[c[k]];
            normals[k] = static_cast<uint32_t>(mesh.normals.size());
            mesh.normals.push_back(glm::normalize(face + 0.3f * (p - glm::vec3(0.5f))));
            uvs[k] = static_cast<uint32_t>(mesh.uvs.size());
            mesh.uvs.emplace_back(p.x + 0.5f * p.z, p.y);
        }
        mesh.triangleNormals.push_back(normals);
        mesh.triangleUvs.push_back(uvs);
    }
    mesh.sharedMeshes.push_back({first, count, placements()});
    return mesh;
}

// The mesh with its shared meshes copied into the world, placement by placement, as a loader
// flattens them: positions through the map, normals through its inverse transpose, a mirroring
// placement's corners 1 and 2 swapped.
MeshData flattened(const MeshData& given) {
    MeshData mesh = given;
    mesh.sharedMeshes.clear();
    std::vector<bool> shared(given.triangles.size(), false);
    for (const SharedMesh& s : given.sharedMeshes) {
        for (uint32_t t = s.firstTriangle; t < s.firstTriangle + s.triangleCount; ++t) shared[t] = true;
        for (const glm::mat4& m : s.placements) {
            const glm::mat3 normalMap = glm::transpose(glm::inverse(glm::mat3(m)));
            const bool mirrored = glm::determinant(glm::mat3(m)) < 0.0f;
            for (uint32_t t = s.firstTriangle; t < s.firstTriangle + s.triangleCount; ++t) {
                std::array<uint32_t, 3> order{0, 1, 2};
                if (mirrored) std::swap(order[1], order[2]);
                std::array<uint32_t, 3> vertices{}, normals{}, uvs{};
                for (int k = 0; k < 3; ++k) {
                    vertices[k] = static_cast<uint32_t>(mesh.positions.size());
                    mesh.positions.emplace_back(m * glm::vec4(given.positions[given.triangles[t][order[k]]], 1.0f));
                    normals[k] = static_cast<uint32_t>(mesh.normals.size());
                    mesh.normals.push_back(glm::normalize(normalMap * given.normals[given.triangleNormals[t][order[k]]]));
                    uvs[k] = given.triangleUvs[t][order[k]];
                }
                mesh.triangles.push_back(vertices);
                mesh.triangleMaterials.push_back(given.triangleMaterials[t]);
                mesh.triangleNormals.push_back(normals);
                mesh.triangleUvs.push_back(uvs);
            }
        }
    }
    // The shared originals out, the copies kept.
    MeshData world = mesh;
    world.triangles.clear();
    world.triangleMaterials.clear();
    world.triangleNormals.clear();
    world.triangleUvs.clear();
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        if (t < shared.size() && shared[t]) continue;
        world.triangles.push_back(mesh.triangles[t]);
        world.triangleMaterials.push_back(mesh.triangleMaterials[t]);
        world.triangleNormals.push_back(mesh.triangleNormals[t]);
        world.triangleUvs.push_back(mesh.triangleUvs[t]);
    }
    return world;
}

// Rays from all around the scene toward the placed boxes, in random directions about them.
std::vector<Ray> raysAtBoxes(size_t count, uint64_t seed) {
    std::vector<Ray> rays;
    for (size_t i = 0; i < count; ++i) {
        const auto u = [&](uint64_t d) { return uniformFloat(mixBits(hashCombine(seed, 8 * i + d))); };
        const glm::vec3 origin(12.0f * u(0) - 6.0f, 12.0f * u(1) - 6.0f, 8.0f * u(2) - 0.5f);
        const glm::vec3 toward(8.0f * u(3) - 4.0f, 8.0f * u(4) - 4.0f, 5.0f * u(5) - 1.0f);
        rays.push_back({origin, glm::normalize(toward - origin)});
    }
    return rays;
}

void checkClose(const glm::vec3& a, const glm::vec3& b, float tolerance) {
    CHECK(glm::length(a - b) <= tolerance);
}

}  // namespace

TEST_CASE("instances: a placed mesh traces and shades as its flattened copy, under every kind of placement") {
    const MeshData mesh = placedBoxScene();
    const Scene placed(mesh);
    const Scene flat(flattened(mesh));
    REQUIRE(placed.summary().placements == placements().size());
    CHECK(placed.summary().triangles == 12);
    CHECK(placed.summary().placedTriangles == flat.summary().triangles);
    checkClose(placed.boundsMin(), flat.boundsMin(), 1e-5f);
    checkClose(placed.boundsMax(), flat.boundsMax(), 1e-5f);
    size_t boxHits = 0;
    for (const Ray& ray : raysAtBoxes(4000, 5)) {
        const auto a = placed.intersect(ray);
        const auto b = flat.intersect(ray);
        REQUIRE(a.has_value() == b.has_value());
        if (!a) continue;
        CHECK(a->t == doctest::Approx(b->t).epsilon(1e-4));
        CHECK(placed.triangle(a->triangle).material == flat.triangle(b->triangle).material);
        if (placed.triangle(a->triangle).material == 1) ++boxHits;
        const SurfaceHit sa = placed.surface(*a);
        const SurfaceHit sb = flat.surface(*b);
        checkClose(sa.point, sb.point, 1e-4f);
        // The front side (the normals' sense) as well as the direction: winding kept under mirrors.
        CHECK(glm::dot(sa.normal, sb.normal) > 0.99999f);
        CHECK(glm::dot(sa.shadingNormal, sb.shadingNormal) > 0.9999f);
        CHECK(glm::dot(placed.coatNormal(*a, sa.uv), flat.coatNormal(*b, sb.uv)) > 0.9999f);
        CHECK(sa.smooth == sb.smooth);
        checkClose(glm::vec3(sa.uv, 0.0f), glm::vec3(sb.uv, 0.0f), 1e-4f);
        // A ray leaving the surface does not find it again.
        const glm::vec3 away = glm::dot(ray.direction, sa.normal) < 0.0f ? sa.normal : -sa.normal;
        const Ray leaving{offsetRayOrigin(sa, away), away};
        const auto again = placed.intersect(leaving);
        CHECK_FALSE((again && again->triangle == a->triangle && again->placement == a->placement && again->t < 1e-3f));
    }
    CHECK(boxHits > 500);
}

TEST_CASE("instances: packets of rays find in placed meshes bit for bit what single rays find") {
    const Scene scene(placedBoxScene());
    const std::vector<Ray> rays = raysAtBoxes(203, 9);
    std::vector<std::optional<RayHit>> hits(rays.size());
    scene.intersect(rays, hits, Scene::Coherence::Incoherent);
    size_t placedHits = 0;
    for (size_t i = 0; i < rays.size(); ++i) {
        const auto alone = scene.intersect(rays[i]);
        REQUIRE(hits[i].has_value() == alone.has_value());
        if (!alone) continue;
        CHECK(hits[i]->t == alone->t);
        CHECK(hits[i]->triangle == alone->triangle);
        CHECK(hits[i]->placement == alone->placement);
        if (alone->placement != kNoPlacement) ++placedHits;
    }
    CHECK(placedHits > 20);
}

TEST_CASE("instances: a placed mesh renders as its flattened copy, within the estimates' errors") {
    MeshData mesh = placedBoxScene();
    mesh.environment.kind = Environment::Kind::Uniform;
    mesh.environment.radiance = glm::vec3(1.0f);
    const Scene placed(mesh);
    const Scene flat(flattened(mesh));
    PathIntegratorSettings settings;
    settings.depth = 3;
    settings.nextEventEstimation = true;
    const PathIntegrator placedIntegrator(placed, settings);
    const PathIntegrator flatIntegrator(flat, settings);
    for (const Ray& ray : raysAtBoxes(6, 21)) {
        const auto a = test::estimateMean(test::pixelEstimates(placedIntegrator, ray, 32, 8, 3));
        const auto b = test::estimateMean(test::pixelEstimates(flatIntegrator, ray, 32, 8, 3));
        INFO("placed " << a.mean << " +- " << a.standardError << ", flattened " << b.mean << " +- " << b.standardError);
        CHECK(std::abs(a.mean - b.mean) <= 5.0 * std::hypot(a.standardError, b.standardError) + 1e-9);
    }
}

TEST_CASE("instances: Lambert's square through placed receiver and emitter, tilted, stretched and mirrored") {
    // The receiver z = 0 and the emitter z = 1 of test::lambertSquareMesh, each given as a shared
    // mesh in coordinates that its placement maps onto them: the receiver's a mirrored stretch of
    // a tilted plane (its normals there are not the world's +z, which only the inverse
    // transpose makes them), the emitter's a mirror in z, its front up in its own coordinates.
    const glm::mat4 receiverMap =
        glm::translate(glm::mat4(1.0f), glm::vec3(0.3f, -0.2f, 0.0f)) *
        glm::rotate(glm::mat4(1.0f), 0.5f, glm::vec3(1.0f, 0.0f, 0.0f)) * glm::scale(glm::mat4(1.0f), glm::vec3(-2.0f, 1.0f, 0.5f));
    const glm::mat4 toLocal = glm::inverse(receiverMap);
    const auto local = [&](const glm::vec3& world) { return glm::vec3(toLocal * glm::vec4(world, 1.0f)); };
    Material receiver;
    receiver.diffuse = glm::vec3(0.5f);
    Material emitter;
    emitter.emission = glm::vec3(1.0f);
    MeshData mesh;
    mesh.materials = {receiver, emitter};
    test::addQuad(mesh, local({-50, -50, 0}), local({50, -50, 0}), local({50, 50, 0}), local({-50, 50, 0}), 0);
    const glm::vec3 localNormal = glm::normalize(glm::transpose(glm::mat3(receiverMap)) * glm::vec3(0, 0, 1));
    mesh.normals = {localNormal};
    mesh.triangleNormals = {{0, 0, 0}, {0, 0, 0}};
    test::addQuad(mesh, {-0.5f, -0.5f, -1}, {0.5f, -0.5f, -1}, {0.5f, 0.5f, -1}, {-0.5f, 0.5f, -1}, 1);
    mesh.sharedMeshes = {{0, 2, {receiverMap}}, {2, 2, {glm::scale(glm::mat4(1.0f), glm::vec3(1, 1, -1))}}};
    mesh.environment.kind = Environment::Kind::None;  // as test::lambertSquareMesh: the square alone
    const Scene scene(std::move(mesh));
    REQUIRE(scene.summary().emitters == 2);
    REQUIRE(scene.summary().placements == 1);
    const double expected = 0.5 * test::kLambertSquareIrradiance / kPi;
    for (const bool nee : {false, true}) {
        CAPTURE(nee);
        PathIntegratorSettings settings;
        settings.depth = 1;
        settings.nextEventEstimation = nee;
        const PathIntegrator integrator(scene, settings);
        const auto estimate = test::estimateMean(
            test::pixelEstimates(integrator, test::rayToOrigin({0.3f, 0.2f, 0.4f}), 64, 40, 11));
        INFO("estimate " << estimate.mean << " +- " << estimate.standardError << ", expected " << expected);
        CHECK(std::abs(estimate.mean - expected) < 5.0 * estimate.standardError);
        CHECK(estimate.standardError < 0.02 * expected);
    }
}

TEST_CASE("instances: each placement of an emitting triangle is a world light of its own") {
    Material lamp;
    lamp.emission = glm::vec3(2.0f);
    Material grey;
    grey.diffuse = glm::vec3(0.5f);
    MeshData mesh;
    mesh.materials = {grey, lamp};
    test::addQuad(mesh, {0, 0, -3}, {1, 0, -3}, {1, 1, -3}, {0, 1, -3}, 0);  // world, not emitting
    test::addQuad(mesh, {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, 1);  // shared: lamp and grey
    test::addQuad(mesh, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}, 0);
    const glm::mat4 twice = glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, 5)), glm::vec3(2.0f));
    const glm::mat4 mirrored = glm::scale(glm::mat4(1.0f), glm::vec3(1, 1, -1));
    mesh.sharedMeshes = {{2, 4, {twice, mirrored}}};
    const Scene scene(std::move(mesh));
    // The lamp's two triangles in the world at each placement; the grey quad stays shared.
    CHECK(scene.summary().emitters == 4);
    CHECK(scene.summary().emittingArea == doctest::Approx(4.0 + 1.0));
    CHECK(scene.summary().triangles == 2 + 2 + 4);
    CHECK(scene.summary().placements == 2);
    CHECK(scene.summary().placedTriangles == 2 + 4 + 4);
    REQUIRE(scene.lights().size() == 4);
    double power = 0.0;
    for (uint32_t i = 0; i < 4; ++i) power += scene.lights().light(i).power().x;
    CHECK(power == doctest::Approx(kPi * 2.0 * 5.0));
    // Each lamp faces where its placement turns its front: up at z = 5, down (mirrored) at z = 0.
    const auto lampNormalAt = [&](const glm::vec3& from, const glm::vec3& direction) {
        const auto hit = scene.intersect(Ray{from, direction});
        REQUIRE(hit.has_value());
        REQUIRE(scene.triangle(hit->triangle).light >= 0);
        CHECK(hit->placement == kNoPlacement);
        return scene.triangle(hit->triangle).normal;
    };
    CHECK(lampNormalAt({1.0f, 1.0f, 6.0f}, {0, 0, -1}).z == doctest::Approx(1.0f));
    CHECK(lampNormalAt({0.5f, 0.5f, -0.5f}, {0, 0, 1}).z == doctest::Approx(-1.0f));
}

TEST_CASE("instances: a placed mesh's cut-outs are cut out at every placement") {
    // A quad half clear across u (its coverage texture), placed at z = 1 and, turned over, at
    // z = 2, above a world floor at z = 0.
    Material floor;
    floor.diffuse = glm::vec3(0.5f);
    Material blocker;
    blocker.diffuse = glm::vec3(0.5f);
    blocker.textures.coverage = std::make_shared<Texture>(2, 1, 1, std::vector<float>{0.0f, 1.0f});
    MeshData mesh;
    mesh.materials = {floor, blocker};
    test::addQuad(mesh, {-5, -5, 0}, {5, -5, 0}, {5, 5, 0}, {-5, 5, 0}, 0);
    test::addQuad(mesh, {-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, 1);
    mesh.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    mesh.triangleUvs = {kNoUvs, kNoUvs, {0, 1, 2}, {0, 2, 3}};
    const glm::mat4 low = glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, 1));
    const glm::mat4 high = glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, 2)), kPi, glm::vec3(0, 1, 0));
    mesh.sharedMeshes = {{2, 2, {low, high}}};
    const Scene scene(std::move(mesh));
    // Down through x < 0: clear at z = 1 (u < 1/2), opaque at z = 2 (turned over: u > 1/2).
    const auto left = scene.intersect(Ray{{-0.5f, 0.1f, 3.0f}, {0, 0, -1}});
    REQUIRE(left.has_value());
    CHECK(left->t == doctest::Approx(1.0f));
    CHECK(left->placement == 1);
    // Down through x > 0: clear at z = 2, opaque at z = 1.
    const auto right = scene.intersect(Ray{{0.5f, 0.1f, 3.0f}, {0, 0, -1}});
    REQUIRE(right.has_value());
    CHECK(right->t == doctest::Approx(2.0f));
    CHECK(right->placement == 0);
    // Up from the floor's left half through the clear half at z = 1 to the opaque one at z = 2.
    CHECK(scene.occluded(Ray{{-0.5f, 0.1f, 0.01f}, {0, 0, 1}}, 1.5f) == false);
    CHECK(scene.occluded(Ray{{-0.5f, 0.1f, 0.01f}, {0, 0, 1}}, 2.5f) == true);
    CHECK(scene.occluded(Ray{{0.5f, 0.1f, 0.01f}, {0, 0, 1}}, 1.5f) == true);
}

TEST_CASE("instances: the rounding gap share counts placed triangles at their size in the world") {
    const MeshData mesh = placedBoxScene();
    const double placed = roundingGapShare(mesh);
    const double flat = roundingGapShare(flattened(mesh));
    // The bound sigma_1^2 / |det| is exact for similarities and above the truth for a stretch.
    CHECK(placed >= flat * (1.0 - 1e-5));
    CHECK(placed <= flat * 3.0);
    MeshData similar = mesh;
    similar.sharedMeshes[0].placements = {glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(1e3f, 0, 0)), glm::vec3(0.25f))};
    CHECK(roundingGapShare(similar) == doctest::Approx(roundingGapShare(flattened(similar))).epsilon(1e-5));
    // A small mesh placed far from the origin needs the watertight test, as its flattened copy does.
    CHECK(roundingGapShare(similar) > kTolerableGapShare);
}

TEST_CASE("instances: malformed shared meshes are refused in one line") {
    const auto refusal = [](MeshData mesh) {
        try {
            Scene scene(std::move(mesh));
        } catch (const Error& error) {
            return std::string(error.what());
        }
        return std::string("(built)");
    };
    MeshData singular = placedBoxScene();
    singular.sharedMeshes[0].placements.push_back(glm::scale(glm::mat4(1.0f), glm::vec3(1, 0, 1)));
    CHECK(refusal(singular) == "a shared mesh's placement is not a finite, invertible affine transform");
    MeshData beyond = placedBoxScene();
    beyond.sharedMeshes[0].triangleCount += 1;
    CHECK(refusal(beyond) == "the shared meshes need disjoint, increasing, non-empty ranges of the triangles");
    MeshData sharedVertex = placedBoxScene();
    sharedVertex.triangles[0][0] = sharedVertex.triangles[2][0];
    CHECK(refusal(sharedVertex) == "a vertex is used by two parts of the scene (mesh.h's shared meshes)");
}

TEST_CASE("instances: the world's area and the default camera take every placement") {
    // A shared unit square placed moved, turned and mirrored (area 1 each) and doubled (area 4).
    MeshData mesh;
    mesh.materials.resize(1);
    test::addQuad(mesh, {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, 0);
    const glm::mat4 identity(1.0f);
    const glm::mat4 moved = glm::translate(identity, glm::vec3(10.0f, 0.0f, 0.0f));
    const glm::mat4 turned = glm::rotate(glm::translate(identity, glm::vec3(-10.0f, 0.0f, 0.0f)), 0.7f,
                                         glm::normalize(glm::vec3(1.0f, 2.0f, -0.5f)));
    const glm::mat4 mirrored = glm::scale(glm::translate(identity, glm::vec3(0.0f, 10.0f, 0.0f)),
                                          glm::vec3(-1.0f, 1.0f, 1.0f));
    const glm::mat4 doubled = glm::scale(glm::translate(identity, glm::vec3(0.0f, -10.0f, 0.0f)), glm::vec3(2.0f));
    mesh.sharedMeshes = {{0, 2, {moved, turned, mirrored, doubled}}};
    CHECK(worldArea(mesh) == doctest::Approx(7.0).epsilon(1e-6));
    // A world triangle beside them counts once.
    MeshData withFloor = mesh;
    test::addQuad(withFloor, {0, 0, -5}, {3, 0, -5}, {3, 2, -5}, {0, 2, -5}, 0);
    CHECK(worldArea(withFloor) == doctest::Approx(13.0).epsilon(1e-6));

    // The default camera frames the placed squares, not the stored one (which alone is flat).
    const auto [lower, upper] = worldBounds(mesh);
    const CameraPose pose = defaultCameraPose(mesh, kGltfOrientation);
    CHECK(glm::length(pose.lookAt - 0.5f * (lower + upper)) < 1e-4f);
    const float radius = 0.5f * glm::length(upper - lower);
    CHECK(glm::length(pose.position - pose.lookAt) ==
          doctest::Approx(radius / std::sin(glm::radians(0.5f * kDefaultFovYDegrees))).epsilon(1e-5));
    CHECK(radius > 10.0f);
}
