#include "scene/scene.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <utility>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <glm/vector_relational.hpp>

#include "geometry/rounding.h"
#include "geometry/smooth_surface.h"
#include "materials/normal_map.h"
#include "util/error.h"

namespace strata {
namespace {

void reportEmbreeError(void*, RTCError code, const char* message) {
    // Embree calls this for API misuse; such a failure is a bug, so say it loudly.
    std::fprintf(stderr, "embree error %d: %s\n", static_cast<int>(code), message ? message : "");
}

}  // namespace

RTCDevice embreeDevice() {
    static RTCDevice device = [] {
        RTCDevice d = rtcNewDevice(nullptr);
        if (!d) throw Error("cannot create the Embree device");
        rtcSetDeviceErrorFunction(d, reportEmbreeError, nullptr);
        return d;
    }();
    return device;
}

namespace {
// Ranges in order and apart, vertices of their own, placements affine and invertible (mesh.h).
void validateSharedMeshes(const MeshData& mesh) {
    const auto& shared = mesh.sharedMeshes;
    if (shared.empty()) return;
    size_t next = 0;
    for (const SharedMesh& s : shared) {
        if (s.firstTriangle < next || s.triangleCount == 0 || s.triangleCount > mesh.triangles.size() - s.firstTriangle) {
            throw Error("the shared meshes need disjoint, increasing, non-empty ranges of the triangles");
        }
        next = s.firstTriangle + size_t{s.triangleCount};
        for (const glm::mat4& placement : s.placements) {
            const bool affine = placement[0][3] == 0.0f && placement[1][3] == 0.0f && placement[2][3] == 0.0f &&
                                placement[3][3] == 1.0f;
            const glm::vec3 translation(placement[3]);
            const bool finite = !glm::any(glm::isnan(translation)) && !glm::any(glm::isinf(translation));
            // A non-finite linear part has no normal determinant either.
            if (!affine || !finite || !std::isnormal(glm::determinant(glm::mat3(placement)))) {
                throw Error("a shared mesh's placement is not a finite, invertible affine transform");
            }
        }
    }
    // The part each vertex belongs to: 0 the world, k + 1 shared mesh k.
    constexpr uint32_t kUnused = UINT32_MAX;
    std::vector<uint32_t> part(mesh.positions.size(), kUnused);
    size_t k = 0;
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        while (k < shared.size() && t >= shared[k].firstTriangle + size_t{shared[k].triangleCount}) ++k;
        const uint32_t trianglePart = k < shared.size() && t >= shared[k].firstTriangle ? static_cast<uint32_t>(k + 1) : 0;
        for (uint32_t v : mesh.triangles[t]) {
            if (part[v] == kUnused) part[v] = trianglePart;
            if (part[v] != trianglePart) throw Error("a vertex is used by two parts of the scene (mesh.h's shared meshes)");
        }
    }
}

// The checks the material table and the lights rely on, made before either is built.
const MeshData& validated(const MeshData& mesh) {
    if (mesh.triangles.empty()) throw Error("the scene has no triangles");
    if (mesh.triangleMaterials.size() != mesh.triangles.size()) {
        throw Error("the scene needs one material per triangle");
    }
    if (!mesh.triangleNormals.empty() && mesh.triangleNormals.size() != mesh.triangles.size()) {
        throw Error("the scene needs normal indices for every triangle or none");
    }
    if (!mesh.triangleUvs.empty() && mesh.triangleUvs.size() != mesh.triangles.size()) {
        throw Error("the scene needs texture coordinate indices for every triangle or none");
    }
    if (!mesh.triangleColours.empty() && mesh.triangleColours.size() != mesh.triangles.size()) {
        throw Error("the scene needs vertex colour indices for every triangle or none");
    }
    for (size_t i = 0; i < mesh.triangles.size(); ++i) {
        for (uint32_t index : mesh.triangles[i]) {
            if (index >= mesh.positions.size()) throw Error("a triangle's vertex index is out of range");
        }
        if (mesh.triangleMaterials[i] >= mesh.materials.size()) {
            throw Error("a triangle's material index is out of range");
        }
        if (!mesh.triangleNormals.empty() && mesh.triangleNormals[i] != kNoNormals) {
            for (uint32_t index : mesh.triangleNormals[i]) {
                if (index >= mesh.normals.size()) throw Error("a triangle's normal index is out of range");
            }
        }
        if (!mesh.triangleUvs.empty() && mesh.triangleUvs[i] != kNoUvs) {
            for (uint32_t index : mesh.triangleUvs[i]) {
                if (index >= mesh.uvs.size()) throw Error("a triangle's texture coordinate index is out of range");
            }
        }
        if (!mesh.triangleColours.empty() && mesh.triangleColours[i] != kNoColours) {
            for (uint32_t index : mesh.triangleColours[i]) {
                if (index >= mesh.colours.size()) throw Error("a triangle's vertex colour index is out of range");
            }
        }
    }
    validateSharedMeshes(mesh);
    return mesh;
}

// Turns over every triangle whose counter-clockwise normal points away from the mean of its
// vertex normals: loaders disagree on winding more often than on normals, and one-sided emission
// and the side a direction is on must agree with the shading.
MeshData& orientedToNormals(MeshData& mesh) {
    for (size_t i = 0; i < mesh.triangleNormals.size(); ++i) {
        auto& corners = mesh.triangleNormals[i];
        if (corners == kNoNormals) continue;
        auto& tri = mesh.triangles[i];
        const glm::vec3 winding = glm::cross(mesh.positions[tri[1]] - mesh.positions[tri[0]],
                                             mesh.positions[tri[2]] - mesh.positions[tri[0]]);
        const glm::vec3 shading = mesh.normals[corners[0]] + mesh.normals[corners[1]] + mesh.normals[corners[2]];
        if (glm::dot(winding, shading) < 0.0f) {
            std::swap(tri[1], tri[2]);
            std::swap(corners[1], corners[2]);
            if (!mesh.triangleUvs.empty()) std::swap(mesh.triangleUvs[i][1], mesh.triangleUvs[i][2]);
            if (!mesh.triangleColours.empty()) std::swap(mesh.triangleColours[i][1], mesh.triangleColours[i][2]);
        }
    }
    return mesh;
}

bool isCutout(const MeshData& mesh, size_t triangle) {
    return mesh.materials[mesh.triangleMaterials[triangle]].textures.coverage != nullptr;
}

// The per-triangle lists of the mesh reordered: entry i becomes the old entry order[i].
void reorderTriangles(MeshData& mesh, const std::vector<uint32_t>& order) {
    const auto reordered = [&](auto& list) {
        if (list.empty()) return;
        auto copy = std::move(list);
        list.resize(order.size());
        for (size_t i = 0; i < order.size(); ++i) list[i] = copy[order[i]];
    };
    reordered(mesh.triangles);
    reordered(mesh.triangleMaterials);
    reordered(mesh.triangleNormals);
    reordered(mesh.triangleUvs);
    reordered(mesh.triangleColours);
}

// Appends triangle `t` of a shared mesh placed by `placement` as a world triangle of its own
// (its own vertices and normals; mirrored, its corners 1 and 2 swapped to keep its front).
void appendPlacedCopy(MeshData& mesh, uint32_t t, const glm::mat4& placement) {
    const glm::mat3 normalToWorld = glm::transpose(glm::inverse(glm::mat3(placement)));
    std::array<uint32_t, 3> corners{0, 1, 2};
    if (glm::determinant(glm::mat3(placement)) < 0.0f) std::swap(corners[1], corners[2]);
    const auto firstVertex = static_cast<uint32_t>(mesh.positions.size());
    for (uint32_t c : corners) mesh.positions.emplace_back(placement * glm::vec4(mesh.positions[mesh.triangles[t][c]], 1.0f));
    mesh.triangles.push_back({firstVertex, firstVertex + 1, firstVertex + 2});
    mesh.triangleMaterials.push_back(mesh.triangleMaterials[t]);
    if (!mesh.triangleNormals.empty()) {
        const std::array<uint32_t, 3> normals = mesh.triangleNormals[t];
        if (normals == kNoNormals) {
            mesh.triangleNormals.push_back(kNoNormals);
        } else {
            const auto firstNormal = static_cast<uint32_t>(mesh.normals.size());
            for (uint32_t c : corners) mesh.normals.push_back(glm::normalize(normalToWorld * mesh.normals[normals[c]]));
            mesh.triangleNormals.push_back({firstNormal, firstNormal + 1, firstNormal + 2});
        }
    }
    // The copy's corners in the order of `corners`, of a per-triangle list of corner indices.
    const auto appendCorners = [&](std::vector<std::array<uint32_t, 3>>& list, const std::array<uint32_t, 3>& none) {
        if (list.empty()) return;
        const std::array<uint32_t, 3> original = list[t];
        list.push_back(original == none ? none
                                        : std::array<uint32_t, 3>{original[corners[0]], original[corners[1]],
                                                                  original[corners[2]]});
    };
    appendCorners(mesh.triangleUvs, kNoUvs);
    appendCorners(mesh.triangleColours, kNoColours);
}

// Lays the triangles out as the scene traces them (Scene's constructor): each shared mesh's
// emitting triangles placed into the world, the world's triangles first, then each shared mesh's,
// the cut-outs of each after its other triangles (stably), so that each kind of each is one
// contiguous range of the index buffer, an Embree geometry of its own.
MeshData& laidOut(MeshData& mesh) {
    const auto worldTriangles = static_cast<uint32_t>(mesh.triangles.size());
    std::vector<bool> placedInWorld(worldTriangles, false);
    for (const SharedMesh& shared : mesh.sharedMeshes) {
        for (uint32_t t = shared.firstTriangle; t < shared.firstTriangle + shared.triangleCount; ++t) {
            if (!emitsLight(mesh.materials[mesh.triangleMaterials[t]])) continue;
            placedInWorld[t] = true;
            for (const glm::mat4& placement : shared.placements) appendPlacedCopy(mesh, t, placement);
        }
    }
    std::vector<uint32_t> order;
    order.reserve(mesh.triangles.size());
    // Appends triangles [first, end) that `keep` keeps, the cut-outs last.
    const auto appendRange = [&](uint32_t first, uint32_t end, auto keep) {
        const size_t start = order.size();
        for (uint32_t t = first; t < end; ++t) {
            if (keep(t)) order.push_back(t);
        }
        std::stable_partition(order.begin() + static_cast<std::ptrdiff_t>(start), order.end(),
                              [&](uint32_t t) { return !isCutout(mesh, t); });
    };
    size_t k = 0;
    const auto inWorld = [&](uint32_t t) {
        if (t >= worldTriangles) return true;  // a placed copy
        while (k < mesh.sharedMeshes.size() &&
               t >= mesh.sharedMeshes[k].firstTriangle + mesh.sharedMeshes[k].triangleCount) {
            ++k;
        }
        return k == mesh.sharedMeshes.size() || t < mesh.sharedMeshes[k].firstTriangle;
    };
    appendRange(0, static_cast<uint32_t>(mesh.triangles.size()), inWorld);
    std::vector<SharedMesh> kept;
    for (SharedMesh& shared : mesh.sharedMeshes) {
        if (shared.placements.empty()) continue;  // drawn nowhere
        const auto first = static_cast<uint32_t>(order.size());
        appendRange(shared.firstTriangle, shared.firstTriangle + shared.triangleCount,
                    [&](uint32_t t) { return !placedInWorld[t]; });
        shared.firstTriangle = first;
        shared.triangleCount = static_cast<uint32_t>(order.size()) - first;
        if (shared.triangleCount > 0) kept.push_back(std::move(shared));
    }
    mesh.sharedMeshes = std::move(kept);
    reorderTriangles(mesh, order);
    return mesh;
}

// What the laid-out mesh is lit by: its emitting triangles, all in the world, and its other lights.
LightDescriptions lightDescriptions(const MeshData& mesh, const std::pair<glm::vec3, glm::vec3>& bounds) {
    LightDescriptions lights;
    lights.triangles = mesh.triangles.size();
    const uint32_t worldEnd = mesh.sharedMeshes.empty() ? static_cast<uint32_t>(mesh.triangles.size())
                                                        : mesh.sharedMeshes.front().firstTriangle;
    for (uint32_t t = 0; t < worldEnd; ++t) {
        const Material& material = mesh.materials[mesh.triangleMaterials[t]];
        if (!emitsLight(material)) continue;
        const auto& c = mesh.triangles[t];
        lights.emitters.push_back({t, {mesh.positions[c[0]], mesh.positions[c[1]], mesh.positions[c[2]]}, &material,
                                   cornerUvs(mesh, t)});
    }
    lights.pointLights = mesh.pointLights;
    lights.spotLights = mesh.spotLights;
    lights.directionalLights = mesh.directionalLights;
    lights.environment = mesh.environment;
    const auto& [lower, upper] = bounds;
    lights.sceneRadius = mesh.positions.empty() ? 0.0f : 0.5f * glm::length(upper - lower);
    lights.surfaceArea = worldArea(mesh);
    return lights;
}

// An Embree geometry of triangles [first, first + count) of the mesh, which it reads in place.
RTCGeometry triangleGeometry(RTCDevice device, const MeshData& mesh, size_t first, size_t count) {
    RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                               mesh.positions.data(), 0, sizeof(glm::vec3), mesh.positions.size());
    rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, mesh.triangles.data(),
                               first * sizeof(std::array<uint32_t, 3>), sizeof(std::array<uint32_t, 3>), count);
    return geometry;
}

