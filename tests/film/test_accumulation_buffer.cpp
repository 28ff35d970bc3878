#include <doctest/doctest.h>

#include <cmath>
#include <limits>

#include "film/accumulation_buffer.h"
#include "integrator/pass_partition.h"
#include "integrator/progressive_renderer.h"
#include "scene/scene_loader.h"
#include "test_support.h"
#include "util/error.h"

using namespace strata;

TEST_CASE("accumulation: mean, counts and the two standard errors") {
    AccumulationBuffer buffer(2, 1);
    // Pixel 0: passes of 2 samples each with pass means 1 and 3.
    buffer.addSample(0, glm::vec3(0.0f));
    buffer.addSample(0, glm::vec3(2.0f));
    buffer.completePass(0);
    buffer.addSample(0, glm::vec3(2.0f));
    buffer.addSample(0, glm::vec3(4.0f));
    buffer.completePass(0);
    CHECK(buffer.mean(0).x == 2.0);
    CHECK(buffer.sampleCount(0) == 4);
    CHECK(buffer.completedPasses(0) == 2);
    // Samples 0,2,2,4 (luminance = value for grey): variance 8/3, SE sqrt(8/3/4).
    CHECK(buffer.sampleStandardError(0) == doctest::Approx(std::sqrt(8.0 / 3.0 / 4.0)));
    // Pass means 1, 3: variance 2, SE sqrt(2/2) = 1.
    CHECK(buffer.passStandardError(0) == doctest::Approx(1.0));
    CHECK(buffer.mean(1).x == 0.0);  // no samples: zero, not NaN
    CHECK(buffer.passStandardError(1) == 0.0);
}

TEST_CASE("accumulation: a buffer without error estimates has the same means, coverage and drops") {
    AccumulationBuffer kept(2, 1);
    AccumulationBuffer bare(2, 1, PixelErrors::NotKept);
    CHECK(kept.keepsErrors());
    CHECK(!bare.keepsErrors());
    const float nan = std::numeric_limits<float>::quiet_NaN();
    for (AccumulationBuffer* buffer : {&kept, &bare}) {
        buffer->addSample(0, glm::vec3(0.25f, 1.0f, 3.0f), true);
        buffer->addSample(0, glm::vec3(2.0f), false);
        buffer->addSample(1, glm::vec3(nan), true);
        buffer->addSample(1, glm::vec3(0.5f), true);
        buffer->completePass(0);
        buffer->completePass(1);
    }
    for (size_t p = 0; p < 2; ++p) {
        CHECK(bare.mean(p) == kept.mean(p));
        CHECK(bare.sampleCount(p) == kept.sampleCount(p));
        CHECK(bare.coverage(p) == kept.coverage(p));
    }
    CHECK(bare.droppedSamples() == 1);
    CHECK(bare.imageMean() == kept.imageMean());
    CHECK(bare.meanImage().pixels == kept.meanImage().pixels);
    CHECK(bare.meanImage().alpha == kept.meanImage().alpha);
    CHECK_THROWS_AS(bare.completedPasses(0), Error);
    CHECK_THROWS_AS(bare.sampleStandardError(0), Error);
    CHECK_THROWS_AS(bare.passStandardError(0), Error);
    // The arrays an MPI reduction adds: the sums' and counts' only (the RGB sums, 3 a pixel).
    size_t reals = 0;
    for (const auto array : bare.realArrays()) reals += array.size();
    size_t counts = 0;
    for (const auto array : bare.countArrays()) counts += array.size();
    CHECK(reals == 3 * 2);
    CHECK(counts == 3 * 2);
}

