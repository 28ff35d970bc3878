#include "scene/scene_description.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string_view>
#include <utility>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <nlohmann/json.hpp>

#include "util/components.h"
#include "util/error.h"
#include "util/printable.h"

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

json parseObject(const std::string& text, const std::string& path) {
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
    return root;
}

CameraPose readPose(const json& root, const std::string& path) {
    CameraPose pose;
    pose.position = readVec3(root, "position", path);
    pose.lookAt = readVec3(root, "look_at", path);
    pose.up = readVec3(root, "up", path);
    const auto fov = root.find("fov_y");
    if (fov == root.end() || !fov->is_number()) {
        throw Error(path + ": \"fov_y\" must be a number (degrees)");
    }
    pose.fovYDegrees = readFloat(*fov, "fov_y", path);
    // The thin lens, optional (camera.h checks the values).
    for (const auto& [key, value] : {std::pair{"aperture_radius", &pose.apertureRadius},
                                     std::pair{"focus_distance", &pose.focusDistance}}) {
        const auto it = root.find(key);
        if (it == root.end()) continue;
        if (!it->is_number()) throw Error(path + ": \"" + key + "\" must be a number");
        *value = readFloat(*it, key, path);
    }
    return pose;
}

// Any of the pose's keys makes the file give the camera, and then all four are required.
bool hasPoseKey(const json& root) {
    constexpr const char* kPoseKeys[] = {"position", "look_at", "up", "fov_y"};
    return std::any_of(std::begin(kPoseKeys), std::end(kPoseKeys),
                       [&](const char* key) { return root.contains(key); });
}

// A light's "intensity": three values >= 0 (W/sr), for `kind` ("point", "spot").
glm::vec3 readIntensity(const json& entry, const std::string& path, const char* kind) {
    const glm::vec3 intensity = readVec3(entry, "intensity", path);
    if (!(minComponent(intensity) >= 0.0f)) {
        throw Error(path + ": a " + kind + " light's \"intensity\" must be three values >= 0 (W/sr)");
    }
    return intensity;
}

PointLight readPointLight(const json& entry, const std::string& path) {
    const glm::vec3 intensity = readIntensity(entry, path, "point");
    return {readVec3(entry, "position", path), intensity};
}

// A spot light: "position", "direction" (where it points), "intensity" (W/sr along its axis), and
// its cones in degrees, "inner_cone" (default 0) and "outer_cone" (default 45), as glTF's.
SpotLight readSpotLight(const json& entry, const std::string& path) {
    const glm::vec3 intensity = readIntensity(entry, path, "spot");
    const glm::vec3 direction = readVec3(entry, "direction", path);
    if (direction == glm::vec3(0.0f)) throw Error(path + ": a spot light's \"direction\" must not be zero");
    const auto degrees = [&](const char* key, float fallback) {
        const auto it = entry.find(key);
        if (it == entry.end()) return fallback;
        if (!it->is_number()) throw Error(path + ": \"" + key + "\" must be a number of degrees");
        return readFloat(*it, key, path);
    };
    const float inner = degrees("inner_cone", 0.0f);
    const float outer = degrees("outer_cone", 45.0f);
    if (!(inner >= 0.0f && inner <= outer && outer <= 90.0f)) {
        throw Error(path + ": a spot light's cones must hold 0 <= \"inner_cone\" <= \"outer_cone\" <= 90");
    }
    // Normalised in double: a float's squared length overflows from about 1e19.
    return {readVec3(entry, "position", path), glm::vec3(glm::normalize(glm::dvec3(direction))), intensity,
            glm::radians(inner), glm::radians(outer)};
}