// Rays for Embree's queries, from t = 0 (origins are already offset off their surfaces).
RTCRay embreeRay(const Ray& ray, float distance) {
    RTCRay r{};
    r.org_x = ray.origin.x;
    r.org_y = ray.origin.y;
    r.org_z = ray.origin.z;
    r.dir_x = ray.direction.x;
    r.dir_y = ray.direction.y;
    r.dir_z = ray.direction.z;
    r.tnear = 0.0f;
    r.tfar = distance;
    r.mask = ~0u;
    return r;
}

RTCRayHit embreeRayHit(const Ray& ray) {
    RTCRayHit rayHit{};
    rayHit.ray = embreeRay(ray, std::numeric_limits<float>::infinity());
    rayHit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rayHit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    return rayHit;
}

// Rays per Embree packet in the many-ray queries: 8, the width of AVX2, on which Embree traces a
// packet of 8 incoherent rays at 1.15-1.2x the speed of single rays (strata bench: the ray ceiling).
constexpr size_t kPacket = 8;

// Lane k of `packet` set to trace `ray` from t = 0 to `distance`.
void setLane(RTCRay8& packet, size_t k, const Ray& ray, float distance) {
    packet.org_x[k] = ray.origin.x;
    packet.org_y[k] = ray.origin.y;
    packet.org_z[k] = ray.origin.z;
    packet.dir_x[k] = ray.direction.x;
    packet.dir_y[k] = ray.direction.y;
    packet.dir_z[k] = ray.direction.z;
    packet.tnear[k] = 0.0f;
    packet.tfar[k] = distance;
    packet.time[k] = 0.0f;
    packet.mask[k] = ~0u;
    packet.id[k] = 0;
    packet.flags[k] = 0;
}

