// RenderSession: its budgets stop where they say, a cancel stops it within the pass in flight,
// and however a render is cut (whole passes, steps, groups of steps, bands, pass ranges) its
// samples are the renderer's for the same (seed, pixel, pass, step).
#include <doctest/doctest.h>

#include <atomic>
#include <chrono>
#include <thread>
#include <vector>

#include "film/accumulation_buffer.h"
#include "integrator/render_session.h"
#include "scene/scene_loader.h"
#include "render_support.h"
#include "test_support.h"
#include "util/error.h"

using namespace strata;

namespace {

const LoadedScene& loadedCornell() {
    static const LoadedScene loaded = loadScene(test::cornellScene());
    return loaded;
}

RenderSettings strata24(int depth, uint64_t seed, int threads) {
    RenderSettings settings;
    settings.integrator.depth = depth;
    settings.integrator.sampler = SamplerKind::Strata24;
    settings.seed = seed;
    settings.threads = threads;
    return settings;
}

// Every statistic the buffer keeps, bit for bit.
}  // namespace

TEST_CASE("render session: a budget in spp stops exactly, inside a pass too") {
    const Camera camera(loadedCornell().settings.pose, 9, 7);
    RenderSession session(loadedCornell().scene, camera, strata24(3, 11, 2));
    session.run({2 * kPathsPerPass + 5});
    CHECK(session.spp() == 2 * kPathsPerPass + 5);
    CHECK(session.completedPasses() == 2);
    CHECK(session.step() == 5);
    CHECK(session.counters().paths == uint64_t{2 * kPathsPerPass + 5} * 9 * 7);
    for (size_t p = 0; p < session.buffer().pixelCount(); ++p) {
        CHECK(session.buffer().sampleCount(p) == 2u * kPathsPerPass + 5u);
        CHECK(session.buffer().completedPasses(p) == 2u);
    }
    CHECK(session.finished({2 * kPathsPerPass + 5}));
    session.run({2 * kPathsPerPass + 5});  // already met: renders nothing
    CHECK(session.spp() == 2 * kPathsPerPass + 5);
    session.run({4 * kPathsPerPass});  // the rest of pass 2, then pass 3
    CHECK(session.completedPasses() == 4);
    CHECK(session.step() == 0);
    CHECK(session.counters().paths == uint64_t{4 * kPathsPerPass} * 9 * 7);
}

TEST_CASE("render session: a budget in seconds stops after the pass that reaches it") {
    const Camera camera(loadedCornell().settings.pose, 16, 16);
    RenderSession session(loadedCornell().scene, camera, strata24(2, 3, 1));
    constexpr double kBudget = 0.05;
    std::vector<double> secondsAtPass;
    session.run({0, kBudget}, [&](const PassReport&) { secondsAtPass.push_back(session.renderSeconds()); });
    REQUIRE(!secondsAtPass.empty());
    CHECK(secondsAtPass.back() >= kBudget);
    for (size_t i = 0; i + 1 < secondsAtPass.size(); ++i) CHECK(secondsAtPass[i] < kBudget);
    CHECK(session.completedPasses() == secondsAtPass.size());
    CHECK(session.step() == 0);
    CHECK(session.finished({0, kBudget}));
}

TEST_CASE("render session: a noise budget stops at the pass that finishes the last pixel") {
    // The furnace: every pixel sees the same radiance with a moderate spread, so at 10% relative
    // error every pixel is done within a few passes after the minimum of 4.
    const LoadedScene furnace = loadScene(test::sourceDir() / "assets/furnace/furnace.obj");
    const Camera camera(furnace.settings.pose, 8, 6);
    RenderSettings settings = strata24(3, 5, 2);
    settings.adaptive.threshold = 0.1;
    RenderSession session(furnace.scene, camera, settings, {0, 200});
    std::vector<size_t> activeAtPass;
    session.run({}, [&](const PassReport&) { activeAtPass.push_back(session.adaptive().activePixels()); });
    REQUIRE(!activeAtPass.empty());
    CHECK(session.converged());
    CHECK(activeAtPass.back() == 0);
    for (size_t i = 0; i + 1 < activeAtPass.size(); ++i) CHECK(activeAtPass[i] > 0);
    CHECK(session.completedPasses() >= settings.adaptive.minPasses);
    CHECK(session.completedPasses() < 200);
    const AccumulationBuffer& buffer = session.buffer();
    for (size_t p = 0; p < buffer.pixelCount(); ++p) {
        CHECK(buffer.passStandardError(p) <= 0.1 * luminance(buffer.mean(p)));
    }
    // Done: more running renders nothing.
    const uint64_t paths = session.counters().paths;
    session.run({});
    CHECK(session.counters().paths == paths);
}

