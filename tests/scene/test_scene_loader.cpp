#include <doctest/doctest.h>

#include <fstream>
#include <glm/geometric.hpp>
#include <stb_image_write.h>

#include "film/accumulation_buffer.h"
#include "io/image_io.h"
#include "lights/environment.h"
#include "util/error.h"
#include "scene/scene_loader.h"
#include "render_support.h"
#include "test_support.h"

using namespace strata;

namespace {

// A unit quad light facing +y, its material library and a scene description with two lights.
void writeQuadScene(const std::filesystem::path& dir, const std::string& description) {
    std::ofstream(dir / "s.obj") << "mtllib s.mtl\nv 0 0 0\nv 1 0 0\nv 1 0 1\nv 0 0 1\nusemtl white\n"
                                    "f 1 3 2\nf 1 4 3\n";
    std::ofstream(dir / "s.mtl") << "newmtl white\nKd 0.5 0.5 0.5\nKe 1 1 1\n";
    if (!description.empty()) std::ofstream(dir / "s.json") << description;
}

const char* kPoseOverQuad = R"("position":[0.5,1,-1],"look_at":[0.5,0,0.5],"up":[0,1,0],"fov_y":60)";

}  // namespace

TEST_CASE("scene loader: files read once then parsed give the scene loadScene gives") {
    const auto obj = test::cornellScene();
    const SceneBundle files = readSceneBundle(obj);
    REQUIRE(files.files.size() == 2);
    CHECK(files.files[1].name == "cornell.mtl");
    REQUIRE(files.description);
    CHECK(files.description->name == "cornell.json");
    CHECK(!files.description->bytes.empty());
    // A copy of the bytes, as another MPI rank would receive them.
    const SceneBundle received = files;
    const LoadedScene parsed = parseScene(received);
    const LoadedScene loaded = loadScene(obj);
    CHECK(parsed.scene.summary().triangles == loaded.scene.summary().triangles);
    CHECK(parsed.scene.summary().emittingArea == loaded.scene.summary().emittingArea);
    CHECK(parsed.settings.width == loaded.settings.width);
    CHECK(parsed.settings.pose.lookAt == loaded.settings.pose.lookAt);
    CHECK(parsed.scenePath() == obj);
}

TEST_CASE("scene loader: a missing scene or camera file is named when reading") {
    const auto dir = test::scratchDir("scene-files");
    CHECK_THROWS_WITH_AS(readSceneBundle(dir / "absent.obj"),
                         doctest::Contains("absent.obj: no such scene file"), Error);
    CHECK_THROWS_WITH_AS(readSceneBundle(test::cornellScene(), dir / "absent.json"),
                         doctest::Contains("absent.json: cannot open camera file"), Error);
}

TEST_CASE("scene loader: the lights are the scene description's, with or without --camera") {
    const auto dir = test::scratchDir("scene-lights");
    writeQuadScene(dir, std::string("{") + kPoseOverQuad +
                            R"(,"lights":[{"type":"point","position":[0,1,0],"intensity":[1,1,1]}],)"
                            R"("point_lights":[{"position":[0,2,0],"intensity":[2,2,2]}]})");
    std::ofstream(dir / "cam.json")
        << R"({"position":[0.5,3,-2],"look_at":[0.5,0,0.5],"up":[0,1,0],"fov_y":30,"width":8,)"
           R"("lights":[{"type":"point","position":[9,9,9],"intensity":[9,9,9]}],)"
           R"("point_lights":[{"position":[0,3,0],"intensity":[3,3,3]}]})";

    const LoadedScene own = loadScene(dir / "s.obj");
    REQUIRE(own.scene.mesh().pointLights.size() == 2);
    CHECK(own.scene.mesh().pointLights[0].intensity == glm::vec3(1.0f));
    CHECK(own.scene.mesh().pointLights[1].intensity == glm::vec3(2.0f));
    CHECK(own.settings.pose.position == glm::vec3(0.5f, 1.0f, -1.0f));

    // The camera from cam.json; the lights still the scene's, plus cam.json's older point_lights.
    const LoadedScene viewed = loadScene(dir / "s.obj", dir / "cam.json");
    CHECK(viewed.settings.pose.position == glm::vec3(0.5f, 3.0f, -2.0f));
    CHECK(viewed.settings.width == 8);
    REQUIRE(viewed.scene.mesh().pointLights.size() == 3);
    CHECK(viewed.scene.mesh().pointLights[2].intensity == glm::vec3(3.0f));

    // --camera naming the description itself counts its lights once.
    const LoadedScene same = loadScene(dir / "s.obj", dir / "s.json");
    CHECK_FALSE(same.bundle.camera);
    CHECK(same.scene.mesh().pointLights.size() == 2);
    CHECK(same.settings.pose.position == own.settings.pose.position);
}