TEST_CASE("accumulation: non-finite samples are dropped and counted, never added") {
    AccumulationBuffer buffer(1, 1);
    buffer.addSample(0, glm::vec3(1.0f));
    const float inf = std::numeric_limits<float>::infinity();
    const float nan = std::numeric_limits<float>::quiet_NaN();
    buffer.addSample(0, glm::vec3(nan, 0.0f, 0.0f));
    buffer.addSample(0, glm::vec3(0.0f, inf, 0.0f));
    buffer.addSample(0, glm::vec3(0.0f, 0.0f, -inf));
    CHECK(buffer.mean(0) == glm::dvec3(1.0));
    CHECK(buffer.sampleCount(0) == 1);
    CHECK(buffer.droppedSamples() == 3);
    buffer.clear();
    CHECK(buffer.droppedSamples() == 0);
    CHECK(buffer.sampleCount(0) == 0);
}

// What the MPI reduction does (app/render_job.cpp), in one process: each "rank" renders its
// passes into its own buffer and the buffers are added element-wise; the result must match one
// buffer that saw every pass, counts exactly and doubles within the summation-order bound
// 2*gamma_{n-1}, gamma_k = k*u/(1 - k*u), u = 2^-53 (Higham §4.2; radiance is non-negative).
TEST_CASE("accumulation buffer: buffers of disjoint passes add up to the single-process buffer") {
    const LoadedScene loaded = loadScene(test::cornellScene());
    const Camera camera(loaded.settings.pose, 20, 16);
    RenderSettings settings;
    settings.seed = 7;
    settings.threads = 2;
    constexpr uint32_t kPasses = 5;
    constexpr int kRanks = 3;  // 2 + 2 + 1 passes

    AccumulationBuffer single(camera.width(), camera.height());
    ProgressiveRenderer renderer(loaded.scene, camera, settings);
    for (uint32_t pass = 0; pass < kPasses; ++pass) renderer.renderPass(single, pass);

    AccumulationBuffer combined(camera.width(), camera.height());
    for (int rank = 0; rank < kRanks; ++rank) {
        AccumulationBuffer part(camera.width(), camera.height());
        const PassRange range = passesOfRank(kPasses, rank, kRanks);
        for (uint32_t pass = range.begin; pass < range.end; ++pass) renderer.renderPass(part, pass);
        const auto into = combined.realArrays();
        const auto from = part.realArrays();
        for (size_t a = 0; a < into.size(); ++a) {
            for (size_t i = 0; i < into[a].size(); ++i) into[a][i] += from[a][i];
        }
        const auto countsInto = combined.countArrays();
        const auto countsFrom = part.countArrays();
        for (size_t a = 0; a < countsInto.size(); ++a) {
            for (size_t i = 0; i < countsInto[a].size(); ++i) countsInto[a][i] += countsFrom[a][i];
        }
    }

    const auto singleCounts = single.countArrays();
    const auto combinedCounts = combined.countArrays();
    for (size_t a = 0; a < singleCounts.size(); ++a) {
        for (size_t i = 0; i < singleCounts[a].size(); ++i) {
            REQUIRE(combinedCounts[a][i] == singleCounts[a][i]);
        }
    }
    const double n = kPasses * kPathsPerPass;
    const double u = std::numeric_limits<double>::epsilon() / 2.0;
    const double bound = 2.0 * (n - 1.0) * u / (1.0 - (n - 1.0) * u);
    const auto singleSums = single.realArrays();
    const auto combinedSums = combined.realArrays();
    double worst = 0.0;
    for (size_t a = 0; a < singleSums.size(); ++a) {
        for (size_t i = 0; i < singleSums[a].size(); ++i) {
            const double x = singleSums[a][i];
            const double y = combinedSums[a][i];
            REQUIRE(x >= 0.0);  // the bound's premise: sums of non-negative values
            if (x != y) worst = std::max(worst, std::abs(x - y) / x);
        }
    }
    MESSAGE("largest relative difference " << worst << ", bound " << bound);
    CHECK(worst <= bound);
    for (size_t pixel = 0; pixel < single.pixelCount(); ++pixel) {
        CHECK(combined.passStandardError(pixel) ==
              doctest::Approx(single.passStandardError(pixel)).epsilon(1e-9));
    }
    CHECK(combined.imageMean().y > 0.0);  // the scene is lit: the comparison is not of zeros
}
