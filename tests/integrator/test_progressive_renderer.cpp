#include <doctest/doctest.h>

#include <vector>

#include "film/accumulation_buffer.h"
#include "util/error.h"
#include "integrator/progressive_renderer.h"
#include "scene/scene_loader.h"
#include "render_support.h"
#include "test_support.h"

using namespace strata;

namespace {
AccumulationBuffer render(const LoadedScene& loaded, const Camera& camera, SamplerKind sampler,
                          int threads, bool inSteps) {
    AccumulationBuffer buffer(camera.width(), camera.height());
    ProgressiveRenderer renderer(loaded.scene, camera, {{4, sampler, false}, 1234, threads});
    for (uint32_t pass = 0; pass < 2; ++pass) {
        if (inSteps) {
            for (int step = 0; step < kPathsPerPass; ++step) renderer.renderStep(buffer, pass, step);
        } else {
            renderer.renderPass(buffer, pass);
        }
    }
    CHECK(renderer.counters().paths == 2ull * kPathsPerPass * camera.width() * camera.height());
    return buffer;
}

}  // namespace

TEST_CASE("renderer: 1, 2 and 7 threads give bit-identical images") {
    const LoadedScene loaded = loadScene(test::cornellScene());
    const Camera camera(loaded.settings.pose, 40, 30);
    for (SamplerKind sampler : {SamplerKind::Uniform, SamplerKind::Strata24}) {
        const auto one = render(loaded, camera, sampler, 1, false);
        CHECK(test::differingPixels(one, render(loaded, camera, sampler, 2, false)) == 0);
        CHECK(test::differingPixels(one, render(loaded, camera, sampler, 7, false)) == 0);
    }
}

TEST_CASE("renderer: a pass in 24 steps equals the pass at once") {
    const LoadedScene loaded = loadScene(test::cornellScene());
    const Camera camera(loaded.settings.pose, 24, 24);
    CHECK(test::differingPixels(render(loaded, camera, SamplerKind::Strata24, 2, false),
                                render(loaded, camera, SamplerKind::Strata24, 2, true)) == 0);
}

TEST_CASE("renderer: a different seed gives a different image") {
    // The furnace: every path carries light, so every pixel's estimate depends on its samples.
    const LoadedScene loaded = loadScene(test::sourceDir() / "assets/furnace/furnace.obj");
    const Camera camera(loaded.settings.pose, 16, 16);
    AccumulationBuffer a(16, 16), b(16, 16);
    ProgressiveRenderer(loaded.scene, camera, {{3, SamplerKind::Strata24, false}, 1, 0}).renderPass(a, 0);
    ProgressiveRenderer(loaded.scene, camera, {{3, SamplerKind::Strata24, false}, 2, 0}).renderPass(b, 0);
    size_t differing = 0;
    for (size_t i = 0; i < a.pixelCount(); ++i) differing += a.mean(i) != b.mean(i) ? 1 : 0;
    CHECK(differing == a.pixelCount());
}

TEST_CASE("renderer: steps and passes leave the pixels of the skip mask alone") {
    const LoadedScene loaded = loadScene(test::sourceDir() / "assets/furnace/furnace.obj");
    const Camera camera(loaded.settings.pose, 8, 8);
    std::vector<uint8_t> skip(64, 0);
    for (size_t p = 0; p < skip.size(); p += 3) skip[p] = 1;
    AccumulationBuffer buffer(8, 8);
    ProgressiveRenderer renderer(loaded.scene, camera, {{2, SamplerKind::Strata24, false}, 5, 1});
    for (int step = 0; step < kPathsPerPass; ++step) renderer.renderStep(buffer, 0, step, {nullptr, &skip});
    renderer.renderPass(buffer, 1, &skip);
    for (size_t p = 0; p < skip.size(); ++p) {
        CAPTURE(p);
        CHECK(buffer.sampleCount(p) == (skip[p] ? 0u : 2u * kPathsPerPass));
        CHECK(buffer.completedPasses(p) == (skip[p] ? 0u : 2u));
    }
}

TEST_CASE("renderer: a step rendered in bands of rows equals the step at once") {
    const LoadedScene loaded = loadScene(test::cornellScene());
    const Camera camera(loaded.settings.pose, 20, 37);
    const RenderSettings settings{{3, SamplerKind::Strata24, false}, 77, 2};
    AccumulationBuffer whole(20, 37), banded(20, 37);
    ProgressiveRenderer a(loaded.scene, camera, settings), b(loaded.scene, camera, settings);
    for (int step = 0; step < kPathsPerPass; ++step) {
        a.renderStep(whole, 0, step);
        for (int row = 0; row < 37; row += 5) b.renderStep(banded, 0, step, {nullptr, nullptr, row, row + 5});
    }
    CHECK(test::differingPixels(whole, banded) == 0);
    CHECK(b.counters().paths == a.counters().paths);
}

TEST_CASE("renderer: a pass in groups of steps equals the pass step by step") {
    const LoadedScene loaded = loadScene(test::cornellScene());
    const Camera camera(loaded.settings.pose, 19, 13);
    const RenderSettings settings{{3, SamplerKind::Strata24, false}, 91, 2};
    AccumulationBuffer stepwise(19, 13), grouped(19, 13);
    ProgressiveRenderer a(loaded.scene, camera, settings), b(loaded.scene, camera, settings);
    for (int step = 0; step < kPathsPerPass; ++step) a.renderStep(stepwise, 0, step);
    // Uneven groups, as the viewer's worker chooses them from the time a step takes.
    const int groupEnds[] = {1, 6, 17, 24};
    int first = 0;
    for (int end : groupEnds) {
        CHECK(grouped.completedPasses(0) == 0u);  // the pass closes with its last step only
        b.renderSteps(grouped, 0, first, end);
        first = end;
    }
    CHECK(test::differingPixels(stepwise, grouped) == 0);
    CHECK(grouped.completedPasses(0) == 1u);
    CHECK_THROWS_AS(b.renderSteps(grouped, 1, 5, 5), Error);
    CHECK_THROWS_AS(b.renderSteps(grouped, 1, 20, 25), Error);
}