// One entry of "lights", read by its "type": a new light type is one more line of the table.
void readLight(const json& entry, const std::string& path, SceneDescription& description) {
    using Reader = void (*)(const json& entry, const std::string& path, SceneDescription& into);
    static constexpr std::pair<std::string_view, Reader> kTypes[] = {
        {"point", [](const json& e, const std::string& p, SceneDescription& into) {
             into.pointLights.push_back(readPointLight(e, p));
         }},
        {"spot", [](const json& e, const std::string& p, SceneDescription& into) {
             into.spotLights.push_back(readSpotLight(e, p));
         }},
    };
    const auto knownTypes = [] {
        std::string known;
        for (const auto& [type, read] : kTypes) known += (known.empty() ? "" : ", ") + std::string(type);
        return "(known: " + known + ")";
    };
    if (!entry.is_object()) throw Error(path + ": each of \"lights\" must be an object");
    const auto type = entry.find("type");
    if (type == entry.end() || !type->is_string()) {
        throw Error(path + ": each of \"lights\" needs a \"type\" " + knownTypes());
    }
    for (const auto& [name, read] : kTypes) {
        if (name == type->get<std::string>()) return read(entry, path, description);
    }
    throw Error(path + ": unknown light type " + quote(type->get<std::string>()) + " " + knownTypes());
}

// The array under `key`, when there is one, entry by entry.
template <typename Read>
void forEachEntry(const json& root, const char* key, const std::string& path, Read read) {
    const auto entries = root.find(key);
    if (entries == root.end()) return;
    if (!entries->is_array()) throw Error(path + ": \"" + key + "\" must be an array");
    for (const json& entry : *entries) read(entry);
}

// "environment": "none", {"color": [r,g,b]} or {"file": "sky.exr", "rotate": degrees}.
void readEnvironment(const json& root, const std::string& path, SceneDescription& description) {
    const auto entry = root.find("environment");
    if (entry == root.end()) return;
    const auto refuse = [&](const std::string& why) { throw Error(path + ": \"environment\" " + why); };
    constexpr const char* kForms =
        "must be \"none\", {\"color\": [r,g,b]} or {\"file\": \"sky.exr\", \"rotate\": degrees}";
    Environment& environment = description.environment;
    if (entry->is_string()) {
        if (entry->get<std::string>() != "none") refuse(kForms);
        environment.kind = Environment::Kind::None;
        return;
    }
    if (!entry->is_object() || entry->contains("file") == entry->contains("color")) refuse(kForms);
    if (entry->contains("color")) {
        environment.kind = Environment::Kind::Uniform;
        environment.radiance = readVec3(*entry, "color", path);
        if (!(minComponent(environment.radiance) >= 0.0f)) {
            refuse("\"color\" must be three radiances >= 0");
        }
        return;
    }
    const json& file = (*entry)["file"];
    if (!file.is_string() || file.get<std::string>().empty()) refuse("\"file\" must be an EXR file's path");
    const auto rotate = entry->find("rotate");
    if (rotate != entry->end()) {
        if (!rotate->is_number()) refuse("\"rotate\" must be a number (degrees)");
        environment.rotationDegrees = readFloat(*rotate, "rotate", path);
    }
    environment.kind = Environment::Kind::Map;
    description.environmentFile = file.get<std::string>();
    description.files.push_back(description.environmentFile);
}

enum class FileRole { SceneDescription, CameraFile };

SceneDescription parse(const std::string& text, const std::string& path, FileRole role) {
    const json root = parseObject(text, path);
    SceneDescription description;
    description.hasPose = role == FileRole::CameraFile || hasPoseKey(root);
    if (description.hasPose) description.camera.pose = readPose(root, path);
    description.camera.width = readSize(root, "width", description.camera.width, path);
    description.camera.height = readSize(root, "height", description.camera.height, path);
    if (role == FileRole::SceneDescription) {
        forEachEntry(root, "lights", path, [&](const json& entry) { readLight(entry, path, description); });
        readEnvironment(root, path, description);
    }
    forEachEntry(root, "point_lights", path, [&](const json& entry) {
        if (!entry.is_object()) throw Error(path + ": each of \"point_lights\" must be an object");
        description.pointLights.push_back(readPointLight(entry, path));
    });
    // Validate the pose now, so a bad file is reported as the file's fault.
    if (description.hasPose) {
        try {
            Camera(description.camera.pose, description.camera.width, description.camera.height);
        } catch (const Error& e) {
            throw Error(path + ": " + e.what());
        }
    }
    return description;
}

}  // namespace

SceneDescription parseSceneDescription(const std::string& text, const std::string& name) {
    return parse(text, name, FileRole::SceneDescription);
}

SceneDescription parseCameraFile(const std::string& text, const std::string& name) {
    return parse(text, name, FileRole::CameraFile);
}

}  // namespace strata