TEST_CASE("scene loader: a description without the camera keys takes the default camera, and --camera needs them") {
    const auto dir = test::scratchDir("scene-framed");
    writeQuadScene(dir, R"({"width":12,"lights":[{"type":"point","position":[0,1,0],"intensity":[1,1,1]}]})");
    const LoadedScene framed = loadScene(dir / "s.obj");
    CHECK(framed.settings.width == 12);
    CHECK(framed.settings.height == 256);
    CHECK(framed.settings.pose.lookAt == glm::vec3(0.5f, 0.0f, 0.5f));  // the bounds' centre
    // The flat quad seen head-on from its face side, +y, with the model's back (-z) up.
    CHECK(framed.settings.pose.position.x == doctest::Approx(0.5f));
    CHECK(framed.settings.pose.position.z == doctest::Approx(0.5f));
    CHECK(framed.settings.pose.position.y > 1.0f);
    CHECK(framed.settings.pose.up.z == doctest::Approx(-1.0f));
    CHECK(framed.scene.mesh().pointLights.size() == 1);
    CHECK_THROWS_WITH_AS(loadScene(dir / "s.obj", dir / "s.json"),
                         ((dir / "s.json").string() + ": missing key \"position\"").c_str(), Error);
}

TEST_CASE("scene loader: an unknown light type in the description is named when reading") {
    const auto dir = test::scratchDir("scene-unknown-light");
    writeQuadScene(dir, R"({"lights":[{"type":"area","position":[0,1,0]}]})");
    CHECK_THROWS_WITH_AS(readSceneBundle(dir / "s.obj"),
                         ((dir / "s.json").string() + ": unknown light type 'area' (known: point, spot)").c_str(),
                         Error);
}

TEST_CASE("scene loader: every bundled and test scene loads, with the point lights of its description") {
    for (const char* scene : {"assets/cornell/cornell.obj", "assets/furnace/furnace.obj", "assets/glossy/glossy.obj"}) {
        CAPTURE(scene);
        const LoadedScene loaded = loadScene(test::sourceDir() / scene);
        CHECK(loaded.bundle.description);
        CHECK(loaded.scene.summary().triangles > 0);
        CHECK(loaded.scene.mesh().pointLights.empty());
    }
    // The point-lit box: no emitter, one point light from its description's "lights".
    const LoadedScene point = loadScene(test::testScene("cornell_point"));
    CHECK(point.scene.summary().emitters == 0);
    REQUIRE(point.scene.mesh().pointLights.size() == 1);
    CHECK(point.scene.mesh().pointLights[0].position == glm::vec3(278.0f, 540.0f, 279.6f));
    CHECK(point.scene.mesh().pointLights[0].intensity == glm::vec3(221000.0f, 156000.0f, 52000.0f));
}

TEST_CASE("scene loader: every scene of the optional shared collection loads") {
    const auto shared = test::sharedDir();
    if (!shared) {
        MESSAGE("skipped: no shared collection beside the checkout (../shared, an optional extra)");
        return;
    }
    size_t scenes = 0;
    for (const auto& entry : std::filesystem::directory_iterator(*shared / "scenes")) {
        const auto obj = entry.path() / "scene.obj";
        if (!std::filesystem::is_regular_file(obj)) continue;
        CAPTURE(obj);
        CHECK(loadScene(obj).bundle.description);
        ++scenes;
    }
    CHECK(scenes >= 1);
}

namespace {

// A grey quad that emits nothing, seen from above with sky around it, and a 2:1 map brighter
// towards +x; the description is s.json.
void writeSkyScene(const std::filesystem::path& dir, const std::string& description) {
    std::ofstream(dir / "s.obj") << "mtllib s.mtl\nv 0 0 0\nv 1 0 0\nv 1 0 1\nv 0 0 1\nusemtl grey\n"
                                    "f 1 3 2\nf 1 4 3\n";
    std::ofstream(dir / "s.mtl") << "newmtl grey\nKd 0.5 0.5 0.5\n";
    std::ofstream(dir / "s.json") << std::string("{") + kPoseOverQuad + R"(,"width":8,"height":8)" + description + "}";
    Image sky{8, 4, std::vector<glm::vec3>(32)};
    for (int i = 0; i < 32; ++i) sky.pixels[i] = glm::vec3(0.25f * (i % 8), 0.5f, 1.0f);
    std::filesystem::create_directories(dir / "maps");
    writeImage(dir / "maps/sky.exr", sky);
}

double renderedMean(const LoadedScene& loaded) {
    const AccumulationBuffer buffer = test::renderPasses(
        loaded.scene, Camera(loaded.settings.pose, loaded.settings.width, loaded.settings.height),
        {{2, SamplerKind::Cosine, false}, 5, 1}, 2);
    double sum = 0.0;
    for (size_t i = 0; i < buffer.pixelCount(); ++i) sum += buffer.mean(i).x;
    return sum / static_cast<double>(buffer.pixelCount());
}

}  // namespace

