#include <doctest/doctest.h>

#include <fstream>
#include <glm/geometric.hpp>

#include "scene/camera.h"
#include "util/error.h"
#include "test_support.h"

using namespace strata;

TEST_CASE("camera: the centre ray looks at look_at and corners span fov_y") {
    const CameraPose pose{{1, 2, 3}, {1, 2, 13}, {0, 1, 0}, 90.0f};
    const Camera camera(pose, 100, 100);
    const Ray centre = camera.generateRay(50, 50, {0.0f, 0.0f});
    CHECK(centre.direction.z == doctest::Approx(1.0));
    const Ray top = camera.generateRay(50, 0, {0.0f, 0.0f});
    // fov 90: the top edge is 45 degrees up.
    CHECK(std::acos(glm::dot(top.direction, glm::vec3(0, 0, 1))) == doctest::Approx(M_PI / 4).epsilon(1e-5));
    CHECK(top.direction.y > 0.0f);
}

TEST_CASE("camera: degenerate poses are refused") {
    CHECK_THROWS_AS(Camera(CameraPose{{0, 0, 0}, {0, 0, 0}, {0, 1, 0}, 45.0f}, 8, 8), Error);
    CHECK_THROWS_AS(Camera(CameraPose{{0, 0, 0}, {0, 1, 0}, {0, 1, 0}, 45.0f}, 8, 8), Error);
    CHECK_THROWS_AS(Camera(CameraPose{{0, 0, 0}, {0, 0, 1}, {0, 1, 0}, 180.0f}, 8, 8), Error);
    CHECK_THROWS_AS(Camera(CameraPose{{0, 0, 0}, {0, 0, 1}, {0, 1, 0}, 45.0f}, 0, 8), Error);
}

TEST_CASE("camera: JSON sidecar is read, and bad files name the file and the problem") {
    const auto dir = test::scratchDir("camera-json");
    auto write = [&](const std::string& name, const std::string& text) {
        std::ofstream(dir / name) << text;
        return dir / name;
    };
    const auto good = write("good.json",
                            R"({"position":[0,0,0],"look_at":[0,0,1],"up":[0,1,0],"fov_y":40,)"
                            R"("width":32,"height":16,"extra":"ignored",)"
                            R"("point_lights":[{"position":[1,2,3],"intensity":[4,5,6]}]})");
    const SceneSettings settings = loadSceneSettings(good);
    CHECK(settings.width == 32);
    CHECK(settings.height == 16);
    REQUIRE(settings.pointLights.size() == 1);
    CHECK(settings.pointLights[0].intensity.z == 6.0f);

    auto messageOf = [](const std::filesystem::path& p) {
        try {
            loadSceneSettings(p);
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    const std::string syntax = messageOf(write("syntax.json", "{\n\"position\": [0,0,\n}"));
    CHECK(syntax.find("syntax.json") != std::string::npos);
    CHECK(syntax.find("line 3") != std::string::npos);
    CHECK(messageOf(write("missing.json", R"({"position":[0,0,0]})")).find("look_at") != std::string::npos);
    CHECK(messageOf(write("type.json", R"({"position":[0,0,"x"],"look_at":[0,0,1],"up":[0,1,0],"fov_y":40})"))
              .find("\"position\" must be an array of 3 numbers") != std::string::npos);
    CHECK(messageOf(write("size.json", R"({"position":[0,0,0],"look_at":[0,0,1],"up":[0,1,0],"fov_y":40,"width":-3})"))
              .find("width") != std::string::npos);
    CHECK(messageOf(write("pose.json", R"({"position":[0,0,0],"look_at":[0,0,0],"up":[0,1,0],"fov_y":40})"))
              .find("look_at must differ") != std::string::npos);
    CHECK(messageOf(dir / "absent.json").find("cannot open") != std::string::npos);
}

TEST_CASE("camera: the JSON text parses from memory as from its file, errors name the given name") {
    const std::string text =
        R"({"position":[0,1,2],"look_at":[0,1,0],"up":[0,1,0],"fov_y":30,"width":8})";
    const auto dir = test::scratchDir("camera-memory");
    std::ofstream(dir / "c.json") << text;
    const SceneSettings fromFile = loadSceneSettings(dir / "c.json");
    const SceneSettings fromMemory = parseSceneSettings(text, "broadcast.json");
    CHECK(fromMemory.width == fromFile.width);
    CHECK(fromMemory.pose.position == fromFile.pose.position);
    CHECK(fromMemory.pose.fovYDegrees == fromFile.pose.fovYDegrees);
    try {
        parseSceneSettings(R"({"position":[0,0,0]})", "broadcast.json");
        FAIL("no error");
    } catch (const Error& e) {
        CHECK(std::string(e.what()).find("broadcast.json: missing key \"look_at\"") !=
              std::string::npos);
    }
}
