// Sampling at the edges of its domain: unit-square inputs at 0 and 1 - ulp, normals exactly along
// and against each axis, directions grazing the surface (z < 1e-7). Every output must be finite,
// unit length within 1e-6, in its stratum and on the right side of the surface.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <vector>
#include <glm/geometric.hpp>

#include "geometry/frame.h"
#include "sampling/hemisphere.h"
#include "scene/scene.h"
#include "sampling/strata24.h"

using namespace strata;

namespace {

const float kOneMinusUlp = std::nextafter(1.0f, 0.0f);
// The corners and edges of [0,1)^2 and values just inside them.
const std::vector<float> kEdgeInputs = {0.0f,  std::numeric_limits<float>::denorm_min(), 1e-30f,
                                        1e-8f, 0x1p-24f, 0.5f, 1.0f - 0x1p-23f, kOneMinusUlp};

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// The six axis normals plus a few off-axis ones, including the Duff et al. branch's edge n.z = -0
// and a normal with z just below zero.
std::vector<glm::vec3> edgeNormals() {
    std::vector<glm::vec3> normals = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1},
                                      {1, 0, -0.0f}, {0, -1, -0.0f}};
    normals.push_back(glm::normalize(glm::vec3(1.0f, 1.0f, -1e-7f)));
    normals.push_back(glm::normalize(glm::vec3(1e-7f, 0.0f, -1.0f)));
    normals.push_back(glm::normalize(glm::vec3(1.0f, 2.0f, 3.0f)));
    return normals;
}

}  // namespace

TEST_CASE("sampling edges: every stratum maps edge inputs into itself, unit and above the horizon") {
    for (int id = 0; id < kStrataCount; ++id) {
        for (float u0 : kEdgeInputs) {
            for (float u1 : kEdgeInputs) {
                const glm::vec3 d = sampleStratum(id, {u0, u1});
                CAPTURE(id);
                CAPTURE(u0);
                CAPTURE(u1);
                REQUIRE(finite(d));
                CHECK(std::abs(glm::length(d) - 1.0f) < 1e-6f);
                CHECK(d.z >= 0.0f);
                CHECK(stratumContains(id, d));
            }
        }
    }
}

TEST_CASE("sampling edges: the uniform hemisphere maps edge inputs to unit directions with z >= 0") {
    for (float u0 : kEdgeInputs) {
        for (float u1 : kEdgeInputs) {
            const glm::vec3 d = sampleUniformHemisphere({u0, u1});
            CAPTURE(u0);
            CAPTURE(u1);
            REQUIRE(finite(d));
            CHECK(std::abs(glm::length(d) - 1.0f) < 1e-6f);
            CHECK(d.z >= 0.0f);
        }
    }
}

TEST_CASE("sampling edges: frames of axis and near-axis normals are orthonormal and keep sides") {
    for (const glm::vec3& n : edgeNormals()) {
        CAPTURE(n.x);
        CAPTURE(n.y);
        CAPTURE(n.z);
        const Frame frame = Frame::fromNormal(n);
        REQUIRE(finite(frame.tangent));
        REQUIRE(finite(frame.bitangent));
        CHECK(std::abs(glm::length(frame.tangent) - 1.0f) < 1e-6f);
        CHECK(std::abs(glm::length(frame.bitangent) - 1.0f) < 1e-6f);
        CHECK(std::abs(glm::dot(frame.tangent, frame.bitangent)) < 1e-6f);
        CHECK(std::abs(glm::dot(frame.tangent, n)) < 1e-6f);
        CHECK(std::abs(glm::dot(frame.bitangent, n)) < 1e-6f);
        // Right-handed, so that the strata's quadrant order is the same on every surface.
        CHECK(glm::dot(glm::cross(frame.tangent, frame.bitangent), n) > 0.999999f);

        // Sampled directions of every stratum, through the frame, stay unit and above the surface.
        for (int id = 0; id < kStrataCount; ++id) {
            for (float u0 : {0.0f, 0.5f, kOneMinusUlp}) {
                for (float u1 : {0.0f, 0.5f, kOneMinusUlp}) {
                    const glm::vec3 local = sampleStratum(id, {u0, u1});
                    const glm::vec3 world = frame.toWorld(local);
                    REQUIRE(finite(world));
                    CHECK(std::abs(glm::length(world) - 1.0f) < 1e-6f);
                    // toLocal inverts toWorld: the stratum is recovered (within rounding).
                    CHECK(glm::length(frame.toLocal(world) - local) < 1e-6f);
                    // Above the surface up to the rounding of the frame (a few ulp).
                    CHECK(glm::dot(world, n) >= local.z - 1e-6f);
                }
            }
        }
    }
}

TEST_CASE("sampling edges: grazing directions (z < 1e-7) leave from the side they head to") {
    // A surface hit at a point far from the origin and at a point near it.
    for (const glm::vec3& point : {glm::vec3(0.25f, -0.5f, 0.75f), glm::vec3(1e5f, -3e5f, 2e5f)}) {
        for (const glm::vec3& n : edgeNormals()) {
            const Frame frame = Frame::fromNormal(n);
            SurfaceHit hit;
            hit.point = point;
            hit.pointError = 0x1p-22f * glm::abs(point);
            hit.normal = n;
            hit.triangle = 0;
            for (float z : {0.0f, 1e-30f, 1e-12f, 1e-8f, 9.9e-8f}) {
                for (int k = 0; k < 16; ++k) {
                    const float phi = 2.0f * 3.14159265f * (static_cast<float>(k) + 0.5f) / 16.0f;
                    const float r = std::sqrt((1.0f - z) * (1.0f + z));
                    const glm::vec3 local(r * std::cos(phi), r * std::sin(phi), z);
                    const glm::vec3 world = frame.toWorld(local);
                    CAPTURE(z);
                    CAPTURE(phi);
                    REQUIRE(finite(world));
                    CHECK(std::abs(glm::length(world) - 1.0f) < 1e-6f);
                    // The origin moves off the surface to the side the direction points to,
                    // whichever way rounding tipped a grazing direction.
                    const glm::vec3 origin = offsetRayOrigin(hit, world);
                    const float side = glm::dot(origin - point, n);
                    CHECK(side != 0.0f);
                    CHECK((glm::dot(world, n) < 0.0f ? side < 0.0f : side > 0.0f));
                }
            }
        }
    }
}
