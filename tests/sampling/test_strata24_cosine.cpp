// Cosine-weighted sampling inside the 24 strata (strata24_cosine.h): the exact projected solid
// angles of notes section 3, and the sampled density cos / PSA_i checked by chi-square against an
// independent quadrature through the uniform stratum map of strata24.h.
#include <doctest/doctest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "sampling/random.h"
#include "sampling/strata24.h"
#include "sampling/strata24_cosine.h"

using namespace strata;

TEST_CASE("strata24-cosine: projected solid angles are the closed forms and sum to pi") {
    const double pole = std::asin(1.0 / std::sqrt(3.0)) / (2.0 * std::sqrt(2.0));
    const double middle = std::asin(1.0 / 3.0) / (2.0 * std::sqrt(2.0));
    const double equator = M_PI / 8.0 - std::acos(1.0 / std::sqrt(3.0)) / (2.0 * std::sqrt(2.0));
    double sum = 0.0;
    for (int id = 0; id < kStrataCount; ++id) {
        const double expected = id % 6 < 2 ? pole : (id % 6 < 4 ? middle : equator);
        CHECK(stratumProjectedSolidAngle(id) == doctest::Approx(expected).epsilon(1e-15));
        sum += stratumProjectedSolidAngle(id);
        // Independently: integral of z over the stratum through the uniform map (pdf 12/pi).
        constexpr int n = 400;
        double integral = 0.0;
        for (int i = 0; i < n; ++i) {
            for (int j = 0; j < n; ++j) {
                integral += sampleStratum(id, {(i + 0.5f) / n, (j + 0.5f) / n}).z;
            }
        }
        integral *= (M_PI / 12.0) / (n * n);
        CHECK(integral == doctest::Approx(expected).epsilon(1e-4));
    }
    CHECK(sum == doctest::Approx(M_PI).epsilon(1e-14));
}

TEST_CASE("strata24-cosine: samples stay in their stratum, unit length, at edges and corners too") {
    const float almostOne = 1.0f - std::numeric_limits<float>::epsilon() / 2.0f;
    const float edges[] = {0.0f, 1e-7f, 0.25f, 0.5f, 0.999f, almostOne};
    for (int id = 0; id < kStrataCount; ++id) {
        for (float a : edges) {
            for (float b : edges) {
                const glm::vec3 d = sampleStratumCosine(id, {a, b});
                INFO("stratum " << id << " u " << a << " v " << b);
                CHECK(std::isfinite(d.x));
                CHECK(std::abs(d.x * d.x + d.y * d.y + d.z * d.z - 1.0f) < 4e-7f);
                CHECK(d.z >= 0.0f);
                CHECK(stratumContains(id, d));
            }
        }
        for (int k = 0; k < 2000; ++k) {
            const uint64_t bits = mixBits(static_cast<uint64_t>(id * 100000 + k));
            const glm::vec3 d = sampleStratumCosine(id, {uniformFloat(bits), uniformFloat(bits << 24)});
            REQUIRE(stratumContains(id, d));
        }
    }
}

TEST_CASE("strata24-cosine: the density inside each stratum is cos / PSA (chi-square)") {
    // Cells are bins of (z, azimuth); their expected probabilities are integrals of z / PSA
    // computed through the uniform map (pdf 12/pi), an independent route to the same density.
    // One stratum per class, plus a mirrored one (odd order) and two in other quadrants.
    constexpr int kZBins = 8;
    constexpr int kPhiBins = 8;
    auto cellOf = [](const glm::vec3& d) {
        const int zb = std::min(kZBins - 1, static_cast<int>(d.z * kZBins));
        const double phi = std::atan2(d.y, d.x) + M_PI;  // [0, 2 pi]
        const int pb = std::min(kPhiBins * 8 - 1, static_cast<int>(phi / (2.0 * M_PI) * kPhiBins * 8));
        return zb * kPhiBins * 8 + pb;
    };
    for (int id : {0, 2, 4, 5, 13, 21}) {
        const double psa = stratumProjectedSolidAngle(id);
        std::vector<double> expected(kZBins * kPhiBins * 8, 0.0);
        constexpr int n = 600;
        for (int i = 0; i < n; ++i) {
            for (int j = 0; j < n; ++j) {
                const glm::vec3 d = sampleStratum(id, {(i + 0.5f) / n, (j + 0.5f) / n});
                expected[cellOf(d)] += d.z * (M_PI / 12.0) / (n * n) / psa;
            }
        }
        constexpr int kSamples = 100000;
        std::vector<int> counts(expected.size(), 0);
        for (int k = 0; k < kSamples; ++k) {
            const uint64_t bits = mixBits(hashCombine(static_cast<uint64_t>(id), k));
            ++counts[cellOf(sampleStratumCosine(id, {uniformFloat(bits), uniformFloat(bits << 24)}))];
        }
        double chi2 = 0.0;
        int cells = 0;
        for (size_t c = 0; c < counts.size(); ++c) {
            const double e = expected[c] * kSamples;
            if (e < 20.0) continue;
            chi2 += (counts[c] - e) * (counts[c] - e) / e;
            ++cells;
        }
        // chi-square with cells - 1 degrees of freedom: fail beyond mean + 5 sd (p < 1e-5).
        const double dof = cells - 1;
        INFO("stratum " << id << ": chi2 " << chi2 << " over " << cells << " cells");
        CHECK(cells >= 8);
        CHECK(chi2 < dof + 5.0 * std::sqrt(2.0 * dof) + 10.0);
    }
}

TEST_CASE("strata24-cosine: the equator azimuth table is the exact inverse to 1e-8") {
    double worst = 0.0;
    for (int i = 0; i <= 20000; ++i) {
        const double u = i / 20000.0;
        worst = std::max(worst, std::abs(equatorTanPhi(u) - equatorTanPhiExact(u)));
    }
    for (double u : {0.0, 1e-12, 1e-6, 0.999999, 1.0}) worst = std::max(worst, std::abs(equatorTanPhi(u) - equatorTanPhiExact(u)));
    CHECK(worst < 1e-8);
    CHECK(equatorTanPhi(0.0) == 0.0);
    CHECK(equatorTanPhi(1.0) == doctest::Approx(1.0).epsilon(1e-12));
}