// The packet's lanes [0, count) active; the rest idle (Embree reads but never traces them).
std::array<int, kPacket> activeLanes(size_t count) {
    std::array<int, kPacket> valid;
    for (size_t k = 0; k < kPacket; ++k) valid[k] = k < count ? -1 : 0;
    return valid;
}
}  // namespace

std::optional<RayHit> Scene::hitOf(uint32_t instance, uint32_t geometry, uint32_t primitive, float t, float u,
                                   float v) const {
    if (geometry == RTC_INVALID_GEOMETRY_ID) return std::nullopt;
    if (instance == RTC_INVALID_GEOMETRY_ID) [[likely]] {
        return RayHit{t, u, v, primitive + (geometry == 1 ? firstCutout_ : 0), kNoPlacement};
    }
    const uint32_t placement = instance - kFirstPlacementID;
    const Placement& p = placements_[placement];
    return RayHit{t, u, v, primitive + (geometry == 1 ? p.firstCutout : p.first), placement};
}

void Scene::attachTriangles(RTCScene scene, const TriangleRange& range) {
    RTCDevice device = embreeDevice();
    if (range.firstCutout > range.first) {
        RTCGeometry opaque = triangleGeometry(device, mesh_, range.first, range.firstCutout - range.first);
        rtcCommitGeometry(opaque);
        rtcAttachGeometryByID(scene, opaque, 0);
        rtcReleaseGeometry(opaque);
    }
    if (range.end > range.firstCutout) {
        auto& cutouts = *cutouts_.emplace_back(std::make_unique<CutoutTriangles>());
        for (uint32_t i = range.firstCutout; i < range.end; ++i) {
            cutouts.uvs.push_back(cornerUvs(mesh_, i));
            cutouts.materials.push_back(&material(i));
        }
        RTCGeometry cutout = triangleGeometry(device, mesh_, range.firstCutout, range.end - range.firstCutout);
        attachCutoutFilter(cutout, cutouts);
        rtcCommitGeometry(cutout);
        rtcAttachGeometryByID(scene, cutout, 1);
        rtcReleaseGeometry(cutout);
    }
}

