// The Owen-scrambled Sobol' (0,2)-sequence of sobol.h and its use per stratum (strata24-qmc):
// net properties exactly, uniformity of each scrambled point, and the variance it saves.
#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <utility>
#include <vector>

#include "integrator/path_integrator.h"
#include "sampling/direction_sampler.h"
#include "sampling/path_samples.h"
#include "sampling/random.h"
#include "scene/scene.h"
#include "sampling/sobol.h"
#include "test_support.h"

using namespace strata;

namespace {

// Whether points (in [0,1)^2) form a (0,m,2)-net: for every split m = a + b, each of the 2^m
// boxes of size 2^-a x 2^-b holds exactly one point.
bool isNet(const std::vector<glm::dvec2>& points, int m) {
    if (points.size() != (size_t{1} << m)) return false;
    for (int a = 0; a <= m; ++a) {
        std::vector<int> boxes(size_t{1} << m, 0);
        for (const auto& p : points) {
            const auto x = static_cast<size_t>(std::floor(p.x * std::ldexp(1.0, a)));
            const auto y = static_cast<size_t>(std::floor(p.y * std::ldexp(1.0, m - a)));
            if (++boxes[(x << (m - a)) | y] > 1) return false;
        }
    }
    return true;
}

}  // namespace

TEST_CASE("sobol: every aligned block of 2^m points is a (0,m,2)-net, scrambled or not") {
    for (int m = 0; m <= 10; ++m) {
        for (uint32_t block : {0u, 1u, 5u}) {
            std::vector<glm::dvec2> plain;
            std::vector<glm::dvec2> scrambled;
            std::vector<glm::dvec2> ordered;
            for (uint32_t i = block << m; i < (block + 1) << m; ++i) {
                plain.emplace_back(sobolFirstCoordinate(i) * 0x1p-32, sobolSecondCoordinate(i) * 0x1p-32);
                const SobolStream stream(0x1234567u + block);
                const glm::vec2 p = stream.point(i);
                scrambled.emplace_back(p.x, p.y);
                const glm::vec2 q = stream.orderedPoint(i);
                ordered.emplace_back(q.x, q.y);
            }
            INFO("m " << m << " block " << block);
            CHECK(isNet(plain, m));
            CHECK(isNet(scrambled, m));
            CHECK(isNet(ordered, m));
        }
    }
    // Not every point set is a net: i.i.d. points fail already at m = 4.
    std::vector<glm::dvec2> random;
    for (uint64_t i = 0; i < 16; ++i) {
        const uint64_t bits = mixBits(i);
        random.emplace_back(uniformFloat(bits), uniformFloat(bits << 24));
    }
    CHECK_FALSE(isNet(random, 4));
}

TEST_CASE("sobol: the third dimension has Joe and Kuo's direction numbers and makes (1,m,3)-nets") {
    // Direction numbers v_k = m_k / 2^k of their table's third dimension (m = 1, 3, 3, 9, 29).
    const uint32_t directions[] = {0x80000000u, 0xc0000000u, 0x60000000u, 0x90000000u, 0xe8000000u};
    for (int k = 0; k < 5; ++k) CHECK(sobolThirdCoordinate(1u << k) == directions[k]);
    // Every aligned block of 2^m points, scrambled or not, has 2 points in each elementary box
    // of volume 2^(1-m).
    for (int m = 1; m <= 9; ++m) {
        for (uint32_t block : {0u, 3u}) {
            for (bool scrambled : {false, true}) {
                std::vector<glm::dvec3> points;
                bool extendsPoint2 = true;
                for (uint32_t i = block << m; i < (block + 1) << m; ++i) {
                    const glm::vec3 p = SobolStream(0xabcdefu + block).point3(i);
                    if (scrambled) {
                        // The 2D point of the same stream is its first two coordinates, bit for bit.
                        const glm::vec2 p2 = SobolStream(0xabcdefu + block).point(i);
                        extendsPoint2 = extendsPoint2 && p.x == p2.x && p.y == p2.y;
                    }
                    points.push_back(scrambled ? glm::dvec3(p)
                                               : glm::dvec3(sobolFirstCoordinate(i), sobolSecondCoordinate(i),
                                                            sobolThirdCoordinate(i)) * 0x1p-32);
                }
                bool net = true;
                for (int a = 0; a <= m - 1; ++a) {
                    for (int b = 0; a + b <= m - 1; ++b) {
                        const int c = m - 1 - a - b;
                        std::vector<int> boxes(size_t{1} << (m - 1), 0);
                        for (const auto& p : points) {
                            const auto x = static_cast<size_t>(std::floor(p.x * std::ldexp(1.0, a)));
                            const auto y = static_cast<size_t>(std::floor(p.y * std::ldexp(1.0, b)));
                            const auto z = static_cast<size_t>(std::floor(p.z * std::ldexp(1.0, c)));
                            net = net && ++boxes[(((x << b) | y) << c) | z] <= 2;
                        }
                    }
                }
                INFO("m " << m << " block " << block << (scrambled ? " scrambled" : " plain"));
                CHECK(net);
                CHECK(extendsPoint2);
            }
        }
    }
}

