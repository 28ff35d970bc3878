#include <doctest/doctest.h>

#include <cmath>
#include <fstream>
#include <memory>
#include <optional>
#include <random>
#include <vector>

#include "bench/reference_cache.h"
#include "test_support.h"

using namespace strata;

namespace {
const auto kFurnace = [] { return test::sourceDir() / "assets" / "furnace" / "furnace.obj"; };
PathIntegratorSettings depth(int k) {
    PathIntegratorSettings settings;
    settings.depth = k;
    return settings;
}
}  // namespace

TEST_CASE("reference cache: the furnace is analytic, with notes section 5.1's value") {
    const LoadedScene furnace = loadScene(kFurnace());
    const auto exact = furnaceRadiance(furnace.scene, furnace.settings.pose, depth(5));
    REQUIRE(exact);
    CHECK(exact->x == doctest::Approx(1.96875));  // Le = 1, rho = 0.5: (1 - 0.5^6) / 0.5
    CHECK(furnaceRadiance(furnace.scene, furnace.settings.pose, depth(0))->y == doctest::Approx(1.0));
    // Seen from outside, the furnace is not a furnace.
    CameraPose outside = furnace.settings.pose;
    outside.position = glm::vec3(0.0f, 0.0f, 5.0f);
    CHECK_FALSE(furnaceRadiance(furnace.scene, outside, depth(5)));

    const LoadedScene cornell = loadScene(test::cornellScene());
    CHECK_FALSE(furnaceRadiance(cornell.scene, cornell.settings.pose, depth(5)));
}

TEST_CASE("reference cache: a furnace with a hole is not analytic") {
    const LoadedScene furnace = loadScene(kFurnace());
    MeshData open = furnace.scene.mesh();
    open.triangles.pop_back();
    open.triangleMaterials.pop_back();
    const Scene scene(std::move(open));
    CHECK_FALSE(furnaceRadiance(scene, furnace.settings.pose, depth(5)));
}

TEST_CASE("reference cache: the key changes with the files, camera and depth, and only then") {
    const auto dir = test::scratchDir("reference-key");
    for (const char* name : {"cornell.obj", "cornell.mtl", "cornell.json"}) {
        std::filesystem::copy_file(test::sourceDir() / "assets" / "cornell" / name, dir / name);
    }
    const auto keyOf = [&](int k, int width) {
        const LoadedScene loaded = loadScene(dir / "cornell.obj");
        const Camera camera(loaded.settings.pose, width, 16);
        return referenceKey(loaded, camera, depth(k));
    };
    const uint64_t base = keyOf(5, 16);
    CHECK(keyOf(5, 16) == base);
    CHECK(keyOf(4, 16) != base);
    CHECK(keyOf(5, 17) != base);
    // A material library beside the scene that its OBJ does not name is not the scene's.
    std::ofstream(dir / "unused.mtl") << "newmtl other\nKd 0.1 0.1 0.1\n";
    CHECK(keyOf(5, 16) == base);
    std::ofstream(dir / "cornell.mtl", std::ios::app) << "\n# edited\n";
    CHECK(keyOf(5, 16) != base);

    const LoadedScene loaded = loadScene(dir / "cornell.obj");
    const Camera camera(loaded.settings.pose, 16, 16);
    const auto path = referencePath("refs", loaded, camera, depth(3));
    CHECK(path.parent_path() == "refs");
    CHECK(path.filename().string().rfind("cornell-d3-", 0) == 0);
    CHECK(path.extension() == ".exr");
    CHECK(sceneName("x/cornell_point/scene.obj") == "cornell_point");
}

TEST_CASE("reference cache: the key changes with the sky the scene is lit by") {
    const auto keyUnder = [](const Environment& sky) {
        LoadedScene loaded = loadScene(test::cornellScene());
        const uint64_t dark = referenceKey(loaded, Camera(loaded.settings.pose, 16, 16), depth(5));
        loaded.scene.setEnvironment(sky);
        return std::pair{dark, referenceKey(loaded, Camera(loaded.settings.pose, 16, 16), depth(5))};
    };
    Environment sky;
    sky.kind = Environment::Kind::None;
    const auto [dark, none] = keyUnder(sky);
    CHECK(none == dark);  // the box is dark outside as loaded
    sky.kind = Environment::Kind::Uniform;
    sky.radiance = glm::vec3(1.0f);
    const uint64_t white = keyUnder(sky).second;
    CHECK(white != dark);
    sky.radiance = glm::vec3(1.0f, 1.0f, 0.5f);
    CHECK(keyUnder(sky).second != white);
    sky.kind = Environment::Kind::Map;
    sky.map = std::make_shared<const EnvironmentMap>(Image{4, 2, std::vector<glm::vec3>(8, glm::vec3(1.0f))}, "map");
    const uint64_t map = keyUnder(sky).second;
    CHECK(map != dark);
    sky.rotationDegrees = 10.0f;
    CHECK(keyUnder(sky).second != map);
}