Scene::Scene(MeshData mesh, Traversal traversal)
    : mesh_(std::move(mesh)),
      bounds_(worldBounds(validated(mesh_))),
      summary_{.roundingGapShare = roundingGapShare(mesh_)},
      materials_(mesh_.materials),
      lights_(lightDescriptions(laidOut(orientedToNormals(mesh_)), bounds_)) {
    triangles_.reserve(mesh_.triangles.size());
    summary_.triangles = mesh_.triangles.size();
    summary_.placedTriangles = placedTriangles(mesh_);
    for (size_t i = 0; i < mesh_.triangles.size(); ++i) {
        const auto& tri = mesh_.triangles[i];
        const glm::vec3 cross = glm::cross(mesh_.positions[tri[1]] - mesh_.positions[tri[0]],
                                           mesh_.positions[tri[2]] - mesh_.positions[tri[0]]);
        triangles_.push_back({glm::normalize(cross), mesh_.triangleMaterials[i],
                              lights_.lightOnTriangle(static_cast<uint32_t>(i))});
        const Material& m = material(static_cast<uint32_t>(i));
        if (m.unlit) {
            // It reflects nothing, and what it shows bounds the truncation error as an emitter's
            // radiance does.
            ++summary_.unlitTriangles;
            const float texel = m.textures.colour ? maxComponent(glm::vec3(m.textures.colour->max())) : 1.0f;
            summary_.maxEmission = glm::max(summary_.maxEmission, maxComponent(m.diffuse) * glm::min(texel, 1.0f));
            continue;
        }
        // Kd + Ks bounds a layered material's albedo from above (material.h keeps it <= 1 too),
        // which is what the truncation bound needs.
        summary_.maxAlbedo =
            glm::max(summary_.maxAlbedo, glm::min(1.0f, maxComponent(m.diffuse) + maxComponent(m.specular)));
        if (triangles_.back().light >= 0) {
            ++summary_.emitters;
            summary_.emittingArea += 0.5 * glm::length(glm::dvec3(cross));
            summary_.maxEmission = glm::max(summary_.maxEmission, m.maxEmission());
        }
    }

    RTCDevice device = embreeDevice();
    // Embree reads the arrays in place: positions padded by the 4 bytes it may read past the end.
    mesh_.positions.reserve(mesh_.positions.size() + 1);
    summary_.watertight = usesWatertightTest(traversal, summary_.roundingGapShare);
    // Each range of triangles (the world's, each shared mesh's) as an Embree scene of its own.
    const auto newScene = [&] {
        RTCScene scene = rtcNewScene(device);
        if (summary_.watertight) rtcSetSceneFlags(scene, RTC_SCENE_FLAG_ROBUST);
        rtcSetSceneBuildQuality(scene, RTC_BUILD_QUALITY_HIGH);
        return scene;
    };
    const auto rangeOf = [&](uint32_t first, uint32_t end) {
        uint32_t firstCutout = first;
        while (firstCutout < end && !isCutout(mesh_, firstCutout)) ++firstCutout;
        return TriangleRange{first, firstCutout, end};
    };
    rtcScene_ = newScene();
    const auto world = rangeOf(0, mesh_.sharedMeshes.empty() ? static_cast<uint32_t>(mesh_.triangles.size())
                                                            : mesh_.sharedMeshes.front().firstTriangle);
    firstCutout_ = world.firstCutout;
    attachTriangles(rtcScene_, world);
    for (const SharedMesh& shared : mesh_.sharedMeshes) {
        const TriangleRange range = rangeOf(shared.firstTriangle, shared.firstTriangle + shared.triangleCount);
        RTCScene sharedScene = newScene();
        attachTriangles(sharedScene, range);
        rtcCommitScene(sharedScene);
        for (const glm::mat4& toWorld : shared.placements) {
            RTCGeometry instance = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_INSTANCE);
            rtcSetGeometryInstancedScene(instance, sharedScene);
            rtcSetGeometryTransform(instance, 0, RTC_FORMAT_FLOAT4X4_COLUMN_MAJOR, &toWorld[0][0]);
            rtcCommitGeometry(instance);
            rtcAttachGeometryByID(rtcScene_, instance, kFirstPlacementID + static_cast<uint32_t>(placements_.size()));
            rtcReleaseGeometry(instance);
            placements_.push_back({toWorld, glm::transpose(glm::inverse(glm::mat3(toWorld))), range.first,
                                   range.firstCutout});
        }
        rtcReleaseScene(sharedScene);  // its instances hold it
    }
    summary_.placements = placements_.size();
    rtcCommitScene(rtcScene_);
    if (rtcGetDeviceError(device) != RTC_ERROR_NONE) throw Error("Embree could not build the scene");
}

