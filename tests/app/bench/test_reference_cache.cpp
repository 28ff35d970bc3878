#include <doctest/doctest.h>

#include <fstream>
#include <memory>
#include <optional>
#include <vector>

#include "bench/reference_cache.h"
#include "test_support.h"

using namespace strata;

namespace {
const auto kFurnace = [] { return test::sourceDir() / "assets" / "furnace" / "furnace.obj"; };
const auto kCornell = [] { return test::sourceDir() / "assets" / "cornell" / "cornell.obj"; };

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

    const LoadedScene cornell = loadScene(kCornell());
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
        LoadedScene loaded = loadScene(test::sourceDir() / "assets" / "cornell" / "cornell.obj");
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
