// The per-pixel low-discrepancy values of path_samples.h (pixel jitter, lens point, light sample,
// lobe sample, roulette): each one uniform (so every path is unbiased), each one stratified over a pixel's
// first 2^m paths, and no two of them correlated.
#include <doctest/doctest.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "sampling/path_samples.h"
#include "sampling/sobol.h"
#include "sampling/stratum_schedule.h"
#include "test_support.h"

using namespace strata;

namespace {

using test::kSigmas;

struct Value {
    std::string name;
    std::function<float(const PathSamples&)> get;
};

// Every scalar the per-pixel streams hand out, at bounces 0 and 3.
std::vector<Value> streamValues() {
    std::vector<Value> values{
        {"jitter x", [](const PathSamples& s) { return s.pixelJitter().x; }},
        {"jitter y", [](const PathSamples& s) { return s.pixelJitter().y; }},
        {"lens x", [](const PathSamples& s) { return s.lensPoint().x; }},
        {"lens y", [](const PathSamples& s) { return s.lensPoint().y; }}};
    for (int bounce : {0, 3}) {
        const std::string at = " at bounce " + std::to_string(bounce);
        values.push_back({"light choice" + at, [bounce](const PathSamples& s) { return s.lightSample(bounce).x; }});
        values.push_back({"light point x" + at, [bounce](const PathSamples& s) { return s.lightSample(bounce).y; }});
        values.push_back({"light point y" + at, [bounce](const PathSamples& s) { return s.lightSample(bounce).z; }});
        values.push_back({"lobe choice" + at, [bounce](const PathSamples& s) { return s.lobeSample(bounce).x; }});
        values.push_back({"lobe point x" + at, [bounce](const PathSamples& s) { return s.lobeSample(bounce).y; }});
        values.push_back({"lobe point y" + at, [bounce](const PathSamples& s) { return s.lobeSample(bounce).z; }});
        values.push_back({"roulette" + at, [bounce](const PathSamples& s) { return s.roulette(bounce); }});
    }
    return values;
}

// The path with number n = 24 pass + step at `pixel`.
PathSamples pathNumber(uint64_t seed, uint64_t pixel, uint32_t n) {
    return PathSamples(seed, pixel, n / 24, static_cast<int>(n % 24));
}

// Whether 2^m points form a (t,m,s)-net in base 2: every elementary box of volume 2^(t-m) (sides
// 2^-d_i with sum d_i = m - t) holds exactly 2^t of them.
template <int S>
bool isNet(const std::vector<std::array<double, S>>& points, int m, int t) {
    if (points.size() != (size_t{1} << m)) return false;
    std::array<int, S> d{};
    const int total = m - t;
    // Enumerate every split of `total` into S parts.
    std::function<bool(int, int)> splits = [&](int axis, int left) {
        if (axis == S - 1) {
            d[axis] = left;
            std::vector<int> boxes(size_t{1} << total, 0);
            for (const auto& p : points) {
                size_t box = 0;
                for (int i = 0; i < S; ++i) {
                    box = (box << d[i]) | static_cast<size_t>(std::floor(p[i] * std::ldexp(1.0, d[i])));
                }
                if (++boxes[box] > (1 << t)) return false;
            }
            return true;
        }
        for (int k = 0; k <= left; ++k) {
            d[axis] = k;
            if (!splits(axis + 1, left - k)) return false;
        }
        return true;
    };
    return splits(0, total);
}

}  // namespace