TEST_CASE("render session: a buffer without error estimates renders the same image, unless adaptive sampling needs them") {
    const LoadedScene& cornell = loadedCornell();
    const Camera camera(cornell.settings.pose, 6, 4);
    RenderSettings settings = strata24(3, 11, 2);
    RenderSession kept(cornell.scene, camera, settings, {0, 2});
    settings.pixelErrors = PixelErrors::NotKept;
    RenderSession bare(cornell.scene, camera, settings, {0, 2});
    kept.run({});
    bare.run({});
    CHECK(kept.buffer().keepsErrors());
    CHECK(!bare.buffer().keepsErrors());
    CHECK(bare.buffer().meanImage().pixels == kept.buffer().meanImage().pixels);
    settings.adaptive.threshold = 0.5;
    const RenderSession adaptive(cornell.scene, camera, settings, {0, 2});
    CHECK(adaptive.buffer().keepsErrors());
}

TEST_CASE("render session: a cancel from the progress callback stops before the next pass") {
    const Camera camera(loadedCornell().settings.pose, 12, 12);
    RenderSession session(loadedCornell().scene, camera, strata24(2, 1, 2));
    std::atomic<bool> cancel{false};
    session.run({}, [&](const PassReport& report) { cancel = report.passes == 3; }, &cancel);
    CHECK(session.completedPasses() == 3);
    CHECK(session.step() == 0);
    CHECK(session.counters().paths == uint64_t{3 * kPathsPerPass} * 12 * 12);
    // A cancelled session's steps report it.
    CHECK_FALSE(session.renderSteps(1, 1, &cancel));
}

TEST_CASE("render session threads: a cancel from another thread stops the pass in flight") {
    // One thread renders the 16x16 tiles one at a time; a cancel lets the tile in flight finish
    // and skips the rest, so at most one tile's paths follow it, wherever in a pass it comes.
    constexpr int kSize = 256;
    constexpr uint64_t kTilePaths = 16 * 16 * kPathsPerPass;
    const Camera camera(loadedCornell().settings.pose, kSize, kSize);
    RenderSession session(loadedCornell().scene, camera, strata24(5, 2, 1));
    std::atomic<bool> cancel{false};
    uint64_t pathsAtCancel = 0;
    std::thread canceller([&] {
        while (session.counters().paths == 0) std::this_thread::sleep_for(std::chrono::milliseconds(1));
        cancel = true;
        pathsAtCancel = session.counters().paths;
    });
    session.run({}, {}, &cancel);  // no budget: only the cancel ends it
    canceller.join();
    const uint64_t paths = session.counters().paths;
    CHECK(paths - pathsAtCancel <= kTilePaths);
    // The pass it stopped in is not counted as done.
    CHECK(session.step() == 0);
    CHECK(uint64_t{session.completedPasses()} * kPathsPerPass * kSize * kSize <= paths);
}

TEST_CASE("render session: the progress callback reports every pass, its index and its paths") {
    const Camera camera(loadedCornell().settings.pose, 10, 4);
    RenderSession session(loadedCornell().scene, camera, strata24(2, 9, 2), {3, 9});
    session.renderSteps(5);  // a pass begun in steps is reported whole when run completes it
    std::vector<PassReport> reports;
    session.run({5 * kPathsPerPass}, [&](const PassReport& report) { reports.push_back(report); });
    REQUIRE(reports.size() == 5);
    for (uint32_t i = 0; i < reports.size(); ++i) {
        CAPTURE(i);
        CHECK(reports[i].pass == 3 + i);
        CHECK(reports[i].passes == i + 1);
        CHECK(reports[i].paths == uint64_t{kPathsPerPass} * 10 * 4);
    }
    // The range ends at pass 9: one more pass, whatever the budget.
    session.run({}, [&](const PassReport& report) { reports.push_back(report); });
    REQUIRE(reports.size() == 6);
    CHECK(reports.back().pass == 8);
    CHECK(session.finished({}));
    CHECK_THROWS_AS(session.renderSteps(1), Error);
}