Scene::~Scene() {
    if (rtcScene_) rtcReleaseScene(rtcScene_);
}

Scene::Scene(Scene&& other) noexcept
    : mesh_(std::move(other.mesh_)),
      bounds_(other.bounds_),
      summary_(other.summary_),
      triangles_(std::move(other.triangles_)),
      materials_(std::move(other.materials_)),
      lights_(std::move(other.lights_)),
      rtcScene_(other.rtcScene_),
      firstCutout_(other.firstCutout_),
      placements_(std::move(other.placements_)),
      cutouts_(std::move(other.cutouts_)) {
    other.rtcScene_ = nullptr;
}

void Scene::setEnvironment(const Environment& environment) {
    lights_.setEnvironment(environment.kind == Environment::Kind::Default ? mesh_.environment : environment);
}

std::optional<RayHit> Scene::intersect(const Ray& ray) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    context.flags = RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
    RTCRayHit rayHit = embreeRayHit(ray);
    rtcIntersect1(rtcScene_, &context, &rayHit);
    return hitOf(rayHit.hit.instID[0], rayHit.hit.geomID, rayHit.hit.primID, rayHit.ray.tfar, rayHit.hit.u,
                 rayHit.hit.v);
}

void Scene::intersect(std::span<const Ray> rays, std::span<std::optional<RayHit>> hits,
                      Coherence coherence) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    context.flags = coherence == Coherence::Coherent ? RTC_INTERSECT_CONTEXT_FLAG_COHERENT
                                                     : RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
    for (size_t first = 0; first < rays.size(); first += kPacket) {
        const size_t count = std::min(kPacket, rays.size() - first);
        alignas(32) const std::array<int, kPacket> valid = activeLanes(count);
        alignas(32) RTCRayHit8 packet;
        for (size_t k = 0; k < kPacket; ++k) {
            setLane(packet.ray, k, rays[first + std::min(k, count - 1)], std::numeric_limits<float>::infinity());
            packet.hit.geomID[k] = RTC_INVALID_GEOMETRY_ID;
            packet.hit.instID[0][k] = RTC_INVALID_GEOMETRY_ID;
        }
        rtcIntersect8(valid.data(), rtcScene_, &context, &packet);
        for (size_t k = 0; k < count; ++k) {
            hits[first + k] = hitOf(packet.hit.instID[0][k], packet.hit.geomID[k], packet.hit.primID[k],
                                    packet.ray.tfar[k], packet.hit.u[k], packet.hit.v[k]);
        }
    }
}

