#include <doctest/doctest.h>

#include <initializer_list>
#include <glm/geometric.hpp>

#include "geometry/frame.h"
#include "sampling/random.h"

using namespace strata;

namespace {
void checkOrthonormal(const glm::vec3& n) {
    const Frame f = Frame::fromNormal(n);
    CHECK(glm::length(f.tangent) == doctest::Approx(1.0).epsilon(1e-6));
    CHECK(glm::length(f.bitangent) == doctest::Approx(1.0).epsilon(1e-6));
    CHECK(std::abs(glm::dot(f.tangent, f.bitangent)) < 1e-6);
    CHECK(std::abs(glm::dot(f.tangent, n)) < 1e-6);
    CHECK(std::abs(glm::dot(f.bitangent, n)) < 1e-6);
    // Right-handed: tangent x bitangent = normal, so local +z maps to the normal.
    CHECK(glm::length(glm::cross(f.tangent, f.bitangent) - n) < 1e-5);
    const glm::vec3 local(0.3f, -0.4f, 0.866f);
    CHECK(glm::length(f.toLocal(f.toWorld(local)) - local) < 1e-5);
}
}  // namespace

TEST_CASE("frame: orthonormal along and against every axis, including n = -z") {
    for (const glm::vec3 n : {glm::vec3(1, 0, 0), glm::vec3(-1, 0, 0), glm::vec3(0, 1, 0),
                              glm::vec3(0, -1, 0), glm::vec3(0, 0, 1), glm::vec3(0, 0, -1)}) {
        checkOrthonormal(n);
    }
}

TEST_CASE("frame: orthonormal for random normals, and near -z") {
    for (uint64_t i = 0; i < 10000; ++i) {
        const uint64_t bits = mixBits(i);
        glm::vec3 n(uniformFloat(bits) - 0.5f, uniformFloat(bits << 24) - 0.5f,
                    uniformFloat(mixBits(bits)) - 0.5f);
        if (i % 2) n = glm::vec3(n.x * 1e-4f, n.y * 1e-4f, -1.0f);  // hugging -z
        if (glm::length(n) < 1e-3f) continue;
        checkOrthonormal(glm::normalize(n));
    }
}
