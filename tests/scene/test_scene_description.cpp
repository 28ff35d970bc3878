#include <doctest/doctest.h>

#include <cmath>
#include <string>
#include <glm/trigonometric.hpp>

#include "scene/scene_description.h"
#include "util/error.h"

using namespace strata;

namespace {

const std::string kPoseFromOrigin = R"("position":[0,0,0],"look_at":[0,0,1],"up":[0,1,0],"fov_y":40)";

std::string descriptionError(const std::string& text) {
    try {
        parseSceneDescription(text, "s.json");
    } catch (const Error& e) {
        return e.what();
    }
    return "no error";
}

}  // namespace

TEST_CASE("scene description: the camera, typed lights and the older point_lights are read") {
    const SceneDescription d = parseSceneDescription(
        "{" + kPoseFromOrigin + R"(,"width":32,"height":16,"extra":"ignored",)"
        R"("lights":[{"type":"point","position":[1,2,3],"intensity":[4,5,6]}],)"
        R"("point_lights":[{"position":[7,8,9],"intensity":[1,2,3]}]})",
        "s.json");
    CHECK(d.hasPose);
    CHECK(d.camera.pose.lookAt == glm::vec3(0, 0, 1));
    CHECK(d.camera.pose.fovYDegrees == 40.0f);
    CHECK(d.camera.width == 32);
    CHECK(d.camera.height == 16);
    REQUIRE(d.pointLights.size() == 2);
    CHECK(d.pointLights[0].position == glm::vec3(1, 2, 3));
    CHECK(d.pointLights[0].intensity == glm::vec3(4, 5, 6));
    CHECK(d.pointLights[1].position == glm::vec3(7, 8, 9));
    CHECK(d.pointLights[1].intensity == glm::vec3(1, 2, 3));
    CHECK(d.files.empty());
}

TEST_CASE("scene description: the camera's thin lens, aperture_radius and focus_distance, is optional") {
    const SceneDescription lens = parseSceneDescription(
        "{" + kPoseFromOrigin + R"(,"aperture_radius":0.25,"focus_distance":12})", "s.json");
    CHECK(lens.camera.pose.apertureRadius == 0.25f);
    CHECK(lens.camera.pose.focusDistance == 12.0f);
    const SceneDescription pinhole = parseSceneDescription("{" + kPoseFromOrigin + "}", "s.json");
    CHECK(pinhole.camera.pose.apertureRadius == 0.0f);
    CHECK(pinhole.camera.pose.focusDistance == 0.0f);
    CHECK(descriptionError("{" + kPoseFromOrigin + R"(,"aperture_radius":"wide"})") ==
          "s.json: \"aperture_radius\" must be a number");
    CHECK(descriptionError("{" + kPoseFromOrigin + R"(,"focus_distance":-2})") ==
          "s.json: focus_distance must be a finite number >= 0");
}

TEST_CASE("scene description: without the camera keys the camera is left to the scene's framing") {
    const SceneDescription lightsOnly = parseSceneDescription(
        R"({"width":8,"lights":[{"type":"point","position":[0,1,0],"intensity":[2,2,2]}]})", "s.json");
    CHECK_FALSE(lightsOnly.hasPose);
    CHECK(lightsOnly.camera.width == 8);
    CHECK(lightsOnly.camera.height == 256);
    CHECK(lightsOnly.pointLights.size() == 1);
    const SceneDescription empty = parseSceneDescription("{}", "s.json");
    CHECK_FALSE(empty.hasPose);
    CHECK(empty.pointLights.empty());
    // One camera key asks for all of them.
    CHECK(descriptionError(R"({"position":[0,0,0]})") == "s.json: missing key \"look_at\"");
    CHECK(descriptionError(R"({"fov_y":40})") == "s.json: missing key \"position\"");
}