TEST_CASE("reference cache: one changed byte of an MTL file, the description or the camera file changes the key") {
    const auto dir = test::scratchDir("reference-key-byte");
    for (const char* name : {"cornell.obj", "cornell.mtl", "cornell.json"}) {
        std::filesystem::copy_file(test::sourceDir() / "assets" / "cornell" / name, dir / name);
    }
    std::filesystem::copy_file(dir / "cornell.json", dir / "camera.json");
    const auto keyOf = [&](const std::optional<std::filesystem::path>& cameraFile = std::nullopt) {
        const LoadedScene loaded = loadScene(dir / "cornell.obj", cameraFile);
        return referenceKey(loaded, Camera(loaded.settings.pose, 16, 16), depth(5));
    };
    // Overwrites one byte in place: the file keeps its size, so only its bytes tell it changed.
    const auto changeByte = [](const std::filesystem::path& path, size_t at, char byte) {
        std::fstream file(path, std::ios::in | std::ios::out | std::ios::binary);
        file.seekp(static_cast<std::streamoff>(at));
        file.put(byte);
    };
    const uint64_t base = keyOf();
    changeByte(dir / "cornell.mtl", 2, 'a');  // "# Albedos" -> "# albedos", a comment
    const uint64_t edited = keyOf();
    CHECK(edited != base);
    changeByte(dir / "cornell.json", 1, '\t');  // whitespace: the same camera
    CHECK(keyOf() != edited);

    // The camera file is keyed as a file of its own, beside the description.
    const uint64_t withCamera = keyOf(dir / "camera.json");
    CHECK(withCamera != keyOf());
    changeByte(dir / "camera.json", 1, '\t');
    CHECK(keyOf(dir / "camera.json") != withCamera);
}

namespace {

// An image of `pixels` grey pixels of radiance `truth` plus independent Gaussian noise of
// standard deviation `sigma` in every channel.
Image noisy(size_t pixels, float truth, float sigma, std::mt19937& random) {
    std::normal_distribution<float> noise(0.0f, sigma);
    Image image{static_cast<int>(pixels), 1, {}, {}};
    for (size_t i = 0; i < pixels; ++i) image.pixels.emplace_back(truth + noise(random), truth + noise(random), truth + noise(random));
    return image;
}

Image mean(const Image& a, const Image& b) {
    Image m = a;
    for (size_t i = 0; i < m.pixels.size(); ++i) m.pixels[i] = 0.5f * (a.pixels[i] + b.pixels[i]);
    return m;
}

}  // namespace

TEST_CASE("reference cache: a reference's own noise is estimated from its halves and taken out of the error") {
    // Halves of variance sh^2 make a reference of variance sh^2 / 2; an independent render of
    // variance sx^2 then measures sx^2 + sh^2 / 2 against it, of which measure() leaves sx^2.
    // n = 3 * 200000 squared Gaussians: each mean is within 4 standard errors, sqrt(2/n) relative.
    constexpr size_t kPixels = 200000;
    constexpr float kTruth = 0.5f, kHalfSigma = 0.02f, kRenderSigma = 0.01f;
    std::mt19937 random(7);
    const Image first = noisy(kPixels, kTruth, kHalfSigma, random);
    const Image second = noisy(kPixels, kTruth, kHalfSigma, random);
    const Reference reference = renderedReference(mean(first, second), first, "made");
    const double tolerance = 4.0 * std::sqrt(2.0 / (3.0 * kPixels));

    const double referenceVariance = kHalfSigma * kHalfSigma / 2.0;
    CHECK(reference.own.mse == doctest::Approx(referenceVariance).epsilon(tolerance));

    const Image render = noisy(kPixels, kTruth, kRenderSigma, random);
    const double renderVariance = kRenderSigma * kRenderSigma;
    const ImageError raw = imageError(render, reference.image);
    CHECK(raw.mse == doctest::Approx(renderVariance + referenceVariance).epsilon(tolerance));
    const ImageError corrected = measure(render, reference);
    // The difference of two estimates, each within the tolerance of its own value.
    CHECK(std::abs(corrected.mse - renderVariance) < tolerance * (raw.mse + reference.own.mse));
    CHECK(corrected.rmse == doctest::Approx(std::sqrt(corrected.mse)));
    CHECK(corrected.relMse == doctest::Approx(raw.relMse - reference.own.relMse));
}

TEST_CASE("reference cache: an analytic reference has no error of its own to take out") {
    const Reference exact{glm::vec3(0.5f), {}, "analytic", {}};
    const Image image{1, 1, {glm::vec3(0.6f)}, {}};
    CHECK(measure(image, exact).mse == doctest::Approx(0.01));
}
