#pragma once
// A scene ready to trace: the mesh in an Embree 3 BVH, its materials ready to become BSDFs
// (materials/material_table.h) and its lights (lights/scene_lights.h). Embree traces every ray.
// The one Embree device of the process is the only global state.
//
// A ray's hit is kept as small as Embree gives it (RayHit: t, barycentrics, triangle); the
// surface record a scattering vertex needs (SurfaceHit: point, error bound, normal) is computed
// from it only where a path goes on, not at its last bounce nor at a black surface.
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>
#include <embree3/rtcore.h>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "geometry/ray.h"
#include "lights/scene_lights.h"
#include "materials/material_table.h"
#include "scene/cutout_filter.h"
#include "scene/mesh.h"
#include "scene/traversal_precision.h"

namespace strata {

// The process's Embree device, created on first use.
RTCDevice embreeDevice();

// Embree's answer: where along the (unit) ray, and where on which triangle.
struct RayHit {
    float t;
    float u, v;  // barycentrics of vertices 1 and 2
    uint32_t triangle;
};

struct SurfaceHit {
    glm::vec3 point;          // on the triangle, from barycentrics (not origin + t * direction)
    glm::vec3 pointError;     // per axis: how far a new ray's origin must clear the surface
    glm::vec3 normal;         // unit geometric normal, counter-clockwise = front
    glm::vec3 shadingNormal;  // unit: interpolated from the vertex normals, then normal-mapped;
                              // `normal` when flat
    glm::vec2 uv;             // texture coordinates, (0, 0) on a triangle without
    uint32_t triangle;
    bool smooth;              // the shading normal is not `normal` (interpolated or mapped)
};

struct SceneSummary {
    size_t triangles = 0;
    size_t emitters = 0;       // emitting triangles (area lights)
    double emittingArea = 0.0;
    float maxAlbedo = 0.0f;    // upper bound on the albedo of the materials in use: max Kd + max Ks
    float maxEmission = 0.0f;  // largest Ke component in use
    double roundingGapShare = 0.0;  // traversal_precision.h
    bool watertight = true;         // traced with Embree's watertight (robust) triangle test
};

class Scene {
public:
    // Throws strata::Error if the mesh has no triangles or an index is out of range. A triangle
    // whose winding disagrees with its vertex normals is turned over, so that its front (the side
    // it emits from) is the side its normals show. Triangles of cut-out materials (with a
    // coverage texture) are moved after all others, in their order, for their own Embree
    // geometry (cutout_filter.h): mesh().triangles is in that order, which is the one hits and
    // lights use. `traversal` picks Embree's triangle test (traversal_precision.h).
    explicit Scene(MeshData mesh, Traversal traversal = Traversal::Automatic);
    ~Scene();
    Scene(Scene&& other) noexcept;
    Scene& operator=(Scene&&) = delete;
    Scene(const Scene&) = delete;
    Scene& operator=(const Scene&) = delete;

    // Lights the scene with `environment` in place of the one it was given (mesh().environment,
    // which stays: Default goes back to it). Only what depends on the environment is rebuilt: its
    // light and the choice among the lights (scene_lights.h); the triangles, their lights and the
    // BVH stay, so relighting costs the same for a model of a million triangles as for a quad.
    void setEnvironment(const Environment& environment);

    std::optional<RayHit> intersect(const Ray& ray) const;
    // Many rays at once, traced in Embree's packets of 8: a packet pays even for incoherent rays,
    // and more for rays that start together (Coherent: a pixel's camera rays). Each ray's answer
    // is bit for bit the one the single-ray query gives it (tests/scene/test_scene.cpp).
    enum class Coherence { Coherent, Incoherent };
    void intersect(std::span<const Ray> rays, std::span<std::optional<RayHit>> hits, Coherence coherence) const;
    // blocked[i]: whether occluded(rays[i], distances[i]).
    void occluded(std::span<const Ray> rays, std::span<const float> distances, std::span<bool> blocked) const;
    // The surface record at a hit.
    SurfaceHit surface(const RayHit& hit) const;
    // Whether anything blocks the open segment from origin to origin + direction * distance.
    bool occluded(const Ray& ray, float distance) const;

    // What a bounce reads of the triangle it hit, in one record.
    struct Triangle {
        glm::vec3 normal;  // unit geometric normal, counter-clockwise = front
        uint32_t material;
        int32_t light;     // index in lights(), -1 when the triangle emits nothing
    };
    const Triangle& triangle(uint32_t index) const { return triangles_[index]; }
    const Material& material(uint32_t triangle) const {
        return mesh_.materials[mesh_.triangleMaterials[triangle]];
    }
    const MaterialTable& materials() const { return materials_; }
    const SceneLights& lights() const { return lights_; }
    const MeshData& mesh() const { return mesh_; }
    const SceneSummary& summary() const { return summary_; }
    // Bounding box of all vertices.
    glm::vec3 boundsMin() const { return boundsMin_; }
    glm::vec3 boundsMax() const { return boundsMax_; }
    // The Embree scene, for measuring raw ray throughput on the same BVH (ray_throughput.h).
    RTCScene embreeScene() const { return rtcScene_; }

private:
    // Embree's answer for one ray (geometry 0: the opaque triangles, 1: the cut-outs) as a RayHit.
    std::optional<RayHit> hitOf(uint32_t geometry, uint32_t primitive, float t, float u, float v) const;

    MeshData mesh_;
    std::vector<Triangle> triangles_;
    MaterialTable materials_;
    SceneLights lights_;
    SceneSummary summary_;
    glm::vec3 boundsMin_{0.0f};
    glm::vec3 boundsMax_{0.0f};
    RTCScene rtcScene_ = nullptr;
    uint32_t firstCutout_ = 0;  // triangles from here on are in the cut-out geometry
    std::unique_ptr<CutoutTriangles> cutouts_;
};

// Moves a ray origin off a surface so that the new ray cannot hit the surface it leaves, however
// far the point is from the origin of the coordinates: the offset follows the point's own rounding
// error bound (pbrt-v4's OffsetRayOrigin idea), not a fixed epsilon.
glm::vec3 offsetRayOrigin(const SurfaceHit& hit, const glm::vec3& direction);

}  // namespace strata