TEST_CASE("path samples: every stream value is uniform for any path, so each path is unbiased") {
    // Over 20000 pixels (independent scrambles) a fixed path's value has mean 1/2 and variance
    // 1/12, and falls into each of 16 intervals equally often.
    constexpr int kPixels = 20000;
    for (const Value& value : streamValues()) {
        for (uint32_t n : {0u, 1u, 29u, 1000u}) {
            double sum = 0.0;
            std::vector<int> counts(16, 0);
            for (int pixel = 0; pixel < kPixels; ++pixel) {
                const float u = value.get(pathNumber(5, static_cast<uint64_t>(pixel), n));
                REQUIRE(u >= 0.0f);
                REQUIRE(u < 1.0f);
                sum += u;
                ++counts[static_cast<int>(u * 16.0f)];
            }
            const double expected = kPixels / 16.0;
            double chi2 = 0.0;
            for (int c : counts) chi2 += (c - expected) * (c - expected) / expected;
            INFO(value.name << ", path " << n << ": mean " << sum / kPixels << ", chi2 " << chi2);
            CHECK(std::abs(sum / kPixels - 0.5) <= kSigmas * std::sqrt(1.0 / 12.0 / kPixels));
            CHECK(chi2 < 45.0);  // 15 degrees of freedom, p ~ 1e-4
        }
    }
}

TEST_CASE("path samples: a pixel's first 2^m paths stratify each value (nets)") {
    for (uint64_t pixel : {0u, 77u}) {
        for (int m = 1; m <= 10; ++m) {
            std::vector<std::array<double, 2>> jitter;
            std::vector<std::array<double, 2>> lens;
            std::vector<std::array<double, 2>> lightPoint;
            std::vector<std::array<double, 3>> light;
            std::vector<std::array<double, 2>> lobePoint;
            std::vector<std::array<double, 3>> lobe;
            std::vector<std::array<double, 1>> roulette;
            for (uint32_t n = 0; n < (1u << m); ++n) {
                const PathSamples s = pathNumber(3, pixel, n);
                jitter.push_back({s.pixelJitter().x, s.pixelJitter().y});
                lens.push_back({s.lensPoint().x, s.lensPoint().y});
                const glm::vec3 l = s.lightSample(2);
                lightPoint.push_back({l.y, l.z});
                // A single light's point alone is the same point, bit for bit.
                CHECK(s.lightPoint(2) == glm::vec2(l.y, l.z));
                light.push_back({l.x, l.y, l.z});
                const glm::vec3 b = s.lobeSample(2);
                lobePoint.push_back({b.y, b.z});
                lobe.push_back({b.x, b.y, b.z});
                roulette.push_back({s.roulette(2)});
            }
            INFO("pixel " << pixel << ", m " << m);
            CHECK(isNet<2>(jitter, m, 0));
            CHECK(isNet<2>(lens, m, 0));
            CHECK(isNet<2>(lightPoint, m, 0));
            // The choice with the point: Sobol's first three dimensions have t = 1.
            CHECK(isNet<3>(light, m, 1));
            CHECK(isNet<2>(lobePoint, m, 0));
            CHECK(isNet<3>(lobe, m, 1));
            CHECK(isNet<1>(roulette, m, 0));
        }
    }
    // The check can fail: hashed (i.i.d.) points are no net.
    std::vector<std::array<double, 2>> bounce;
    for (uint32_t n = 0; n < 16; ++n) {
        const glm::vec2 p = pathNumber(3, 0, n).bouncePoint(0);
        bounce.push_back({p.x, p.y});
    }
    CHECK_FALSE(isNet<2>(bounce, 4, 0));
}

TEST_CASE("path samples: no two stream values of a pixel are correlated") {
    // Padding: every value has its own index shuffle, so two values pair their points at random.
    // The sample correlation of independent values over n paths is about N(0, 1/n).
    constexpr uint32_t kPaths = 4096;
    const std::vector<Value> values = streamValues();
    for (uint64_t pixel : {2u, 9000u}) {
        std::vector<std::vector<double>> series(values.size());
        for (uint32_t n = 0; n < kPaths; ++n) {
            const PathSamples s = pathNumber(11, pixel, n);
            for (size_t v = 0; v < values.size(); ++v) series[v].push_back(values[v].get(s) - 0.5);
        }
        for (size_t a = 0; a < values.size(); ++a) {
            for (size_t b = a + 1; b < values.size(); ++b) {
                double ab = 0.0, aa = 0.0, bb = 0.0;
                for (uint32_t n = 0; n < kPaths; ++n) {
                    ab += series[a][n] * series[b][n];
                    aa += series[a][n] * series[a][n];
                    bb += series[b][n] * series[b][n];
                }
                const double correlation = ab / std::sqrt(aa * bb);
                INFO(values[a].name << " with " << values[b].name << " at pixel " << pixel << ": "
                                    << correlation);
                CHECK(std::abs(correlation) <= kSigmas / std::sqrt(double{kPaths}));
            }
        }
    }
}