TEST_CASE("sobol: a scrambled value sequence puts one of 2^m values in each interval of 2^-m") {
    for (int m = 0; m <= 12; ++m) {
        for (uint32_t block : {0u, 7u}) {
            std::vector<int> counts(size_t{1} << m, 0);
            bool stratified = true;
            for (uint32_t i = block << m; i < (block + 1) << m; ++i) {
                const float u = SobolStream(0x51u + block).value(i);
                stratified = stratified && ++counts[static_cast<size_t>(std::ldexp(u, m))] == 1;
                // The first coordinate of the 2D point with the same stream: one sequence.
                stratified = stratified && u == SobolStream(0x51u + block).point(i).x;
            }
            INFO("m " << m << " block " << block);
            CHECK(stratified);
        }
    }
}

TEST_CASE("sobol: Owen scrambling keeps leading digits together and is a bijection") {
    // Values that share their t leading bits still share them after scrambling (nested), and
    // distinct values stay distinct.
    for (uint32_t seed : {0u, 1u, 0xdeadbeefu}) {
        for (uint32_t k = 0; k < 2000; ++k) {
            const auto a = static_cast<uint32_t>(mixBits(k));
            const auto b = static_cast<uint32_t>(mixBits(k + 100000));
            const int shared = a == b ? 32 : __builtin_clz(a ^ b);
            const uint32_t sa = owenScramble(a, seed);
            const uint32_t sb = owenScramble(b, seed);
            CHECK(sa != sb);
            CHECK((sa == sb ? 32 : __builtin_clz(sa ^ sb)) == shared);
        }
    }
}

TEST_CASE("sobol: each scrambled point is uniform over the streams (chi-square)") {
    // Owen scrambling makes every single point uniform on [0,1)^2, which is what makes each path
    // of strata24-qmc unbiased, with the index shuffle or without it (the pixel jitter).
    // 16 x 16 cells, points 0, 1 and 77 over 64000 streams.
    for (const bool ordered : {false, true}) {
        for (uint32_t index : {0u, 1u, 77u}) {
            constexpr int kBins = 16;
            constexpr int kStreams = 64000;
            std::vector<int> counts(kBins * kBins, 0);
            for (int s = 0; s < kStreams; ++s) {
                const SobolStream stream(hashCombine(99, s));
                const glm::vec2 p = ordered ? stream.orderedPoint(index) : stream.point(index);
                ++counts[static_cast<int>(p.x * kBins) * kBins + static_cast<int>(p.y * kBins)];
            }
            const double expected = static_cast<double>(kStreams) / (kBins * kBins);
            double chi2 = 0.0;
            for (int c : counts) chi2 += (c - expected) * (c - expected) / expected;
            INFO((ordered ? "ordered" : "shuffled") << " index " << index << " chi2 " << chi2);
            CHECK(chi2 < 360.0);  // 255 degrees of freedom, p ~ 1e-5
        }
    }
}

