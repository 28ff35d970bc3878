#pragma once
// A scene ready to trace: the mesh in an Embree 3 BVH plus what shading needs per triangle.
// Embree traces every ray. The one Embree device of the process is the only global state.
#include <cstdint>
#include <optional>
#include <vector>
#include <embree3/rtcore.h>
#include <glm/vec3.hpp>

#include "scene/mesh.h"
#include "geometry/ray.h"

namespace strata {

// The process's Embree device, created on first use.
RTCDevice embreeDevice();

struct SurfaceHit {
    glm::vec3 point;       // on the triangle, from barycentrics (not origin + t * direction)
    glm::vec3 pointError;  // per axis: how far a new ray's origin must clear the surface
    glm::vec3 normal;      // unit geometric normal, counter-clockwise = front
    uint32_t triangle;
};

struct SceneSummary {
    size_t triangles = 0;
    size_t emitters = 0;       // emitting triangles
    double emittingArea = 0.0;
    float maxAlbedo = 0.0f;    // upper bound on the albedo of the materials in use: max Kd + max Ks
    float maxEmission = 0.0f;  // largest Ke component in use
};

class Scene {
public:
    // Throws strata::Error if the mesh has no triangles or an index is out of range.
    explicit Scene(MeshData mesh);
    ~Scene();
    Scene(Scene&& other) noexcept;
    Scene& operator=(Scene&&) = delete;
    Scene(const Scene&) = delete;
    Scene& operator=(const Scene&) = delete;

    std::optional<SurfaceHit> intersect(const Ray& ray) const;
    // Whether anything blocks the open segment from origin to origin + direction * distance.
    bool occluded(const Ray& ray, float distance) const;

    const Material& material(uint32_t triangle) const {
        return mesh_.materials[mesh_.triangleMaterials[triangle]];
    }
    const MeshData& mesh() const { return mesh_; }
    const SceneSummary& summary() const { return summary_; }
    // Bounding box of all vertices.
    glm::vec3 boundsMin() const { return boundsMin_; }
    glm::vec3 boundsMax() const { return boundsMax_; }
    // The Embree scene, for measuring raw ray throughput on the same BVH (ray_throughput.h).
    RTCScene embreeScene() const { return rtcScene_; }

private:
    MeshData mesh_;
    std::vector<glm::vec3> normals_;
    SceneSummary summary_;
    glm::vec3 boundsMin_{0.0f};
    glm::vec3 boundsMax_{0.0f};
    RTCScene rtcScene_ = nullptr;
};

// Moves a ray origin off a surface so that the new ray cannot hit the surface it leaves, however
// far the point is from the origin of the coordinates: the offset follows the point's own rounding
// error bound (pbrt-v4's OffsetRayOrigin idea), not a fixed epsilon.
glm::vec3 offsetRayOrigin(const SurfaceHit& hit, const glm::vec3& direction);

}  // namespace strata
