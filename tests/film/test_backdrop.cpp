// The backdrop (backdrop.h): what camera rays that miss every surface show, apart from the
// environment that lights the scene and that every other ray sees; and the coverage beside it.
#include <doctest/doctest.h>

#include <glm/common.hpp>

#include "film/accumulation_buffer.h"
#include "film/backdrop.h"
#include "integrator/progressive_renderer.h"
#include "scene/camera.h"
#include "scene/scene.h"
#include "render_support.h"
#include "test_support.h"

using namespace strata;

namespace {

using Kind = BackdropSetting::Kind;

// The cube [-1,1]^3 of albedo 0.4 (seen from outside: a convex diffuse object) under `environment`.
Scene greyCube(const Environment& environment = {}) {
    Material grey;
    grey.diffuse = glm::vec3(0.4f);
    MeshData mesh = test::furnaceMesh(grey);
    mesh.environment = environment;
    return Scene(std::move(mesh));
}

const Camera kCamera(CameraPose{{0.5f, 1.0f, 6.0f}, {0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, 40.0f}, 24, 24);

// Cosine sampling without next-event estimation reads a convex object under a uniform sky exactly.
AccumulationBuffer render(const Scene& scene, const BackdropSetting& backdrop) {
    RenderSettings settings{{2, SamplerKind::Cosine, false}, 5, 1};
    settings.backdrop = backdrop;
    return test::renderPasses(scene, kCamera, settings, 2);
}

}  // namespace

TEST_CASE("backdrop: --background's spelling") {
    CHECK(parseBackdrop("env") == BackdropSetting{Kind::Environment});
    CHECK(parseBackdrop("gradient") == BackdropSetting{Kind::Gradient});
    CHECK(parseBackdrop("0.25") == BackdropSetting{Kind::Colour, glm::vec3(0.25f)});
    CHECK(parseBackdrop("1,0.5,0") == BackdropSetting{Kind::Colour, glm::vec3(1.0f, 0.5f, 0.0f)});
    CHECK(parseBackdrop("2e3,0,0") == BackdropSetting{Kind::Colour, glm::vec3(2000.0f, 0.0f, 0.0f)});
    for (const char* bad : {"", "environment", "1,2", "1,2,3,4", "-1", "1,,2", "nan", "inf", "1e99", "0.5x",
                            " 1", "1,2,3,"}) {
        CAPTURE(bad);
        CHECK_FALSE(parseBackdrop(bad).has_value());
    }
}

TEST_CASE("backdrop: automatic is the gradient under the default sky, else the environment") {
    CHECK(Backdrop({}, true).showsEnvironment() == false);
    CHECK(Backdrop({}, false).showsEnvironment());
    CHECK(Backdrop({Kind::Environment}, true).showsEnvironment());
    CHECK_FALSE(Backdrop({Kind::Gradient}, false).showsEnvironment());
    const Backdrop gradient({}, true);
    CHECK(gradient.radiance(0.0f) == glm::vec3(Backdrop::kGradientTop));
    CHECK(gradient.radiance(1.0f) == glm::vec3(Backdrop::kGradientBottom));
    CHECK(gradient.radiance(0.5f).x == doctest::Approx(0.5f * (Backdrop::kGradientTop + Backdrop::kGradientBottom)));
    CHECK(Backdrop({Kind::Colour, glm::vec3(1, 2, 3)}, true).radiance(0.3f) == glm::vec3(1, 2, 3));
}

TEST_CASE("backdrop: under the default sky the object reads its albedo and the rest the grey gradient") {
    const Scene scene = greyCube();
    REQUIRE(scene.lights().litByDefault());
    const AccumulationBuffer buffer = render(scene, {});
    int object = 0, backdrop = 0;
    for (int y = 0; y < kCamera.height(); ++y) {
        for (int x = 0; x < kCamera.width(); ++x) {
            const size_t pixel = static_cast<size_t>(y) * kCamera.width() + x;
            const glm::dvec3 value = buffer.mean(pixel);
            if (buffer.coverage(pixel) == 1.0) {
                // Its bounces see the white sky, not the backdrop: exactly 0.4.
                CHECK(value.y == doctest::Approx(0.4).epsilon(1e-6));
                ++object;
            } else if (buffer.coverage(pixel) == 0.0) {
                // The gradient is linear in the image height: the pixel's mean lies within its row's.
                const float top = glm::mix(Backdrop::kGradientTop, Backdrop::kGradientBottom,
                                           static_cast<float>(y) / kCamera.height());
                const float bottom = glm::mix(Backdrop::kGradientTop, Backdrop::kGradientBottom,
                                              static_cast<float>(y + 1) / kCamera.height());
                CHECK(value.y <= top + 1e-6);
                CHECK(value.y >= bottom - 1e-6);
                CHECK(value.x == value.y);
                ++backdrop;
            }
        }
    }
    CHECK(object > 100);
    CHECK(backdrop > 100);
}

TEST_CASE("backdrop: a given environment, or --background env, is seen by camera rays as it is") {
    Environment sky;
    sky.kind = Environment::Kind::Uniform;
    sky.radiance = glm::vec3(1.0f);
    const Scene given = greyCube(sky);
    const Scene lit = greyCube();
    const AccumulationBuffer automatic = render(given, {});
    const AccumulationBuffer forced = render(lit, {Kind::Environment});
    const AccumulationBuffer coloured = render(given, {Kind::Colour, glm::vec3(0.0f, 0.5f, 2.0f)});
    int sky1 = 0;
    for (size_t pixel = 0; pixel < automatic.pixelCount(); ++pixel) {
        if (automatic.coverage(pixel) > 0.0) continue;
        CHECK(automatic.mean(pixel) == glm::dvec3(1.0));
        CHECK(forced.mean(pixel) == glm::dvec3(1.0));
        CHECK(coloured.mean(pixel) == glm::dvec3(0.0, 0.5, 2.0));
        ++sky1;
    }
    CHECK(sky1 > 100);
    // Where the camera sees the object, every choice renders the same image.
    for (size_t pixel = 0; pixel < automatic.pixelCount(); ++pixel) {
        if (automatic.coverage(pixel) < 1.0) continue;
        CHECK(automatic.mean(pixel) == forced.mean(pixel));
        CHECK(automatic.mean(pixel) == coloured.mean(pixel));
    }
}

TEST_CASE("backdrop: the coverage is the share of a pixel's camera rays that found a surface") {
    AccumulationBuffer buffer(2, 1);
    buffer.addSample(0, glm::vec3(1.0f), true);
    buffer.addSample(0, glm::vec3(1.0f), false);
    buffer.addSample(0, glm::vec3(1.0f), true);
    buffer.addSample(0, glm::vec3(NAN), true);  // dropped, and not counted
    CHECK(buffer.coverage(0) == doctest::Approx(2.0 / 3.0));
    CHECK(buffer.coverage(1) == 0.0);
    buffer.clear();
    CHECK(buffer.coverage(0) == 0.0);
    // A silhouette pixel of the rendered cube lies strictly between.
    const AccumulationBuffer rendered = render(greyCube(), {});
    bool partial = false;
    for (size_t pixel = 0; pixel < rendered.pixelCount(); ++pixel) {
        partial |= rendered.coverage(pixel) > 0.0 && rendered.coverage(pixel) < 1.0;
    }
    CHECK(partial);
}