TEST_CASE("scene loader: a description's environment map travels in the bundle and lights like --env") {
    const auto dir = test::scratchDir("scene-environment");
    writeSkyScene(dir, R"(,"environment":{"file":"maps/sky.exr","rotate":30})");
    SceneBundle bundle = readSceneBundle(dir / "s.obj");
    REQUIRE(bundle.find("maps/sky.exr"));
    CHECK(bundle.find("maps/sky.exr")->bytes == test::fileBytes(dir / "maps/sky.exr"));
    // Parsed from the bundle alone, as another MPI rank would: the file on disk is gone.
    std::filesystem::remove(dir / "maps/sky.exr");
    const LoadedScene described = parseScene(bundle);
    CHECK(!described.scene.lights().litByDefault());

    writeSkyScene(dir, "");
    LoadedScene given = loadScene(dir / "s.obj");
    const double defaultSky = renderedMean(given);
    Environment environment;
    environment.kind = Environment::Kind::Map;
    environment.map = readEnvironmentMap(dir / "maps/sky.exr").map;
    environment.rotationDegrees = 30.0f;
    given.scene.setEnvironment(environment);
    CHECK(described.scene.lights().size() == given.scene.lights().size());
    CHECK(described.scene.lights().maxRadianceAtInfinity() == given.scene.lights().maxRadianceAtInfinity());
    const double mean = renderedMean(described);
    CHECK(mean == renderedMean(given));
    CHECK(mean != defaultSky);
}

TEST_CASE("scene loader: the description's environment map counts with the textures against the budget") {
    const auto dir = test::scratchDir("scene-environment-budget");
    writeSkyScene(dir, R"(,"environment":{"file":"maps/sky.exr"})");
    std::ofstream(dir / "s.mtl") << "newmtl grey\nKd 0.5 0.5 0.5\nmap_Kd t.png\n";
    const std::vector<unsigned char> texels(8 * 8 * 3, 100);
    REQUIRE(stbi_write_png((dir / "t.png").string().c_str(), 8, 8, 3, texels.data(), 8 * 3));
    const SceneBundle bundle = readSceneBundle(dir / "s.obj");
    // The texture: 8 x 8 x 3 bytes; the map: 8 x 4 x 3 floats.
    const LoadedScene loaded = parseScene(bundle, Traversal::Automatic, SceneBudget{.textureBytes = 192 + 384});
    CHECK(loaded.report.textureBytes == 192);
    CHECK_THROWS_WITH_AS(parseScene(bundle, Traversal::Automatic, SceneBudget{.textureBytes = 192 + 383}),
                         doctest::Contains("sky.exr: the environment map is 8 x 4, 3 channels of 32 bits (384 bytes); "
                                           "with it the scene's textures would take 576 bytes, over the --texture-budget of 575 bytes"),
                         Error);
    CHECK_THROWS_WITH_AS(parseScene(bundle, Traversal::Automatic, SceneBudget{.textureBytes = 191}),
                         doctest::Contains("s.mtl:3: map_Kd: texture 't.png' is 8 x 8, 3 channels of 8 bits"), Error);
    // Texels decoded before the scene's files (an --env map) take their share first.
    const SceneBudget shared{.textureBytes = 192 + 384 + 10, .textureBytesSpent = 10};
    CHECK(parseScene(bundle, Traversal::Automatic, shared).report.textureBytes == 192);
    CHECK_THROWS_WITH_AS(parseScene(bundle, Traversal::Automatic, SceneBudget{.textureBytes = 586, .textureBytesSpent = 11}),
                         doctest::Contains("the scene's textures would take 587 bytes, over the --texture-budget of 586 bytes"),
                         Error);
}

TEST_CASE("scene loader: a description's environment file that is missing or not a map is named") {
    const auto dir = test::scratchDir("scene-environment-bad");
    writeSkyScene(dir, R"(,"environment":{"file":"absent.exr"})");
    CHECK_THROWS_WITH_AS(readSceneBundle(dir / "s.obj"),
                         doctest::Contains("s.json: \"environment\" file 'absent.exr': no such file"), Error);
    writeSkyScene(dir, R"(,"environment":{"file":"s.mtl"})");
    CHECK_THROWS_WITH_AS(loadScene(dir / "s.obj"), doctest::Contains("s.mtl: not a readable EXR file"), Error);
    writeImage(dir / "square.exr", Image{4, 4, std::vector<glm::vec3>(16, glm::vec3(1.0f))});
    writeSkyScene(dir, R"(,"environment":{"file":"square.exr"})");
    CHECK_THROWS_WITH_AS(loadScene(dir / "s.obj"),
                         doctest::Contains("square.exr: an environment map must be a latitude-longitude image"),
                         Error);
}

TEST_CASE("scene loader: parseScene names its stages as they begin, and one that throws ends it there") {
    const SceneBundle bundle = readSceneBundle(test::cornellScene());
    std::vector<ParseStage> stages;
    const LoadedScene loaded =
        parseScene(bundle, Traversal::Automatic, {}, [&](ParseStage stage) { stages.push_back(stage); });
    CHECK(stages == std::vector<ParseStage>{ParseStage::Parsing, ParseStage::Building});
    CHECK(loaded.scene.summary().triangles == 32);

    struct Stop {};
    stages.clear();
    CHECK_THROWS_AS(parseScene(bundle, Traversal::Automatic, {},
                               [&](ParseStage stage) {
                                   stages.push_back(stage);
                                   if (stage == ParseStage::Building) throw Stop{};
                               }),
                    Stop);
    CHECK(stages == std::vector<ParseStage>{ParseStage::Parsing, ParseStage::Building});
}