TEST_CASE("path samples: a pixel's streams differ from its neighbour's") {
    // Each pixel has its own scrambles: the same path number gives unrelated values elsewhere.
    int equal = 0;
    for (uint32_t n = 0; n < 1000; ++n) {
        equal += pathNumber(1, 0, n).lightSample(0) == pathNumber(1, 1, n).lightSample(0);
        equal += pathNumber(1, 0, n).pixelJitter() == pathNumber(2, 0, n).pixelJitter();
    }
    CHECK(equal == 0);
}

TEST_CASE("path samples: a path's strata are the schedule's, and its stratum points come with them") {
    // PathSamples works the schedule out once per path: asking again, going back or skipping
    // bounces must still give scheduledStratum's answer, and stratumSequencePoint names the same
    // stratum.
    for (int step = 0; step < 24; ++step) {
        const PathSamples samples(3, 41, 7, step);
        for (int bounce : {0, 0, 1, 1, 4, 2, 2, 0, 9, 3, 3}) {
            const int scheduled = scheduledStratum(samples.pixelKey(), 7, step, bounce);
            CHECK(samples.stratum(bounce) == scheduled);
            CHECK(samples.stratumSequencePoint(bounce).stratum == scheduled);
        }
    }
}

TEST_CASE("path samples: from a pixel's shared streams they are the per-path numbers, bit for bit") {
    // A pixel's paths may share its streams (PixelStreams) or work each out alone: the numbers
    // must not depend on which, at cached bounces and past them (depth 3 caches bounces 0..2).
    for (uint64_t pixel : {0u, 5u, 1234567u}) {
        for (uint32_t pass : {0u, 1u, 17u, 600u}) {
            const PixelStreams shared(11, pixel, pass, 3);
            CHECK(shared.cachedBounces() == 3);
            for (int step : {0, 9, 23}) {
                const PathSamples alone(11, pixel, pass, step);
                const PathSamples fromShared(shared, step);
                CHECK(fromShared.pixelKey() == alone.pixelKey());
                CHECK(fromShared.pixelJitter() == alone.pixelJitter());
                CHECK(fromShared.lensPoint() == alone.lensPoint());
                for (int bounce = 0; bounce < 6; ++bounce) {
                    INFO("pixel " << pixel << ", pass " << pass << ", step " << step << ", bounce " << bounce);
                    CHECK(fromShared.lightSample(bounce) == alone.lightSample(bounce));
                    CHECK(fromShared.lightPoint(bounce) == alone.lightPoint(bounce));
                    CHECK(fromShared.lobeSample(bounce) == alone.lobeSample(bounce));
                    CHECK(fromShared.roulette(bounce) == alone.roulette(bounce));
                    CHECK(fromShared.bouncePoint(bounce) == alone.bouncePoint(bounce));
                    CHECK(fromShared.stratum(bounce) == alone.stratum(bounce));
                    CHECK(fromShared.stratumSequencePoint(bounce).stratum == alone.stratumSequencePoint(bounce).stratum);
                    CHECK(fromShared.stratumSequencePoint(bounce).point == alone.stratumSequencePoint(bounce).point);
                }
            }
        }
    }
    // A depth past the cache holds only kMaxCachedBounces; depth 0 none.
    CHECK(PixelStreams(1, 2, 3, 1000).cachedBounces() == PixelStreams::kMaxCachedBounces);
    CHECK(PixelStreams(1, 2, 3, 0).cachedBounces() == 0);
}
