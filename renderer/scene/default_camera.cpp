#include "scene/default_camera.h"

#include <cmath>
#include <optional>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace strata {
namespace {

// Flat: every vertex this close to the plane, as a fraction of the bounding sphere's radius.
constexpr double kFlatness = 0.01;
// Area-weighted normals that sum to less than this share of the area cancel: no face side.
constexpr double kCancelling = 0.01;
// A view this close to the up axis (its up projected normal to the view shorter than this) looks
// straight down or up, and takes the model's back as its up.
constexpr float kVertical = 0.1f;

struct Sphere {
    glm::dvec3 centre;
    double radius;
};

Sphere boundingSphere(const MeshData& mesh) {
    const auto [lower, upper] = worldBounds(mesh);
    const glm::dvec3 low(lower), high(upper);
    return {0.5 * (low + high), 0.5 * glm::length(high - low)};
}

// Twice the triangle's area along its counter-clockwise normal.
glm::dvec3 areaNormal(const MeshData& mesh, const std::array<uint32_t, 3>& t) {
    const glm::dvec3 p0(mesh.positions[t[0]]);
    return glm::cross(glm::dvec3(mesh.positions[t[1]]) - p0, glm::dvec3(mesh.positions[t[2]]) - p0);
}

// The unit normal of a flat model's face side, or nullopt when the model is not flat (or has
// shared meshes). `threeQuarter` breaks the tie of normals that cancel.
std::optional<glm::dvec3> flatFace(const MeshData& mesh, const Sphere& sphere, const glm::dvec3& threeQuarter) {
    if (!mesh.sharedMeshes.empty()) return std::nullopt;
    size_t largest = 0;
    double largestArea = -1.0;
    for (size_t i = 0; i < mesh.triangles.size(); ++i) {
        const double area = glm::length(areaNormal(mesh, mesh.triangles[i]));
        if (area > largestArea) {
            largestArea = area;
            largest = i;
        }
    }
    if (!(largestArea > 0.0)) return std::nullopt;
    glm::dvec3 normal = areaNormal(mesh, mesh.triangles[largest]) / largestArea;
    const glm::dvec3 onPlane(mesh.positions[mesh.triangles[largest][0]]);
    for (const glm::vec3& p : mesh.positions) {
        if (std::abs(glm::dot(glm::dvec3(p) - onPlane, normal)) > kFlatness * sphere.radius) return std::nullopt;
    }
    double facing = 0.0;
    double area = 0.0;
    for (const auto& t : mesh.triangles) {
        const glm::dvec3 n = areaNormal(mesh, t);
        facing += glm::dot(n, normal);
        area += glm::length(n);
    }
    const bool cancel = std::abs(facing) < kCancelling * area;
    if (cancel ? glm::dot(normal, threeQuarter) < 0.0 : facing < 0.0) normal = -normal;
    return normal;
}

}  // namespace

CameraPose defaultCameraPose(const MeshData& mesh, const ModelOrientation& orientation) {
    const Sphere sphere = boundingSphere(mesh);
    const glm::dvec3 up(orientation.up);
    const glm::dvec3 front(orientation.front);
    const glm::dvec3 side = glm::cross(up, front);
    const double azimuth = glm::radians(static_cast<double>(kAzimuthDegrees));
    const double elevation = glm::radians(static_cast<double>(kElevationDegrees));
    glm::dvec3 toCamera =
        std::cos(elevation) * (std::cos(azimuth) * front + std::sin(azimuth) * side) + std::sin(elevation) * up;
    glm::dvec3 cameraUp = up;
    if (const auto face = flatFace(mesh, sphere, toCamera)) {
        toCamera = *face;
        cameraUp = up - glm::dot(up, toCamera) * toCamera;
        if (glm::length(cameraUp) < kVertical) cameraUp = -front - glm::dot(-front, toCamera) * toCamera;
    }
    const double radius = glm::max(sphere.radius, 1e-6);
    const double distance = radius / std::sin(glm::radians(0.5 * static_cast<double>(kDefaultFovYDegrees)));
    CameraPose pose;
    pose.fovYDegrees = kDefaultFovYDegrees;
    pose.lookAt = glm::vec3(sphere.centre);
    pose.position = glm::vec3(sphere.centre + distance * toCamera);
    pose.up = glm::vec3(glm::normalize(cameraUp));
    return pose;
}

}  // namespace strata
