#include "scene/gltf_cameras_lights.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/trigonometric.hpp>

#include "util/constants.h"
#include "util/printable.h"

namespace strata {
namespace {
// For a vec3 of doubles, or of the floats they become.
template <typename Vector>
bool isFinite(const Vector& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
}  // namespace

// glTF 2.0, "Cameras": a camera looks down its node's local -Z, +Y up; the first one reached
// becomes the scene's. A perspective camera's yfov is in radians; an orthographic one's ymag is
// half the height it sees. aspectRatio, xmag and the clip planes give way to Strata's image size
// and unbounded rays.
void takeGltfCamera(GltfModel& gltf, int index, const glm::dmat4& world, std::optional<CameraPose>& camera) {
    const tinygltf::Camera& gltfCamera = gltf.element(gltf.model.cameras, index, "camera");
    if (camera) return;
    CameraPose pose;
    const std::string name = "camera " + std::to_string(index);
    if (gltfCamera.type == "orthographic") {
        const double ymag = std::abs(gltfCamera.orthographic.ymag);
        if (!(ymag > 0.0) || !std::isfinite(ymag)) gltf.fail(name + ": ymag is not a finite nonzero number");
        pose.orthographicHalfHeight = static_cast<float>(ymag);
    } else {
        const double yfov = gltfCamera.perspective.yfov;
        if (!(yfov > 0.0 && yfov < glm::pi<double>())) gltf.fail(name + ": yfov outside (0, pi)");
        pose.fovYDegrees = static_cast<float>(glm::degrees(yfov));
    }
    const glm::dvec3 position(world * glm::dvec4(0.0, 0.0, 0.0, 1.0));
    const glm::dvec3 forward(world * glm::dvec4(0.0, 0.0, -1.0, 0.0));
    const glm::dvec3 up(world * glm::dvec4(0.0, 1.0, 0.0, 0.0));
    if (!(glm::length(glm::cross(forward, up)) > 0.0)) {
        gltf.warnOnce(name + " is degenerate (the scene is framed instead)");
        return;
    }
    pose.position = glm::vec3(position);
    if (!isFinite(pose.position)) {
        gltf.warnOnce("camera " + std::to_string(index) + " is beyond float range (the scene is framed instead)");
        return;
    }
    pose.lookAt = glm::vec3(position + glm::normalize(forward));
    pose.up = glm::vec3(glm::normalize(up));
    camera = pose;
}

// The camera's look-at point straight ahead at the distance of the scene's centre, so that a
// viewer orbiting it turns about the scene (the direction stays the file's).
void aimGltfCameraAtScene(CameraPose& pose, const MeshData& mesh) {
    if (mesh.positions.empty()) return;
    const auto [lower, upper] = worldBounds(mesh);
    const float distance = glm::length(0.5f * (lower + upper) - pose.position);
    if (distance > 0.0f && std::isfinite(distance)) {
        pose.lookAt = pose.position + distance * glm::normalize(pose.lookAt - pose.position);
    }
}

// KHR_lights_punctual. Its intensities are photometric (candela for point and spot lights,
// lux for directional ones); Strata takes them as radiometric without conversion: candela x
// color as W/sr, lux x color as W/m^2. `range` is ignored (the light falls off as 1/r^2
// everywhere, as the extension allows). A spot light's cone falls off as the extension's reference
// implementation does (spot_light.h). A light points down its node's local -Z.
void addGltfLight(GltfModel& gltf, int index, const glm::dmat4& world, MeshData& mesh) {
    const tinygltf::Light& light = gltf.element(gltf.model.lights, index, "KHR_lights_punctual light");
    const std::string name = "light " + quote(light.name) + " (" + std::to_string(index) + ")";
    glm::dvec3 color(1.0);
    if (!light.color.empty()) {
        if (light.color.size() != 3) gltf.fail(name + ": color needs 3 numbers");
        color = glm::make_vec3(light.color.data());
    }
    if (!(glm::min(glm::min(color.x, color.y), color.z) >= 0.0) || !isFinite(color) ||
        !(light.intensity >= 0.0) || !std::isfinite(light.intensity)) {
        gltf.fail(name + ": color and intensity must be finite and not negative");
    }
    // Checked again as the floats they become: 1e300 is a finite double and an infinite float.
    const glm::vec3 emitted(light.intensity * color);
    if (!isFinite(emitted)) gltf.fail(name + ": intensity x color is beyond float range");
    const glm::dvec3 direction(world * glm::dvec4(0.0, 0.0, -1.0, 0.0));
    if ((light.type == "directional" || light.type == "spot") && !(glm::length(direction) > 0.0)) {
        gltf.fail(name + ": its node's transform has no direction");
    }
    if (light.type == "directional") {
        mesh.directionalLights.emplace_back(glm::vec3(glm::normalize(direction)), emitted);
        return;
    }
    if (light.type != "point" && light.type != "spot") {
        gltf.fail(name + ": unknown type " + quote(light.type) + " (known: point, spot, directional)");
    }
    const glm::vec3 position(world * glm::dvec4(0.0, 0.0, 0.0, 1.0));
    if (!isFinite(position)) gltf.fail(name + ": its node's position is beyond float range");
    if (light.type == "point") {
        mesh.pointLights.emplace_back(position, emitted);
        return;
    }
    double inner = light.spot.innerConeAngle;
    double outer = light.spot.outerConeAngle;
    if (!std::isfinite(inner) || !std::isfinite(outer) || inner < 0.0 || outer < 0.0) {
        gltf.fail(name + ": spot cone angles must be finite and not negative");
    }
    // glTF: 0 <= inner < outer <= pi/2. Others are taken into that range, as viewers tolerate them.
    if (!(inner < outer && outer <= kPi / 2.0)) {
        gltf.warnOnce(name + ": spot cone angles outside 0 <= inner < outer <= pi/2; taken into that range");
        outer = std::min(outer, kPi / 2.0);
        inner = std::min(inner, outer);
    }
    mesh.spotLights.emplace_back(position, glm::vec3(glm::normalize(direction)), emitted, static_cast<float>(inner),
                                 static_cast<float>(outer));
}

}  // namespace strata
