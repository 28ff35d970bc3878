#include <doctest/doctest.h>

#include <cmath>

#include "film/adaptive_sampling.h"
#include "integrator/path_integrator.h"
#include "integrator/progressive_renderer.h"
#include "scene/scene_loader.h"
#include "test_support.h"

using namespace strata;

TEST_CASE("adaptive: pixels stop at the threshold, and converged pixels keep the exact mean") {
    // Furnace at depth 3: every pixel's exact value is 1.875.
    const LoadedScene loaded = loadScene(test::sourceDir() / "assets/furnace/furnace.obj");
    const Camera camera(loaded.settings.pose, 32, 32);
    for (SamplerKind sampler : {SamplerKind::Uniform, SamplerKind::Strata24}) {
        AccumulationBuffer buffer(32, 32);
        ProgressiveRenderer renderer(loaded.scene, camera, {{3, sampler, false}, 17, 0});
        constexpr double kThreshold = 0.01;
        AdaptiveSampling adaptive({kThreshold, 4}, buffer.pixelCount());
        uint32_t pass = 0;
        for (; pass < 400 && adaptive.activePixels() > 0; ++pass) {
            renderer.renderPass(buffer, pass, &adaptive.doneMask());
            adaptive.update(buffer);
        }
        INFO(samplerName(sampler) << ": " << pass << " passes, " << adaptive.activePixels() << " active");
        CHECK(adaptive.activePixels() == 0);
        double sum = 0.0;
        double variance = 0.0;
        uint32_t minPasses = ~0u, maxPasses = 0;
        for (size_t i = 0; i < buffer.pixelCount(); ++i) {
            CHECK(adaptive.doneMask()[i] == 1);
            CHECK(buffer.passStandardError(i) <= kThreshold * buffer.mean(i).x);
            sum += buffer.mean(i).x;
            variance += buffer.passStandardError(i) * buffer.passStandardError(i);
            minPasses = std::min(minPasses, buffer.completedPasses(i));
            maxPasses = std::max(maxPasses, buffer.completedPasses(i));
        }
        const double n = static_cast<double>(buffer.pixelCount());
        const double mean = sum / n;
        const double standardError = std::sqrt(variance) / n;
        MESSAGE(samplerName(sampler) << ": mean over converged pixels " << mean << " +- " << standardError
                                     << " (exact 1.875), passes per pixel " << minPasses << ".." << maxPasses);
        CHECK(std::abs(mean - 1.875) < 4.0 * standardError);
        CHECK(maxPasses > minPasses);  // the point: pixels stop at different times
    }
}

TEST_CASE("adaptive: off when the threshold is 0") {
    AccumulationBuffer buffer(4, 4);
    AdaptiveSampling adaptive({0.0}, buffer.pixelCount());
    CHECK_FALSE(adaptive.enabled());
    CHECK(adaptive.update(buffer) == 16);
}

TEST_CASE("early out: a scene without reachable light is recognised as black") {
    MeshData mesh;
    mesh.materials = {Material{"grey", glm::vec3(0.5f), glm::vec3(0.0f)}};
    test::addQuad(mesh, {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, 0);
    mesh.environment.kind = Environment::Kind::None;  // else the default white sky lights it
    const Scene dark(mesh);
    CHECK(whyBlack(dark, {3, SamplerKind::Strata24, true}).has_value());
    mesh.pointLights = {PointLight{{0.5f, 0.5f, 1.0f}, glm::vec3(1.0f)}};
    const Scene pointLit(mesh);
    CHECK(whyBlack(pointLit, {3, SamplerKind::Strata24, false}).has_value());
    CHECK(whyBlack(pointLit, {0, SamplerKind::Strata24, true}).has_value());
    CHECK_FALSE(whyBlack(pointLit, {1, SamplerKind::Strata24, true}).has_value());
    const LoadedScene lit = loadScene(test::cornellScene());
    CHECK_FALSE(whyBlack(lit.scene, {0, SamplerKind::Uniform, false}).has_value());
}
