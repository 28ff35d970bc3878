#include "scene/camera.h"

#include <cmath>
#include <limits>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <nlohmann/json.hpp>

#include "util/error.h"
#include "util/text_file.h"

namespace strata {
namespace {

using nlohmann::json;

// A JSON number as a float; a value beyond float range is an error here rather than an undefined
// conversion (found by the loader fuzzer).
float readFloat(const json& value, const char* key, const std::string& path) {
    const double d = value.get<double>();
    if (!(std::abs(d) <= std::numeric_limits<float>::max())) {
        throw Error(path + ": \"" + key + "\" must be finite and within float range");
    }
    return static_cast<float>(d);
}

glm::vec3 readVec3(const json& object, const char* key, const std::string& path) {
    const auto it = object.find(key);
    if (it == object.end()) {
        throw Error(path + ": missing key \"" + key + "\"");
    }
    if (!it->is_array() || it->size() != 3 || !(*it)[0].is_number() || !(*it)[1].is_number() ||
        !(*it)[2].is_number()) {
        throw Error(path + ": \"" + key + "\" must be an array of 3 numbers");
    }
    glm::vec3 v;
    for (int i = 0; i < 3; ++i) v[i] = readFloat((*it)[i], key, path);
    return v;
}

int readSize(const json& object, const char* key, int fallback, const std::string& path) {
    const auto it = object.find(key);
    if (it == object.end()) return fallback;
    if (!it->is_number_integer() || it->get<int64_t>() < 1 || it->get<int64_t>() > 65536) {
        throw Error(path + ": \"" + key + "\" must be an integer in 1..65536");
    }
    return static_cast<int>(it->get<int64_t>());
}

}  // namespace

SceneSettings loadSceneSettings(const std::filesystem::path& path) {
    return parseSceneSettings(readTextFile(path, "camera file"), path.string());
}

SceneSettings parseSceneSettings(const std::string& text, const std::string& path) {
    json root;
    try {
        root = json::parse(text);
    } catch (const json::exception& e) {
        // nlohmann's message reads "[json.exception.parse_error.N] parse error at line L,
        // column C: ..."; drop the bracketed id, keep the position and the explanation.
        // Not only parse_error: a number beyond double range throws out_of_range.406 (a fuzzer
        // finding, which escaped as an unexpected failure without the file's name).
        const std::string what = e.what();
        const auto bracket = what.find("] ");
        throw Error(path + ": invalid JSON: " +
                    (bracket == std::string::npos ? what : what.substr(bracket + 2)));
    }
    if (!root.is_object()) throw Error(path + ": expected a JSON object");

    SceneSettings settings;
    settings.pose.position = readVec3(root, "position", path);
    settings.pose.lookAt = readVec3(root, "look_at", path);
    settings.pose.up = readVec3(root, "up", path);
    const auto fov = root.find("fov_y");
    if (fov == root.end() || !fov->is_number()) {
        throw Error(path + ": \"fov_y\" must be a number (degrees)");
    }
    settings.pose.fovYDegrees = readFloat(*fov, "fov_y", path);
    settings.width = readSize(root, "width", settings.width, path);
    settings.height = readSize(root, "height", settings.height, path);

    if (const auto lights = root.find("point_lights"); lights != root.end()) {
        if (!lights->is_array()) throw Error(path + ": \"point_lights\" must be an array");
        for (const auto& light : *lights) {
            if (!light.is_object()) {
                throw Error(path + ": each of \"point_lights\" must be an object");
            }
            settings.pointLights.push_back(
                {readVec3(light, "position", path), readVec3(light, "intensity", path)});
        }
    }
    // Validate the pose now, so a bad file is reported as the file's fault.
    try {
        Camera(settings.pose, settings.width, settings.height);
    } catch (const Error& e) {
        throw Error(path + ": " + e.what());
    }
    return settings;
}

Camera::Camera(const CameraPose& pose, int width, int height)
    : pose_(pose), width_(width), height_(height) {
    if (width < 1 || height < 1) throw Error("image size must be at least 1x1");
    if (!(pose.fovYDegrees > 0.0f && pose.fovYDegrees < 180.0f)) {
        throw Error("fov_y must be in (0, 180) degrees");
    }
    const glm::vec3 view = pose.lookAt - pose.position;
    if (!(glm::length(view) > 0.0f)) throw Error("look_at must differ from position");
    forward_ = glm::normalize(view);
    const glm::vec3 side = glm::cross(forward_, pose.up);
    if (!(glm::length(side) > 1e-6f * glm::length(pose.up))) {
        throw Error("up must not be parallel to the view direction");
    }
    const float halfHeight = std::tan(glm::radians(pose.fovYDegrees) * 0.5f);
    const float halfWidth = halfHeight * static_cast<float>(width) / static_cast<float>(height);
    right_ = glm::normalize(side) * halfWidth;
    upScaled_ = glm::normalize(glm::cross(side, forward_)) * halfHeight;
}

Ray Camera::generateRay(int x, int y, glm::vec2 jitter) const {
    const float ndcX = 2.0f * (static_cast<float>(x) + jitter.x) / static_cast<float>(width_) - 1.0f;
    const float ndcY = 1.0f - 2.0f * (static_cast<float>(y) + jitter.y) / static_cast<float>(height_);
    return {pose_.position, glm::normalize(forward_ + ndcX * right_ + ndcY * upScaled_)};
}

}  // namespace strata