void Scene::occluded(std::span<const Ray> rays, std::span<const float> distances, std::span<bool> blocked) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    context.flags = RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
    for (size_t first = 0; first < rays.size(); first += kPacket) {
        const size_t count = std::min(kPacket, rays.size() - first);
        alignas(32) const std::array<int, kPacket> valid = activeLanes(count);
        alignas(32) RTCRay8 packet;
        for (size_t k = 0; k < kPacket; ++k) {
            const size_t i = first + std::min(k, count - 1);
            setLane(packet, k, rays[i], distances[i]);
        }
        rtcOccluded8(valid.data(), rtcScene_, &context, &packet);
        // Embree marks a blocked ray by setting its tfar to -infinity.
        for (size_t k = 0; k < count; ++k) blocked[first + k] = packet.tfar[k] < 0.0f;
    }
}

// The surface record at a hit in a placed shared mesh, from its own coordinates to the world's.
// Apart from Scene::surface, so that a flat scene's hits pay a test and no more.
[[gnu::noinline]] void Scene::placeInWorld(SurfaceHit& hit, const Placement& placement) {
    // The point and its error bound through the affine map (pbrt-v4's Transform of a Point3fi):
    // the map's own rounding, gamma(3) of each row's terms, plus the bound carried through |M|.
    // Embree moves the ray into the shared mesh's coordinates and back as well; that rounding is
    // relative to the world's coordinates, which gamma(4) of the largest of the point's and the
    // translation's covers, as the local term in localSurface does.
    const glm::mat4& m = placement.toWorld;
    const glm::vec3 local = hit.point;
    const glm::mat3 linear(m);
    const glm::mat3 magnitude(magnitudes(linear[0]), magnitudes(linear[1]), magnitudes(linear[2]));
    const glm::vec3 translation(m[3]);
    hit.point = linear * local + translation;
    const glm::vec3 terms = magnitude * magnitudes(local) + magnitudes(translation);
    const float reach = glm::max(maxComponent(magnitudes(hit.point)), maxComponent(magnitudes(translation)));
    hit.pointError = gammaBound(3) * terms + (1.0f + gammaBound(3)) * (magnitude * hit.pointError) +
                     traversalError(reach);
    // Normals by the inverse transpose, which keeps the front side under a mirroring map (mesh.h).
    hit.normal = glm::normalize(placement.normalToWorld * hit.normal);
    hit.shadingNormal = hit.smooth ? glm::normalize(placement.normalToWorld * hit.shadingNormal) : hit.normal;
}