TEST_CASE("sobol: a pixel's passes put a (0,m,2)-net into every stratum (strata24-qmc)") {
    // The first 2^m passes give each stratum, at each bounce, the points 0..2^m-1 of its stream.
    constexpr int m = 6;
    for (int bounce : {0, 1, 4}) {
        std::vector<std::vector<glm::dvec2>> perStratum(24);
        for (uint32_t pass = 0; pass < (1u << m); ++pass) {
            for (int step = 0; step < 24; ++step) {
                const PathSamples samples(3, 41, pass, step);
                const auto [stratum, p] = samples.stratumSequencePoint(bounce);
                perStratum[stratum].emplace_back(p.x, p.y);
            }
        }
        for (int s = 0; s < 24; ++s) {
            INFO("bounce " << bounce << " stratum " << s);
            CHECK(isNet(perStratum[s], m));
        }
    }
}

TEST_CASE("sobol: the strata's points in a pass are independent of each other (strata24-qmc)") {
    // The pass's 24 points share one scrambled point, each XORed with its stratum's random bits:
    // over pixels, two strata's points must be jointly uniform on [0,1)^2 (8 x 8 cells of each
    // coordinate pair). Shifts that differed by fixed bits would tie them together.
    constexpr int kPixels = 64000;
    constexpr int kCells = 8;
    constexpr uint32_t kPass = 5;
    for (int bounce : {0, 3}) {
        for (const auto& [first, second] : {std::pair{0, 1}, std::pair{2, 17}}) {
            std::vector<int> xx(kCells * kCells, 0), xy(kCells * kCells, 0), yy(kCells * kCells, 0);
            for (int pixel = 0; pixel < kPixels; ++pixel) {
                glm::vec2 points[24];
                for (int step = 0; step < 24; ++step) {
                    const auto [stratum, p] = PathSamples(7, static_cast<uint64_t>(pixel), kPass, step).stratumSequencePoint(bounce);
                    points[stratum] = p;
                }
                const auto cell = [](float a, float b) {
                    return static_cast<int>(a * kCells) * kCells + static_cast<int>(b * kCells);
                };
                ++xx[cell(points[first].x, points[second].x)];
                ++xy[cell(points[first].x, points[second].y)];
                ++yy[cell(points[first].y, points[second].y)];
            }
            const double expected = static_cast<double>(kPixels) / (kCells * kCells);
            for (const auto* counts : {&xx, &xy, &yy}) {
                double chi2 = 0.0;
                for (int c : *counts) chi2 += (c - expected) * (c - expected) / expected;
                INFO("bounce " << bounce << ", strata " << first << " and " << second << ": chi2 " << chi2);
                CHECK(chi2 < 115.0);  // 63 degrees of freedom, p ~ 1e-4
            }
        }
    }
}

TEST_CASE("sobol: the qmc samplers have lower variance than their i.i.d. forms on Lambert's polygon") {
    // Measured, not a law: printed for the record, and asserted only where the gap is wide.
    Material receiver;
    receiver.diffuse = glm::vec3(0.7f);
    const Scene scene(test::lambertSquareMesh(receiver));
    const Ray ray = test::rayToOrigin({0.2f, 0.1f, 0.5f});
    const double exact = 0.7 * test::kLambertSquareIrradiance / M_PI;
    const std::pair<SamplerKind, SamplerKind> pairs[] = {
        {SamplerKind::Strata24, SamplerKind::Strata24Qmc},
        {SamplerKind::Strata24Cosine, SamplerKind::Strata24CosineQmc}};
    for (const auto& [plain, qmc] : pairs) {
        for (uint32_t passes : {4u, 32u}) {
            double meanSquaredError[2] = {0.0, 0.0};
            const SamplerKind kinds[2] = {plain, qmc};
            for (int k = 0; k < 2; ++k) {
                const PathIntegrator integrator(scene, {1, kinds[k], false});
                const auto estimates = test::pixelEstimates(integrator, ray, 300, passes, 17);
                for (double e : estimates) meanSquaredError[k] += (e - exact) * (e - exact);
                meanSquaredError[k] /= estimates.size();
            }
            const double ratio = meanSquaredError[1] / meanSquaredError[0];
            std::printf("%s / %s mean squared error at %u passes: %.3f\n", samplerName(qmc).data(),
                        samplerName(plain).data(), passes, ratio);
            CHECK(ratio < 0.8);
        }
    }
}
