#pragma once
// A scene ready to trace: the mesh in an Embree 3 BVH, its materials ready to become BSDFs
// (materials/material_table.h) and its lights (lights/scene_lights.h). Embree traces every ray.
// The one Embree device of the process is the only global state.
//
// A ray's hit is kept as small as Embree gives it (RayHit: t, barycentrics, triangle, placement);
// the surface record a scattering vertex needs (SurfaceHit: point, error bound, normal) is
// computed from it only where a path goes on, not at its last bounce nor at a black surface.
//
// A shared mesh (mesh.h) is one BVH of its own, each of its placements an Embree instance of it:
// the scene stores its triangles once however often it is placed. A flat scene has no instance
// level, which would cost every ray a little. Emitting triangles are never shared: each placement
// of one becomes a world triangle of its own, since a light is one triangle in the world
// (lights/area_light.h) and a hit finds its light by the triangle's index alone.
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <utility>
#include <vector>
#include <embree3/rtcore.h>
#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
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

inline constexpr uint32_t kNoPlacement = UINT32_MAX;

// Embree's answer: where along the (unit) ray, and where on which triangle.
struct RayHit {
    float t;
    float u, v;  // barycentrics of vertices 1 and 2
    uint32_t triangle;
    // Which placement of the shared mesh the triangle belongs to (an index of the scene's
    // placements, shared mesh by shared mesh in mesh().sharedMeshes' order), kNoPlacement for a
    // world triangle.
    uint32_t placement = kNoPlacement;
};

struct SurfaceHit {
    glm::vec3 point;          // on the triangle, from barycentrics (not origin + t * direction)
    glm::vec3 pointError;     // per axis: how far a new ray's origin must clear the surface
    glm::vec3 normal;         // unit geometric normal, counter-clockwise = front
    glm::vec3 shadingNormal;  // unit: interpolated from the vertex normals, then normal-mapped;
                              // `normal` when flat
    glm::vec2 uv;             // texture coordinates, (0, 0) on a triangle without
    glm::vec3 colour;         // the vertex colours interpolated, (1, 1, 1) on a triangle without
    uint32_t triangle;        // and RayHit::placement, for what is in world coordinates above
    bool smooth;              // the shading normal is not `normal` (interpolated or mapped)
};

struct SceneSummary {
    size_t triangles = 0;        // stored: a shared mesh's once
    uint64_t placedTriangles = 0;  // in the world: a shared mesh's once per placement
    size_t placements = 0;       // of shared meshes (Embree instances)
    size_t emitters = 0;       // emitting triangles (area lights)
    double emittingArea = 0.0;
    float maxAlbedo = 0.0f;    // upper bound on the albedo of the materials in use: max Kd + max Ks
    float maxEmission = 0.0f;  // largest Ke component in use, or colour of an unlit surface
    size_t unlitTriangles = 0;  // of unlit materials (material.h): seen, though no light
    double roundingGapShare = 0.0;  // traversal_precision.h
    bool watertight = true;         // traced with Embree's watertight (robust) triangle test
};

class Scene {
public:
    // Throws strata::Error if the mesh has no triangles, an index is out of range or a shared
    // mesh is malformed (ranges, vertices, placements: mesh.h). A triangle whose winding
    // disagrees with its vertex normals is turned over, so that its front (the side it emits
    // from) is the side its normals show. The emitting triangles of shared meshes become world
    // triangles, one per placement, after the others of the world. Then the world's triangles
    // come first, each shared mesh's after them, and within each the triangles of cut-out
    // materials (with a coverage texture) after the others, in their order, for an Embree
    // geometry of their own (cutout_filter.h): mesh().triangles is in that order, which is the
    // one hits and lights use; a flat scene keeps its order but for the cut-outs. `traversal`
    // picks Embree's triangle test (traversal_precision.h).
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
    // The displacement, in world coordinates, from the hit's point to the curved surface that its
    // triangle's vertex normals describe (geometry/smooth_surface.h), on the triangle's front
    // side (`front`) or its back; zero on a triangle without vertex normals.
    glm::vec3 smoothSurfaceLift(const RayHit& hit, bool front) const;
    // The normal of a clear coat at the hit (texture coordinates `uv`), in world coordinates and
    // not yet turned toward the viewer: the vertex normals' (the geometric one without them) under
    // the coat's own normal map, if any. A base's normal map does not reach the coat (glTF's
    // KHR_materials_clearcoat).
    glm::vec3 coatNormal(const RayHit& hit, glm::vec2 uv) const;
    // Whether anything blocks the open segment from origin to origin + direction * distance.
    bool occluded(const Ray& ray, float distance) const;