TEST_CASE("scene description: a bad file is named with the problem") {
    const std::string syntax = descriptionError("{\n\"position\": [0,0,\n}");
    CHECK(syntax.rfind("s.json: invalid JSON: parse error at line 3", 0) == 0);
    CHECK(descriptionError("[1, 2, 3]") == "s.json: expected a JSON object");
    CHECK(descriptionError(R"({"position":[0,0,"x"],"look_at":[0,0,1],"up":[0,1,0],"fov_y":40})") ==
          "s.json: \"position\" must be an array of 3 numbers");
    CHECK(descriptionError("{" + kPoseFromOrigin + R"(,"width":-3})") == "s.json: \"width\" must be an integer in 1..65536");
    CHECK(descriptionError(R"({"height":0})") == "s.json: \"height\" must be an integer in 1..65536");
    CHECK(descriptionError(R"({"position":[0,0,0],"look_at":[0,0,0],"up":[0,1,0],"fov_y":40})") ==
          "s.json: look_at must differ from position");
    CHECK(descriptionError(R"({"point_lights":[{"position":[0,1,0]}]})") == "s.json: missing key \"intensity\"");
    CHECK(descriptionError(R"({"point_lights":{}})") == "s.json: \"point_lights\" must be an array");
    CHECK(descriptionError(R"({"point_lights":[3]})") == "s.json: each of \"point_lights\" must be an object");
    // A negative intensity would give negative radiance.
    CHECK(descriptionError(R"({"lights":[{"type":"point","position":[0,1,0],"intensity":[1,-5,1]}]})") ==
          "s.json: a point light's \"intensity\" must be three values >= 0 (W/sr)");
}

TEST_CASE("scene description: a spot light with its direction and cones in degrees, glTF's by default") {
    const SceneDescription d = parseSceneDescription(
        R"({"lights":[{"type":"spot","position":[0,4,0],"direction":[0,-2,0],"intensity":[5,5,5],)"
        R"("inner_cone":10,"outer_cone":30},{"type":"spot","position":[1,1,1],"direction":[1,0,0],"intensity":[1,1,1]}]})",
        "s.json");
    REQUIRE(d.spotLights.size() == 2);
    const SpotLight& spot = d.spotLights[0];
    CHECK(spot.position == glm::vec3(0, 4, 0));
    CHECK(spot.axis == glm::vec3(0, -1, 0));
    CHECK(spot.falloff(std::cos(glm::radians(9.9f))) == 1.0f);
    CHECK(spot.falloff(std::cos(glm::radians(30.1f))) == 0.0f);
    CHECK(d.spotLights[1].falloff(std::cos(glm::radians(44.9f))) > 0.0f);
    CHECK(d.spotLights[1].falloff(std::cos(glm::radians(45.1f))) == 0.0f);
    const std::string light = R"({"lights":[{"type":"spot","position":[0,4,0],"intensity":[5,5,5],)";
    CHECK(descriptionError(light + R"("direction":[0,0,0]}]})") == "s.json: a spot light's \"direction\" must not be zero");
    CHECK(descriptionError(light + R"("direction":[0,1,0],"inner_cone":50,"outer_cone":40}]})") ==
          "s.json: a spot light's cones must hold 0 <= \"inner_cone\" <= \"outer_cone\" <= 90");
    CHECK(descriptionError(light + R"("direction":[0,1,0],"outer_cone":"wide"}]})") ==
          "s.json: \"outer_cone\" must be a number of degrees");
}

