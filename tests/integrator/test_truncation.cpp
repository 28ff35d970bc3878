#include <doctest/doctest.h>

#include <cmath>
#include <fstream>
#include <string>

#include "util/error.h"
#include "integrator/progressive_renderer.h"
#include "scene/scene_loader.h"
#include "test_support.h"
#include "integrator/truncation.h"

using namespace strata;

TEST_CASE("truncation: K_eps matches the notes' table (section 5.5, absolute epsilon, Le_max = 1)") {
    struct Row {
        double albedo;
        int depths[3];  // epsilon = 1e-2, 1e-3, 1e-4
    };
    for (const Row& row : {Row{0.5, {7, 10, 14}}, Row{0.8, {27, 38, 48}}, Row{0.9, {65, 87, 109}},
                           Row{0.95, {148, 193, 237}}}) {
        const double epsilons[] = {1e-2, 1e-3, 1e-4};
        for (int i = 0; i < 3; ++i) {
            const auto choice = chooseTruncationDepth(epsilons[i], row.albedo, 1.0);
            REQUIRE(choice.has_value());
            CHECK(choice->depth == row.depths[i]);
            CHECK(choice->bound <= epsilons[i]);
            // Minimal: one bounce fewer would exceed epsilon.
            CHECK(truncationBound(choice->depth - 1, row.albedo, 1.0) > epsilons[i]);
        }
    }
}

TEST_CASE("truncation: albedo >= 1 has no finite depth, and no light or no reflection needs none") {
    CHECK_FALSE(chooseTruncationDepth(1e-3, 1.0, 1.0).has_value());
    CHECK(chooseTruncationDepth(1e-3, 0.0, 5.0)->depth == 0);
    CHECK(chooseTruncationDepth(1e-3, 0.7, 0.0)->depth == 0);
    CHECK_THROWS_AS(chooseTruncationDepth(0.0, 0.5, 1.0), Error);
}

TEST_CASE("truncation: on the furnace the bound is the exact error of the truncated series") {
    // L_inf - L_K = Le rho^(K+1) / (1 - rho): render at K_eps and compare with 2 - bound.
    const LoadedScene loaded = loadScene(test::sourceDir() / "assets/furnace/furnace.obj");
    const SceneSummary& summary = loaded.scene.summary();
    const auto choice = chooseTruncationDepth(0.05, summary.maxAlbedo, summary.maxEmission);
    REQUIRE(choice.has_value());
    CHECK(choice->depth == 5);  // 0.5^6 / 0.5 = 0.03125 <= 0.05 < 0.0625
    const Camera camera(loaded.settings.pose, 16, 16);
    AccumulationBuffer buffer(16, 16);
    ProgressiveRenderer renderer(loaded.scene, camera, {{choice->depth, SamplerKind::Strata24, false}, 3, 0});
    for (uint32_t pass = 0; pass < 8; ++pass) renderer.renderPass(buffer, pass);
    std::vector<double> means;
    for (size_t i = 0; i < buffer.pixelCount(); ++i) means.push_back(buffer.mean(i).x);
    const auto estimate = test::estimateMean(means);
    const double infinite = summary.maxEmission / (1.0 - summary.maxAlbedo);
    CHECK(std::abs(estimate.mean - (infinite - choice->bound)) < 4.0 * estimate.standardError);
}

TEST_CASE("truncation: a scene's K_eps comes from its summary, or an error says why there is none") {
    const LoadedScene furnace = loadScene(test::sourceDir() / "assets/furnace/furnace.obj");
    CHECK(chooseSceneTruncationDepth(1e-3, furnace.scene).depth == 10);  // 0.5^K <= 1e-3
    const LoadedScene pointLit = loadScene(test::testScene("cornell_point"));
    CHECK_THROWS_WITH_AS(chooseSceneTruncationDepth(1e-3, pointLit.scene), "point, spot and directional lights have no radiance bound",
                         Error);
    const auto dir = test::scratchDir("truncation-white");
    std::ofstream(dir / "white.mtl") << "newmtl white\nKd 1 1 1\nKe 1 1 1\n";
    std::ofstream(dir / "white.obj") << "mtllib white.mtl\nusemtl white\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    const LoadedScene white = loadScene(dir / "white.obj");
    try {
        chooseSceneTruncationDepth(1e-3, white.scene);
        FAIL("a white scene has no finite K_eps");
    } catch (const Error& e) {
        CHECK(std::string(e.what()).find("largest albedo is 1 >= 1") != std::string::npos);
    }
}
