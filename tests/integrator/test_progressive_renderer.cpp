#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
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

TEST_CASE("renderer: a thin lens blurs an emitter off its focal plane over its circle of confusion, keeping its light") {
    // A square emitter of radiance 1, 2 wide, at distance 10 from the camera, in the dark; depth
    // 0, so a path sees 1 or 0. Focused at 20, a lens of radius 0.5 moves the square's image on
    // the focal plane by the lens point's offset times 1 - 20/10: up to 0.5, which is 2.99
    // pixels at 64 pixels over 2 x 20 tan 15 degrees.
    MeshData mesh;
    mesh.materials = {{"lamp", glm::vec3(0.0f), glm::vec3(1.0f)}};
    mesh.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
    mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
    mesh.triangleMaterials = {0, 0};
    const Scene scene(mesh);
    CameraPose pose{{0, 0, 10}, {0, 0, 0}, {0, 1, 0}, 30.0f};
    const RenderSettings settings{{0, SamplerKind::Uniform, false}, 7, 2};
    const AccumulationBuffer pinhole = test::renderPasses(scene, Camera(pose, 64, 64), settings, 4);
    pose.apertureRadius = 0.5f;
    pose.focusDistance = 20.0f;
    const AccumulationBuffer lens = test::renderPasses(scene, Camera(pose, 64, 64), settings, 4);
    // The square's edges along the middle row, in pixel coordinates: 32 -+ 32 / (10 tan 15).
    const double halfWidth = 32.0 / (10.0 * std::tan(15.0 * M_PI / 180.0));
    const double blur = 0.5 * 32.0 / (20.0 * std::tan(15.0 * M_PI / 180.0));
    CHECK(blur == doctest::Approx(2.986).epsilon(1e-3));
    for (int x = 0; x < 64; ++x) {
        const double distance = std::min(std::abs(x + 0.5 - (32.0 - halfWidth)), std::abs(x + 0.5 - (32.0 + halfWidth)));
        const double sharp = pinhole.mean(32 * 64 + x).x;
        const double blurred = lens.mean(32 * 64 + x).x;
        CAPTURE(x);
        CAPTURE(distance);
        // Off the edges' pixels the pinhole sees all or nothing; off the circle of confusion the
        // lens too, and within 2 pixels of an edge it sees part of the square at every pixel.
        if (distance > 1.0) CHECK((sharp == 0.0 || sharp == 1.0));
        if (distance > blur + 0.75) CHECK((blurred == 0.0 || blurred == 1.0));
        if (distance < 2.0) CHECK((blurred > 0.0 && blurred < 1.0));
    }
    // Every lens point sees the square at the same size on the focal plane, so the image keeps
    // its light: the image means agree within the errors of the two renders.
    double difference = 0.0;
    double variance = 0.0;
    for (size_t i = 0; i < pinhole.pixelCount(); ++i) {
        difference += lens.mean(i).x - pinhole.mean(i).x;
        variance += std::pow(lens.passStandardError(i), 2) + std::pow(pinhole.passStandardError(i), 2);
    }
    CHECK(std::abs(difference) <= test::kSigmas * std::sqrt(variance));
    CHECK(variance > 0.0);
}