TEST_CASE("render session: a pass range renders exactly those passes, and two ranges add up to the whole") {
    const Camera camera(loadedCornell().settings.pose, 13, 11);
    const RenderSettings settings = strata24(3, 21, 2);
    RenderSession first(loadedCornell().scene, camera, settings, {0, 3});
    RenderSession second(loadedCornell().scene, camera, settings, {3, 7});
    RenderSession whole(loadedCornell().scene, camera, settings, {0, 7});
    for (RenderSession* session : {&first, &second, &whole}) session->run({});
    CHECK(first.completedPasses() == 3);
    CHECK(second.completedPasses() == 4);

    // The second range holds passes 3..6 exactly, as the renderer renders them.
    AccumulationBuffer passes(13, 11);
    ProgressiveRenderer renderer(loadedCornell().scene, camera, settings);
    for (uint32_t pass = 3; pass < 7; ++pass) renderer.renderPass(passes, pass);
    CHECK(test::differingPixels(second.buffer(), passes) == 0);

    // Added as the MPI ranks' buffers are (render_job.cpp): the counts exactly, the sums up to the
    // order of the additions, which no two orders can make bit-identical in general (a few ulps:
    // render_job.cpp's bound is 2 gamma_{n-1}, 3.7e-14 at n = 168).
    AccumulationBuffer& sum = first.buffer();
    const auto reals = sum.realArrays();
    const auto moreReals = second.buffer().realArrays();
    for (size_t a = 0; a < reals.size(); ++a) {
        for (size_t i = 0; i < reals[a].size(); ++i) reals[a][i] += moreReals[a][i];
    }
    const auto counts = sum.countArrays();
    const auto moreCounts = second.buffer().countArrays();
    for (size_t a = 0; a < counts.size(); ++a) {
        for (size_t i = 0; i < counts[a].size(); ++i) counts[a][i] += moreCounts[a][i];
    }
    const AccumulationBuffer& expected = whole.buffer();
    for (size_t p = 0; p < sum.pixelCount(); ++p) {
        CAPTURE(p);
        CHECK(sum.sampleCount(p) == expected.sampleCount(p));
        CHECK(sum.completedPasses(p) == expected.completedPasses(p));
        for (int c = 0; c < 3; ++c) {
            CHECK(std::abs(sum.mean(p)[c] - expected.mean(p)[c]) <= 1e-13 * std::abs(expected.mean(p)[c]));
        }
    }
}

TEST_CASE("render session: whole passes, steps, groups of steps and bands give bit-identical buffers") {
    // Adaptive sampling on, so that the mask (which changes between passes only) is cut the same way.
    const Camera camera(loadedCornell().settings.pose, 21, 17);
    RenderSettings settings = strata24(3, 77, 2);
    settings.adaptive.threshold = 0.3;
    settings.adaptive.minPasses = 2;
    const RenderBudget budget{6 * kPathsPerPass};
    RenderSession whole(loadedCornell().scene, camera, settings);
    whole.run(budget);
    RenderSession stepwise(loadedCornell().scene, camera, settings);
    while (!stepwise.finished(budget)) stepwise.renderSteps(1);
    // Uneven groups in uneven bands, as the viewer's worker cuts them.
    RenderSession grouped(loadedCornell().scene, camera, settings);
    const int groups[] = {1, 5, 11, 7};
    int bandsUsed = 0;
    for (size_t i = 0; !grouped.finished(budget); ++i) {
        const int bands = 1 + static_cast<int>(i % 4);
        int betweenBands = 0;
        grouped.renderSteps(groups[i % 4], bands, nullptr, [&] { ++betweenBands; });
        CHECK(betweenBands == bands - 1);
        bandsUsed += bands;
    }
    CHECK(bandsUsed > 24);
    REQUIRE(whole.completedPasses() == 6);
    CHECK(whole.adaptive().activePixels() < whole.buffer().pixelCount());  // the mask did skip pixels
    for (const RenderSession* session : {&stepwise, &grouped}) {
        CHECK(session->completedPasses() == 6);
        CHECK(session->counters().paths == whole.counters().paths);
        CHECK(session->adaptive().doneMask() == whole.adaptive().doneMask());
        CHECK(test::differingPixels(session->buffer(), whole.buffer()) == 0);
    }
}