TEST_CASE("scene description: a light of an unknown type names the file and the type, and the known ones") {
    CHECK(descriptionError(R"({"lights":[{"type":"area","position":[0,1,0],"intensity":[1,1,1]}]})") ==
          "s.json: unknown light type 'area' (known: point, spot)");
    CHECK(descriptionError(R"({"lights":[{"position":[0,1,0],"intensity":[1,1,1]}]})") ==
          "s.json: each of \"lights\" needs a \"type\" (known: point, spot)");
    CHECK(descriptionError(R"({"lights":[{"type":7}]})") == "s.json: each of \"lights\" needs a \"type\" (known: point, spot)");
    CHECK(descriptionError(R"({"lights":[{"type":"point","position":[0,1,0]}]})") == "s.json: missing key \"intensity\"");
    CHECK(descriptionError(R"({"lights":{"type":"point"}})") == "s.json: \"lights\" must be an array");
    CHECK(descriptionError(R"({"lights":["point"]})") == "s.json: each of \"lights\" must be an object");
}

TEST_CASE("scene description: a camera file must give the camera, and lends only its point_lights") {
    const SceneDescription camera = parseCameraFile(
        "{" + kPoseFromOrigin + R"(,"width":8,"lights":[{"type":"point","position":[1,1,1],"intensity":[1,1,1]}],)"
        R"("point_lights":[{"position":[2,2,2],"intensity":[3,3,3]}]})",
        "cam.json");
    CHECK(camera.hasPose);
    CHECK(camera.camera.width == 8);
    REQUIRE(camera.pointLights.size() == 1);
    CHECK(camera.pointLights[0].position == glm::vec3(2, 2, 2));
    CHECK_THROWS_WITH_AS(parseCameraFile(R"({"width":8})", "cam.json"),
                         "cam.json: missing key \"position\"", Error);
    // Its lights are not read, so a type only a later version knows is no error there.
    CHECK_NOTHROW(parseCameraFile("{" + kPoseFromOrigin + R"(,"lights":[{"type":"spot"}]})", "cam.json"));
}

TEST_CASE("scene description: the environment is none, a colour or a map file that travels with it") {
    CHECK(parseSceneDescription("{}", "s.json").environment.kind == Environment::Kind::Default);
    CHECK(parseSceneDescription(R"({"environment":"none"})", "s.json").environment.kind ==
          Environment::Kind::None);
    const SceneDescription colour = parseSceneDescription(R"({"environment":{"color":[0.5,1,2]}})", "s.json");
    CHECK(colour.environment.kind == Environment::Kind::Uniform);
    CHECK(colour.environment.radiance == glm::vec3(0.5f, 1.0f, 2.0f));
    CHECK(colour.files.empty());
    const SceneDescription map =
        parseSceneDescription(R"({"environment":{"file":"sky/sky.exr","rotate":30}})", "s.json");
    CHECK(map.environment.kind == Environment::Kind::Map);
    CHECK(map.environment.rotationDegrees == 30.0f);
    CHECK(map.environment.map == nullptr);  // parseScene decodes it from the bundle
    CHECK(map.environmentFile == "sky/sky.exr");
    CHECK(map.files == std::vector<std::string>{"sky/sky.exr"});
}

TEST_CASE("scene description: a bad environment names the file and the key") {
    const std::string forms =
        R"(s.json: "environment" must be "none", {"color": [r,g,b]} or {"file": "sky.exr", "rotate": degrees})";
    CHECK(descriptionError(R"({"environment":"sky"})") == forms);
    CHECK(descriptionError(R"({"environment":3})") == forms);
    CHECK(descriptionError(R"({"environment":{}})") == forms);
    CHECK(descriptionError(R"({"environment":{"file":"a.exr","color":[1,1,1]}})") == forms);
    CHECK(descriptionError(R"({"environment":{"color":[1,-1,1]}})") ==
          R"(s.json: "environment" "color" must be three radiances >= 0)");
    CHECK(descriptionError(R"({"environment":{"color":[1,1]}})") == R"(s.json: "color" must be an array of 3 numbers)");
    CHECK(descriptionError(R"({"environment":{"file":""}})") == R"(s.json: "environment" "file" must be an EXR file's path)");
    CHECK(descriptionError(R"({"environment":{"file":"a.exr","rotate":"x"}})") ==
          R"(s.json: "environment" "rotate" must be a number (degrees))");
}