    // What a bounce reads of the triangle it hit, in one record.
    struct Triangle {
        // Unit geometric normal, counter-clockwise = front, in the triangle's coordinates: the
        // world's for every emitting triangle and every triangle of a flat scene, a shared
        // mesh's own for its triangles (SurfaceHit::normal is the world's for any hit).
        glm::vec3 normal;
        uint32_t material;
        int32_t light;     // index in lights(), -1 when the triangle emits nothing
    };
    const Triangle& triangle(uint32_t index) const { return triangles_[index]; }
    const Material& material(uint32_t triangle) const {
        return mesh_.materials[mesh_.triangleMaterials[triangle]];
    }
    const MaterialTable& materials() const { return materials_; }
    const SceneLights& lights() const { return lights_; }
    // The mesh as laid out (the constructor's order). With shared meshes, their triangles' vertices
    // are in their own coordinates, and the emitting triangles placed into the world leave their
    // originals' vertices unused.
    const MeshData& mesh() const { return mesh_; }
    const SceneSummary& summary() const { return summary_; }
    // World bounding box of all vertices (mesh.h's worldBounds).
    glm::vec3 boundsMin() const { return bounds_.first; }
    glm::vec3 boundsMax() const { return bounds_.second; }
    // The Embree scene, for measuring raw ray throughput on the same BVH (ray_throughput.h).
    RTCScene embreeScene() const { return rtcScene_; }

private:
    // Triangles [first, end) of the mesh, its cut-outs from firstCutout on: the world's or a
    // shared mesh's, each an Embree scene (geometry 0: the opaque triangles, 1: the cut-outs).
    struct TriangleRange {
        uint32_t first, firstCutout, end;
    };
    // A placement of a shared mesh: the Embree instance of geometry ID kFirstPlacementID + its
    // index in the top-level scene.
    struct Placement {
        glm::mat4 toWorld;
        glm::mat3 normalToWorld;  // the inverse transpose of toWorld's linear part
        uint32_t first, firstCutout;  // its shared mesh's TriangleRange
    };
    static constexpr uint32_t kFirstPlacementID = 2;

    // Embree's answer for one ray as a RayHit.
    std::optional<RayHit> hitOf(uint32_t instance, uint32_t geometry, uint32_t primitive, float t, float u,
                                float v) const;
    // Attaches the triangles of `range` to `scene` as geometries 0 and 1.
    void attachTriangles(RTCScene scene, const TriangleRange& range);
    // The triangle's vertex normals interpolated at barycentrics (b0, b1, b2), of unit length;
    // empty without vertex normals or where they cancel.
    std::optional<glm::vec3> vertexNormalAt(uint32_t triangle, float b0, float b1, float b2) const;
    // The surface record at a hit in the triangle's own coordinates.
    SurfaceHit localSurface(const RayHit& hit) const;
    static void placeInWorld(SurfaceHit& hit, const Placement& placement);

    MeshData mesh_;
    std::pair<glm::vec3, glm::vec3> bounds_;  // of the mesh as given, before its layout
    SceneSummary summary_;
    std::vector<Triangle> triangles_;
    MaterialTable materials_;
    SceneLights lights_;
    RTCScene rtcScene_ = nullptr;
    uint32_t firstCutout_ = 0;  // world triangles from here on are in the cut-out geometry
    std::vector<Placement> placements_;
    std::vector<std::unique_ptr<CutoutTriangles>> cutouts_;  // each range's with cut-outs
};

// Moves a ray origin off a surface so that the new ray cannot hit the surface it leaves, however
// far the point is from the origin of the coordinates: the offset follows the point's own rounding
// error bound (pbrt-v4's OffsetRayOrigin idea), not a fixed epsilon.
glm::vec3 offsetRayOrigin(const SurfaceHit& hit, const glm::vec3& direction);

}  // namespace strata