SurfaceHit Scene::surface(const RayHit& rayHit) const {
    SurfaceHit hit = localSurface(rayHit);
    if (rayHit.placement != kNoPlacement) [[unlikely]] placeInWorld(hit, placements_[rayHit.placement]);
    return hit;
}

SurfaceHit Scene::localSurface(const RayHit& rayHit) const {
    const uint32_t triangle = rayHit.triangle;
    const auto& tri = mesh_.triangles[triangle];
    const glm::vec3& p0 = mesh_.positions[tri[0]];
    const glm::vec3& p1 = mesh_.positions[tri[1]];
    const glm::vec3& p2 = mesh_.positions[tri[2]];
    const float b1 = rayHit.u;
    const float b2 = rayHit.v;
    const float b0 = 1.0f - b1 - b2;
    const glm::vec3 weighted0 = b0 * p0;
    const glm::vec3 weighted1 = b1 * p1;
    const glm::vec3 weighted2 = b2 * p2;
    SurfaceHit hit;
    hit.point = weighted0 + weighted1 + weighted2;
    // Rounding of the barycentric sum (pbrt-v4's bound), plus Embree's own error (rounding.h; the
    // fast test is kept to the scenes where that suffices, traversal_precision.h).
    const glm::vec3 largest = glm::max(glm::max(magnitudes(p0), magnitudes(p1)), magnitudes(p2));
    hit.pointError = gammaBound(7) * (magnitudes(weighted0) + magnitudes(weighted1) + magnitudes(weighted2)) +
                     traversalError(maxComponent(largest));
    // Component by component: copied whole, GCC 12 moves normal.z and the next field as one
    // 8-byte word through the stack, a load that store-to-load forwarding cannot serve (a stall
    // perf annotate showed on every ray, ~6% of the path tracer's time).
    const glm::vec3& normal = triangles_[triangle].normal;
    hit.normal.x = normal.x;
    hit.normal.y = normal.y;
    hit.normal.z = normal.z;
    hit.shadingNormal = hit.normal;
    hit.smooth = false;
    if (const std::optional<glm::vec3> interpolated = vertexNormalAt(triangle, b0, b1, b2)) {
        hit.shadingNormal = *interpolated;
        hit.smooth = true;
    }
    hit.uv = glm::vec2(0.0f);
    if (!mesh_.triangleUvs.empty() && mesh_.triangleUvs[triangle] != kNoUvs) {
        const auto& corners = mesh_.triangleUvs[triangle];
        hit.uv = b0 * mesh_.uvs[corners[0]] + b1 * mesh_.uvs[corners[1]] + b2 * mesh_.uvs[corners[2]];
        const MaterialTextures& textures = material(triangle).textures;
        if (textures.normal) {
            const auto tangents = surfaceTangents({p0, p1, p2}, cornerUvs(mesh_, triangle));
            if (tangents) {
                const glm::vec3 mapped =
                    mappedNormal(*textures.normal, textures.normalScale, hit.uv, hit.shadingNormal, *tangents);
                hit.smooth = hit.smooth || mapped != hit.shadingNormal;
                hit.shadingNormal = mapped;
            }
        }
    }
    hit.colour = glm::vec3(1.0f);
    if (!mesh_.triangleColours.empty() && mesh_.triangleColours[triangle] != kNoColours) {
        const auto& corners = mesh_.triangleColours[triangle];
        hit.colour = b0 * mesh_.colours[corners[0]] + b1 * mesh_.colours[corners[1]] + b2 * mesh_.colours[corners[2]];
    }
    hit.triangle = triangle;
    return hit;
}

