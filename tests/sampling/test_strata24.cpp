#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <vector>
#include <glm/geometric.hpp>

#include "sampling/hemisphere.h"
#include "sampling/strata24.h"
#include "test_support.h"

using namespace strata;

namespace {

using Triangle = std::array<glm::dvec3, 3>;

// Solid angle of a spherical triangle (Van Oosterom & Strackee 1983): no cancellation for small
// or large triangles, unlike Girard's angle excess.
double solidAngle(const Triangle& t) {
    const auto& [a, b, c] = t;
    const double numerator = std::abs(glm::dot(a, glm::cross(b, c)));
    const double denominator = 1.0 + glm::dot(a, b) + glm::dot(b, c) + glm::dot(c, a);
    return 2.0 * std::atan2(numerator, denominator);
}

Triangle verticesOf(int id) {
    const auto v = stratumVertices(id);
    return {glm::dvec3(v[0]), glm::dvec3(v[1]), glm::dvec3(v[2])};
}

bool insideSpherical(const Triangle& t, const glm::dvec3& d) {
    const double s0 = glm::dot(d, glm::cross(t[0], t[1]));
    const double s1 = glm::dot(d, glm::cross(t[1], t[2]));
    const double s2 = glm::dot(d, glm::cross(t[2], t[0]));
    return (s0 >= 0 && s1 >= 0 && s2 >= 0) || (s0 <= 0 && s1 <= 0 && s2 <= 0);
}

// Splits a spherical triangle into 4 by its edge midpoints, `levels` times: a partition into
// 4^levels cells whose areas are exact (Van Oosterom), independent of the sampler's own map.
std::vector<Triangle> subdivide(const Triangle& t, int levels) {
    if (levels == 0) return {t};
    const glm::dvec3 ab = glm::normalize(t[0] + t[1]);
    const glm::dvec3 bc = glm::normalize(t[1] + t[2]);
    const glm::dvec3 ca = glm::normalize(t[2] + t[0]);
    std::vector<Triangle> cells;
    for (const Triangle& child : {Triangle{t[0], ab, ca}, Triangle{ab, t[1], bc},
                                  Triangle{ca, bc, t[2]}, Triangle{ab, bc, ca}}) {
        const auto grandchildren = subdivide(child, levels - 1);
        cells.insert(cells.end(), grandchildren.begin(), grandchildren.end());
    }
    return cells;
}

}  // namespace

TEST_CASE("strata24: every stratum has solid angle pi/12 and angles pi/4, pi/2, pi/3") {
    double total = 0.0;
    for (int id = 0; id < kStrataCount; ++id) {
        const Triangle t = verticesOf(id);
        CHECK(solidAngle(t) == doctest::Approx(M_PI / 12).epsilon(1e-6));
        total += solidAngle(t);
        for (const auto& v : t) CHECK(v.z >= -1e-7);
    }
    CHECK(total == doctest::Approx(2 * M_PI).epsilon(1e-6));
}

TEST_CASE("strata24: the strata partition the hemisphere (each direction in exactly one)") {
    std::array<int, kStrataCount> counts{};
    constexpr int kSamples = 240000;
    for (int i = 0; i < kSamples; ++i) {
        const glm::vec3 d = sampleUniformHemisphere(test::hashedPoint(i + 0x5eed24));
        int containing = 0;
        for (int id = 0; id < kStrataCount; ++id) containing += stratumContains(id, d) ? 1 : 0;
        REQUIRE(containing == 1);  // boundaries have measure zero
        const int id = classifyStratum(d);
        REQUIRE(stratumContains(id, d));
        ++counts[id];
    }
    // Equal solid angles: a uniform direction is equally likely to fall in each.
    const double expected = static_cast<double>(kSamples) / kStrataCount;
    double chiSquare = 0.0;
    for (int c : counts) chiSquare += (c - expected) * (c - expected) / expected;
    CHECK(chiSquare < test::chiSquareCritical(kStrataCount - 1));
}

TEST_CASE("strata24: the convention of the notes (section 2.2) holds") {
    CHECK(classifyStratum(glm::normalize(glm::vec3(0.2f, 0.1f, 1.0f))) == 0);   // Fig. 2 triangle
    CHECK(classifyStratum(glm::normalize(glm::vec3(0.9f, 0.5f, 0.1f))) == 4);   // x >= y >= z
    CHECK(classifyStratum(glm::normalize(glm::vec3(-0.2f, 0.1f, 1.0f))) == 6);  // quadrant 1
    CHECK(classifyStratum(glm::normalize(glm::vec3(-0.1f, -0.5f, 0.3f))) == 15);  // q2, |y|>=z>=|x|
    CHECK(classifyStratum(glm::normalize(glm::vec3(0.3f, -0.9f, 0.1f))) == 23);   // q3, |y|>=|x|>=z
}