std::optional<glm::vec3> Scene::vertexNormalAt(uint32_t triangle, float b0, float b1, float b2) const {
    if (mesh_.triangleNormals.empty() || mesh_.triangleNormals[triangle] == kNoNormals) return std::nullopt;
    const auto& corners = mesh_.triangleNormals[triangle];
    const glm::vec3 interpolated =
        b0 * mesh_.normals[corners[0]] + b1 * mesh_.normals[corners[1]] + b2 * mesh_.normals[corners[2]];
    const float length = glm::length(interpolated);
    // Opposed vertex normals can cancel; the geometric normal is the only sensible answer.
    if (!(length > 1e-6f)) return std::nullopt;
    return interpolated / length;
}

glm::vec3 Scene::coatNormal(const RayHit& rayHit, glm::vec2 uv) const {
    const uint32_t triangle = rayHit.triangle;
    glm::vec3 normal = vertexNormalAt(triangle, 1.0f - rayHit.u - rayHit.v, rayHit.u, rayHit.v)
                           .value_or(triangles_[triangle].normal);
    const MaterialTextures& textures = material(triangle).textures;
    if (textures.clearcoatNormal && !mesh_.triangleUvs.empty() && mesh_.triangleUvs[triangle] != kNoUvs) {
        const auto& tri = mesh_.triangles[triangle];
        const auto tangents = surfaceTangents({mesh_.positions[tri[0]], mesh_.positions[tri[1]], mesh_.positions[tri[2]]},
                                              cornerUvs(mesh_, triangle));
        if (tangents) {
            normal = mappedNormal(*textures.clearcoatNormal, textures.clearcoatNormalScale, uv, normal, *tangents);
        }
    }
    if (rayHit.placement == kNoPlacement) return normal;
    return glm::normalize(placements_[rayHit.placement].normalToWorld * normal);
}

glm::vec3 Scene::smoothSurfaceLift(const RayHit& rayHit, bool front) const {
    if (mesh_.triangleNormals.empty() || mesh_.triangleNormals[rayHit.triangle] == kNoNormals) return glm::vec3(0.0f);
    const auto& tri = mesh_.triangles[rayHit.triangle];
    const auto& corners = mesh_.triangleNormals[rayHit.triangle];
    const float side = front ? 1.0f : -1.0f;
    const glm::vec3 lift = strata::smoothSurfaceLift(
        {mesh_.positions[tri[0]], mesh_.positions[tri[1]], mesh_.positions[tri[2]]},
        {side * mesh_.normals[corners[0]], side * mesh_.normals[corners[1]], side * mesh_.normals[corners[2]]},
        glm::vec3(1.0f - rayHit.u - rayHit.v, rayHit.u, rayHit.v));
    // An affine map keeps a point on each vertex's tangent plane on that plane's image, so the
    // lift is mapped as a displacement is.
    if (rayHit.placement == kNoPlacement) return lift;
    return glm::mat3(placements_[rayHit.placement].toWorld) * lift;
}

bool Scene::occluded(const Ray& ray, float distance) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    context.flags = RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
    RTCRay r = embreeRay(ray, distance);
    rtcOccluded1(rtcScene_, &context, &r);
    return r.tfar < 0.0f;
}

glm::vec3 offsetRayOrigin(const SurfaceHit& hit, const glm::vec3& direction) {
    return offsetRayOrigin(hit.point, hit.pointError, hit.normal, direction);
}

}  // namespace strata