TEST_CASE("strata24: samples are unit, above the surface, in their stratum") {
    for (int id = 0; id < kStrataCount; ++id) {
        for (uint64_t i = 0; i < 20000; ++i) {
            const glm::vec3 d = sampleStratum(id, test::hashedPoint(i + 1000000 * id + 0x5eed24));
            REQUIRE(std::abs(glm::length(d) - 1.0f) < 1e-6f);
            REQUIRE(d.z >= 0.0f);
            REQUIRE(stratumContains(id, d));
        }
    }
}

TEST_CASE("strata24: edges and corners of the unit square stay inside the stratum") {
    const float almostOne = std::nextafter(1.0f, 0.0f);
    const float values[] = {0.0f, std::numeric_limits<float>::denorm_min(), 1e-7f, 0.5f,
                            std::nextafter(almostOne, 0.0f), almostOne};
    for (int id = 0; id < kStrataCount; ++id) {
        for (float u : values) {
            for (float v : values) {
                const glm::vec3 d = sampleStratum(id, {u, v});
                INFO("id " << id << " u " << u << " v " << v);
                CHECK(std::isfinite(d.x));
                CHECK(std::abs(glm::length(d) - 1.0f) < 1e-6f);
                CHECK(d.z >= 0.0f);
                CHECK(stratumContains(id, d));
            }
        }
    }
}

TEST_CASE("strata24: the map is area-preserving (chi-square over 256 exact-area cells)") {
    // An independent partition of each stratum into 4^4 = 256 spherical triangles with exact
    // areas: a uniform map fills each in proportion to its area.
    constexpr int kLevels = 4;
    constexpr int kSamples = 128000;
    for (int id = 0; id < kStrataCount; id += 5) {  // one stratum of every class and quadrant
        const auto cells = subdivide(verticesOf(id), kLevels);
        std::vector<int> counts(cells.size(), 0);
        for (int i = 0; i < kSamples; ++i) {
            const glm::dvec3 d(sampleStratum(id, test::hashedPoint(i + 7777777ull * (id + 1) + 0x5eed24)));
            // Descend the subdivision: the cell index has one base-4 digit per level.
            Triangle t = verticesOf(id);
            size_t index = 0;
            for (int level = 0; level < kLevels; ++level) {
                const glm::dvec3 ab = glm::normalize(t[0] + t[1]);
                const glm::dvec3 bc = glm::normalize(t[1] + t[2]);
                const glm::dvec3 ca = glm::normalize(t[2] + t[0]);
                const Triangle children[] = {{t[0], ab, ca}, {ab, t[1], bc}, {ca, bc, t[2]}, {ab, bc, ca}};
                int child = 3;
                for (int c = 0; c < 3; ++c) {
                    if (insideSpherical(children[c], d)) {
                        child = c;
                        break;
                    }
                }
                index = index * 4 + child;
                t = children[child];
            }
            ++counts[index];
        }
        double chiSquare = 0.0;
        for (size_t c = 0; c < cells.size(); ++c) {
            const double expected = kSamples * solidAngle(cells[c]) / (M_PI / 12);
            chiSquare += (counts[c] - expected) * (counts[c] - expected) / expected;
        }
        INFO("stratum " << id << " chi-square " << chiSquare);
        CHECK(chiSquare < test::chiSquareCritical(cells.size() - 1));
    }
}

TEST_CASE("strata24: mean of cos(theta) per stratum class matches the exact values (notes 3)") {
    // E[z] inside a stratum = (integral of z over it) / (pi/12): pole, middle, equator classes.
    const double exact[] = {0.8311896360, 0.4589410716, 0.2098692924};
    const double variance[] = {0.0100097193, 0.0242210046, 0.0202210380};
    constexpr int kSamples = 200000;
    for (int id = 0; id < kStrataCount; ++id) {
        double sum = 0.0;
        for (int i = 0; i < kSamples; ++i) sum += sampleStratum(id, test::hashedPoint(i + 31337ull * id + 0x5eed24)).z;
        const int cls = (id % 6) / 2;
        const double standardError = std::sqrt(variance[cls] / kSamples);
        CHECK(std::abs(sum / kSamples - exact[cls]) < 4.0 * standardError);
    }
}
