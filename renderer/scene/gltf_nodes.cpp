#include "scene/gltf_nodes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <set>
#include <optional>
#include <utility>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/matrix.hpp>

#include "lights/scene_lights.h"
#include "scene/gltf_accessors.h"
#include "scene/gltf_cameras_lights.h"
#include "scene/gltf_materials.h"

namespace strata {
namespace {

// Counts that a file's claims can make as large as they like: held at the largest count rather
// than wrapped around, so that the budget sees them.
uint64_t saturatingAdd(uint64_t a, uint64_t b) {
    uint64_t sum;
    return __builtin_add_overflow(a, b, &sum) ? UINT64_MAX : sum;
}
uint64_t saturatingProduct(uint64_t a, uint64_t b) {
    uint64_t product;
    return __builtin_mul_overflow(a, b, &product) ? UINT64_MAX : product;
}

bool isFinite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

bool isFinite(const glm::dmat4& m) {
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) {
            if (!std::isfinite(m[c][r])) return false;
        }
    }
    return true;
}

// The scene's root nodes: the default scene's, else the first scene's; without scenes, every
// node that is no other's child (glTF 2.0, "Scenes": a file need not say which to show).
std::vector<int> rootNodes(const GltfModel& gltf) {
    if (gltf.model.defaultScene >= 0) return gltf.element(gltf.model.scenes, gltf.model.defaultScene, "default scene").nodes;
    if (!gltf.model.scenes.empty()) return gltf.model.scenes.front().nodes;
    std::vector<bool> isChild(gltf.model.nodes.size(), false);
    for (const tinygltf::Node& node : gltf.model.nodes) {
        for (int child : node.children) {
            if (child >= 0 && static_cast<size_t>(child) < isChild.size()) isChild[static_cast<size_t>(child)] = true;
        }
    }
    std::vector<int> roots;
    for (size_t i = 0; i < gltf.model.nodes.size(); ++i) {
        if (!isChild[i]) roots.push_back(static_cast<int>(i));
    }
    return roots;
}

// glTF 2.0, "Transformations": T * R * S, the rotation a quaternion (x, y, z, w) normalised;
// nothing where it has no length.
std::optional<glm::dmat4> composeTrs(const glm::dvec3& translation, const glm::dquat& rotation, const glm::dvec3& scale) {
    if (!(glm::length(rotation) > 0.0)) return std::nullopt;
    return glm::scale(glm::translate(glm::dmat4(1.0), translation) * glm::mat4_cast(glm::normalize(rotation)), scale);
}

// glTF 2.0, "Transformations": a node's matrix, else T * R * S.
glm::dmat4 localTransform(const GltfModel& gltf, const tinygltf::Node& node, int index) {
    const std::string name = "node " + std::to_string(index);
    if (!node.matrix.empty()) {
        if (node.matrix.size() != 16) gltf.fail(name + ": matrix needs 16 numbers");
        return glm::make_mat4(node.matrix.data());  // column-major, as glm's
    }
    glm::dvec3 translation(0.0);
    glm::dquat rotation(1.0, 0.0, 0.0, 0.0);
    glm::dvec3 scale(1.0);
    if (!node.translation.empty()) {
        if (node.translation.size() != 3) gltf.fail(name + ": translation needs 3 numbers");
        translation = glm::make_vec3(node.translation.data());
    }
    if (!node.rotation.empty()) {
        if (node.rotation.size() != 4) gltf.fail(name + ": rotation needs 4 numbers");
        rotation = glm::dquat(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
    }
    if (!node.scale.empty()) {
        if (node.scale.size() != 3) gltf.fail(name + ": scale needs 3 numbers");
        scale = glm::make_vec3(node.scale.data());
    }
    const auto transform = composeTrs(translation, rotation, scale);
    if (!transform) gltf.fail(name + ": rotation is not a unit quaternion");
    return *transform;
}

// EXT_mesh_gpu_instancing on a node: its mesh is drawn once per instance, at the node's world
// transform times the instance's T * R * S, and not at the node itself. The attributes' accessors
// (-1: absent, the identity's part) and the instances' count, which all of them share.
struct GpuInstances {
    int translation = -1;
    int rotation = -1;
    int scale = -1;
    size_t count = 0;
};

std::optional<GpuInstances> gpuInstancesOf(GltfModel& gltf, const tinygltf::Node& node, int index) {
    const auto extension = node.extensions.find("EXT_mesh_gpu_instancing");
    if (extension == node.extensions.end()) return std::nullopt;
    const std::string name = "node " + std::to_string(index) + ": EXT_mesh_gpu_instancing";
    if (node.mesh < 0) {
        gltf.warnOnce("EXT_mesh_gpu_instancing on a node without a mesh places nothing; ignored");
        return std::nullopt;
    }
    // tinygltf reads an empty object as no value, as it reads a missing one: both have no accessor.
    const tinygltf::Value& attributes = extension->second.Get("attributes");
    if (!attributes.IsObject() && attributes.Type() != tinygltf::NULL_TYPE) gltf.fail(name + " needs an attributes object");
    GpuInstances instances;
    std::optional<std::pair<const char*, size_t>> counted;  // the first accessor's name and count
    for (const auto& [attribute, accessor] : {std::pair{"TRANSLATION", &instances.translation},
                                              std::pair{"ROTATION", &instances.rotation},
                                              std::pair{"SCALE", &instances.scale}}) {
        if (!attributes.Has(attribute)) continue;
        const tinygltf::Value& value = attributes.Get(attribute);
        if (!value.IsInt()) gltf.fail(name + ": " + attribute + " is not an accessor index");
        *accessor = value.GetNumberAsInt();
        const size_t count = gltf.element(gltf.model.accessors, *accessor, name + ": " + attribute + " accessor").count;
        if (counted && count != counted->second) {
            gltf.fail(name + ": " + attribute + " has " + std::to_string(count) + " elements, " + counted->first +
                      " " + std::to_string(counted->second) + "; every attribute needs one per instance");
        }
        counted = {attribute, count};
    }
    if (!counted) gltf.fail(name + " has no TRANSLATION, ROTATION or SCALE accessor");
    instances.count = counted->second;
    return instances;
}

// What makes two of a file's primitives the same geometry: their POSITION, NORMAL, TEXCOORD_0
// and COLOR_0 accessors, their indices (-1 for none), mode and material.
using PrimitiveKey = std::array<int, 7>;

PrimitiveKey keyOf(const tinygltf::Primitive& primitive) {
    const auto attribute = [&](const char* name) {
        const auto it = primitive.attributes.find(name);
        return it == primitive.attributes.end() ? -1 : it->second;
    };
    return {attribute("POSITION"), attribute("NORMAL"), attribute("TEXCOORD_0"), attribute("COLOR_0"),
            primitive.indices, primitive.mode, primitive.material};
}

// A node with a mesh, at its world transform: a use of each of the mesh's primitives, or with
// GPU instances one per instance. Kept per node, not per use, so that a small file of many
// primitives on many nodes, or of many instances, costs no more memory here than its nodes do in
// tinygltf before the budget has been checked.
struct MeshNode {
    int mesh;
    glm::dmat4 world;
    std::optional<GpuInstances> instances;

    size_t useCount() const { return instances ? instances->count : 1; }
};

// The scene's nodes visited once each, their camera and lights taken, their meshes' primitives
// appended: in world space where a primitive is used once, else once in its own coordinates as a
// shared mesh (mesh.h) placed at each node that uses it.
class SceneBuilder {
public:
    SceneBuilder(GltfModel& gltf, SceneTextures& textures, const SceneBudget& budget)
        : gltf_(gltf), textures_(textures), budget_(budget) {}

    ParsedScene build() {
        for (size_t i = 0; i < gltf_.model.materials.size(); ++i) {
            parsed_.mesh.materials.push_back(gltfMaterial(gltf_, textures_, i));
            uvTransforms_.push_back(gltfTextureTransform(gltf_, i));
        }
        visitNodes();
        addPrimitives();
        if (parsed_.mesh.triangles.empty()) refuseEmpty();
        // A flat scene keeps no per-triangle normal indices, one without UVs none (mesh.h).
        if (parsed_.mesh.normals.empty()) parsed_.mesh.triangleNormals.clear();
        if (parsed_.mesh.uvs.empty()) parsed_.mesh.triangleUvs.clear();
        if (parsed_.mesh.colours.empty()) parsed_.mesh.triangleColours.clear();
        if (parsed_.camera) aimGltfCameraAtScene(*parsed_.camera, parsed_.mesh);
        return std::move(parsed_);
    }

    size_t dropped() const { return dropped_; }

private:
    // A scene left without triangles, refused by what left it so (else the scene's loader says
    // it has no usable triangles).
    void refuseEmpty() const {
        if (outOfRange_ > 0) fail("every triangle uses an index past its primitive's vertices; nothing is left");
        if (hasPoints_ || hasLines_) {
            const char* kinds = hasPoints_ && hasLines_ ? "points and lines" : hasPoints_ ? "points" : "lines";
            fail(std::string("the file holds only ") + kinds +
                 ", no surfaces; Strata renders triangles, strips and fans");
        }
    }

    [[noreturn]] void fail(const std::string& message) const { gltf_.fail(message); }
    void warnOnce(const std::string& message) { gltf_.warnOnce(message); }
    template <typename T>
    const T& element(const std::vector<T>& list, int index, const std::string& what) const {
        return gltf_.element(list, index, what);
    }

    // Depth first from the roots with a stack of its own, so that no depth of hierarchy can
    // overflow the call stack. glTF 2.0, "Nodes and Hierarchy": the nodes form disjoint strict
    // trees, so a node reached twice (a cycle, or two parents) is an error.
    void visitNodes() {
        const std::vector<int> roots = rootNodes(gltf_);
        std::vector<std::pair<int, glm::dmat4>> pending;
        for (auto it = roots.rbegin(); it != roots.rend(); ++it) pending.emplace_back(*it, glm::dmat4(1.0));
        std::vector<bool> visited(gltf_.model.nodes.size(), false);
        while (!pending.empty()) {
            const auto [index, parent] = pending.back();
            pending.pop_back();
            const tinygltf::Node& node = element(gltf_.model.nodes, index, "node");
            if (visited[static_cast<size_t>(index)]) {
                fail("node " + std::to_string(index) + " is reached twice: the node hierarchy is not a tree");
            }
            visited[static_cast<size_t>(index)] = true;
            const glm::dmat4 world = parent * localTransform(gltf_, node, index);
            if (!isFinite(world)) fail("node " + std::to_string(index) + " has a non-finite transform");
            std::optional<GpuInstances> instances = gpuInstancesOf(gltf_, node, index);
            if (node.mesh >= 0) {
                element(gltf_.model.meshes, node.mesh, "mesh");
                meshNodes_.push_back({node.mesh, world, instances});
            }
            if (node.camera >= 0) takeGltfCamera(gltf_, node.camera, world, parsed_.camera);
            if (const auto it = node.extensions.find("KHR_lights_punctual"); it != node.extensions.end()) {
                const tinygltf::Value& light = it->second.Get("light");
                if (!light.IsInt()) fail("node " + std::to_string(index) + ": KHR_lights_punctual needs a light index");
                addGltfLight(gltf_, light.GetNumberAsInt(), world, parsed_.mesh);
            }
            for (auto child = node.children.rbegin(); child != node.children.rend(); ++child) {
                pending.emplace_back(*child, world);
            }
        }
    }

    // The corners of a primitive's triangles, three by three (glTF 2.0, "Meshes": the topology
    // of each mode); vertices that make no whole triangle are left out with a warning, as assimp
    // does.
    std::vector<uint32_t> triangleCorners(int mode, std::vector<uint32_t> vertices, const std::string& where) {
        std::vector<uint32_t> corners;
        const size_t n = vertices.size();
        switch (mode) {
            case TINYGLTF_MODE_TRIANGLES:
                if (n % 3 != 0) {
                    warnOnce(where + ": " + std::to_string(n) + " vertices do not make whole triangles; the last " +
                             std::to_string(n % 3) + " left out");
                    vertices.resize(n - n % 3);
                }
                return vertices;
            case TINYGLTF_MODE_TRIANGLE_STRIP:
                for (size_t i = 0; i + 2 < n; ++i) {
                    // Every other triangle reversed, so that all keep the strip's winding.
                    corners.insert(corners.end(), {vertices[i], vertices[i + 1 + i % 2], vertices[i + 2 - i % 2]});
                }
                return corners;
            case TINYGLTF_MODE_TRIANGLE_FAN:
                for (size_t i = 0; i + 2 < n; ++i) {
                    corners.insert(corners.end(), {vertices[i + 1], vertices[i + 2], vertices[0]});
                }
                return corners;
            default:
                fail(where + ": mode " + std::to_string(mode) + " is not a glTF primitive mode");
        }
    }

    // Whether the primitive is points or lines, which have no surface to render: skipped with a
    // warning, and noted for the message of a file that has nothing else.
    bool skippedAsNoSurface(int mode) {
        if (mode == TINYGLTF_MODE_POINTS) {
            hasPoints_ = true;
        } else if (mode == TINYGLTF_MODE_LINE || mode == TINYGLTF_MODE_LINE_LOOP || mode == TINYGLTF_MODE_LINE_STRIP) {
            hasLines_ = true;
        } else {
            return false;
        }
        warnOnce("points and lines are not surfaces; their primitives are skipped");
        return true;
    }

    // The triangles a primitive will have, by its accessors' counts, before any is read; 0 where
    // reading it will fail (and say why).
    uint64_t triangleCount(const tinygltf::Primitive& primitive) const {
        const auto& accessors = gltf_.model.accessors;
        const auto position = primitive.attributes.find("POSITION");
        const int counted = primitive.indices >= 0 ? primitive.indices
                                                   : (position == primitive.attributes.end() ? -1 : position->second);
        if (counted < 0 || static_cast<size_t>(counted) >= accessors.size()) return 0;
        const uint64_t n = accessors[static_cast<size_t>(counted)].count;
        switch (primitive.mode) {
            case TINYGLTF_MODE_TRIANGLES: return n / 3;
            case TINYGLTF_MODE_TRIANGLE_STRIP:
            case TINYGLTF_MODE_TRIANGLE_FAN: return n < 3 ? 0 : n - 2;
            default: return 0;
        }
    }

    bool emits(const tinygltf::Primitive& primitive) const {
        const int m = primitive.material;
        return m >= 0 && static_cast<size_t>(m) < parsed_.mesh.materials.size() &&
               emitsLight(parsed_.mesh.materials[static_cast<size_t>(m)]);
    }

    // f(world) for each world transform at which `node` draws its mesh: the node's own, or one per
    // GPU instance, its T * R * S read from the accessors now (after the budget's check).
    template <typename F>
    void forEachWorld(const MeshNode& node, F f) const {
        if (!node.instances) {
            f(node.world);
            return;
        }
        const GpuInstances& instances = *node.instances;
        const std::string where = "mesh '" + gltf_.model.meshes[static_cast<size_t>(node.mesh)].name + "' (" +
                                  std::to_string(node.mesh) + ") EXT_mesh_gpu_instancing";
        const auto values = [&](int accessor, AccessorUse use) {
            return accessor < 0 ? std::vector<double>() : accessorValues(gltf_, accessor, use, where);
        };
        const std::vector<double> translations = values(instances.translation, AccessorUse::InstanceTranslation);
        const std::vector<double> rotations = values(instances.rotation, AccessorUse::InstanceRotation);
        const std::vector<double> scales = values(instances.scale, AccessorUse::InstanceScale);
        for (size_t i = 0; i < instances.count; ++i) {
            const glm::dvec3 translation = translations.empty() ? glm::dvec3(0.0) : glm::make_vec3(&translations[3 * i]);
            const glm::dquat rotation = rotations.empty() ? glm::dquat(1.0, 0.0, 0.0, 0.0)
                                                          : glm::dquat(rotations[4 * i + 3], rotations[4 * i],
                                                                       rotations[4 * i + 1], rotations[4 * i + 2]);
            const glm::dvec3 scale = scales.empty() ? glm::dvec3(1.0) : glm::make_vec3(&scales[3 * i]);
            const auto transform = composeTrs(translation, rotation, scale);
            if (!transform) fail(where + ": instance " + std::to_string(i) + "'s ROTATION is not a unit quaternion");
            f(node.world * *transform);
        }
    }

    // Every primitive use, in the order of the nodes and their instances: a primitive used once
    // in world space, as before instancing, so that a flat file loads as it always has; one used
    // more often once in its own coordinates, where first used, with a placement for each use
    // (the emitting ones are placed into the world by the scene, each use's a copy: scene.h). The
    // budget is checked first, from the accessors' counts, before any geometry or instance is read.
    void addPrimitives() {
        // f(mesh, primitive index, uses) for every node's primitives, in order.
        const auto forEachPrimitive = [&](auto f) {
            for (const MeshNode& node : meshNodes_) {
                const tinygltf::Mesh& mesh = gltf_.model.meshes[static_cast<size_t>(node.mesh)];
                for (size_t p = 0; p < mesh.primitives.size(); ++p) f(node.mesh, p, node.useCount());
            }
        };
        const auto primitiveOf = [&](int mesh, size_t p) -> const tinygltf::Primitive& {
            return gltf_.model.meshes[static_cast<size_t>(mesh)].primitives[p];
        };
        std::map<PrimitiveKey, uint64_t> uses;
        forEachPrimitive([&](int mesh, size_t p, uint64_t n) {
            uint64_t& used = uses[keyOf(primitiveOf(mesh, p))];
            used = saturatingAdd(used, n);
        });
        TriangleCount count;
        std::set<PrimitiveKey> counted;
        forEachPrimitive([&](int mesh, size_t p, uint64_t n) {
            if (n == 0) return;
            const tinygltf::Primitive& primitive = primitiveOf(mesh, p);
            const PrimitiveKey key = keyOf(primitive);
            const uint64_t triangles = triangleCount(primitive);
            // An emitting primitive is placed into the world at each use, as a copy (scene.h).
            const bool instanced = uses[key] > 1 && !emits(primitive);
            count.placed = saturatingAdd(count.placed, saturatingProduct(triangles, n));
            if (instanced) count.placements = saturatingAdd(count.placements, n);
            if (!instanced) {
                count.stored = saturatingAdd(count.stored, saturatingProduct(triangles, n));
            } else if (counted.insert(key).second) {
                count.stored = saturatingAdd(count.stored, triangles);
            }
        });
        checkTriangleBudget(gltf_.path, count, budget_);

        // Each shared primitive's index in the mesh's shared meshes (SIZE_MAX: it has no triangles)
        // and how many of its triangles are degenerate.
        struct Shared {
            size_t index = SIZE_MAX;
            size_t degenerate = 0;
        };
        std::map<PrimitiveKey, Shared> sharedMeshes;
        MeshData& meshData = parsed_.mesh;
        const auto addUse = [&](int mesh, size_t p, const glm::dmat4& world) {
            const PrimitiveKey key = keyOf(primitiveOf(mesh, p));
            if (uses[key] == 1) {
                addPrimitive(mesh, p, world);
                return;
            }
            const auto [it, first] = sharedMeshes.try_emplace(key);
            Shared& shared = it->second;
            if (first) {
                const auto firstTriangle = static_cast<uint32_t>(meshData.triangles.size());
                const size_t droppedBefore = dropped_;
                addPrimitive(mesh, p, glm::dmat4(1.0));
                shared.degenerate = dropped_ - droppedBefore;
                const auto triangles = static_cast<uint32_t>(meshData.triangles.size() - firstTriangle);
                if (triangles > 0) {
                    shared.index = meshData.sharedMeshes.size();
                    meshData.sharedMeshes.push_back({firstTriangle, triangles, {}});
                }
            } else {
                dropped_ += shared.degenerate;  // each use leaves out what flattening it would
            }
            if (shared.index == SIZE_MAX) return;
            SharedMesh& sharedMesh = meshData.sharedMeshes[shared.index];
            // A placement that flattens the primitive makes every triangle degenerate.
            const glm::mat4 placement(world);
            if (!std::isnormal(glm::determinant(glm::mat3(placement)))) {
                dropped_ += sharedMesh.triangleCount;
                return;
            }
            sharedMesh.placements.push_back(placement);
        };
        for (const MeshNode& node : meshNodes_) {
            const size_t primitives = gltf_.model.meshes[static_cast<size_t>(node.mesh)].primitives.size();
            forEachWorld(node, [&](const glm::dmat4& world) {
                for (size_t p = 0; p < primitives; ++p) addUse(node.mesh, p, world);
            });
        }
    }

    // The primitive's triangles appended, at `world`.
    void addPrimitive(int meshIndex, size_t p, const glm::dmat4& world) {
        const tinygltf::Mesh& gltfMesh = gltf_.model.meshes[static_cast<size_t>(meshIndex)];
        // glTF 2.0, "Transformations" and "Meshes": normals go by the inverse transpose, and a
        // negative determinant turns counter-clockwise into clockwise.
        const glm::dmat3 linear(world);
        const glm::dmat3 normalTransform = glm::transpose(glm::inverse(linear));
        const bool mirrored = glm::determinant(linear) < 0.0;
        MeshData& mesh = parsed_.mesh;
        const tinygltf::Primitive& primitive = gltfMesh.primitives[p];
        const std::string where = "mesh '" + gltfMesh.name + "' (" + std::to_string(meshIndex) +
                                  ") primitive " + std::to_string(p);
        const auto position = primitive.attributes.find("POSITION");
        if (position == primitive.attributes.end()) {
            // glTF 2.0, "Meshes": a primitive without positions should not be rendered.
            warnOnce("primitives without POSITION are skipped");
            return;
        }
        if (skippedAsNoSurface(primitive.mode)) return;
        const std::vector<double> positions = accessorValues(gltf_, position->second, AccessorUse::Position, where);
        const size_t vertexCount = positions.size() / 3;
        std::vector<double> normals;
        if (const auto normal = primitive.attributes.find("NORMAL"); normal != primitive.attributes.end()) {
            normals = accessorValues(gltf_, normal->second, AccessorUse::Normal, where);
            if (normals.size() != positions.size()) {
                fail(where + ": NORMAL has " + std::to_string(normals.size() / 3) + " elements, POSITION " +
                     std::to_string(vertexCount));
            }
        }
        // TEXCOORD_0 with v turned up (texture.h's convention; glTF's v runs down).
        std::vector<double> texCoords;
        if (const auto uv = primitive.attributes.find("TEXCOORD_0"); uv != primitive.attributes.end()) {
            texCoords = accessorValues(gltf_, uv->second, AccessorUse::TexCoord, where);
            if (texCoords.size() / 2 != vertexCount) {
                fail(where + ": TEXCOORD_0 has " + std::to_string(texCoords.size() / 2) + " elements, POSITION " +
                     std::to_string(vertexCount));
            }
        }
        // COLOR_0, RGB or RGBA: glTF 2.0, "Meshes", multiplies the base colour by RGB. Its alpha
        // would multiply the base colour's, which Strata reads only from a MASK texture; not read.
        std::vector<double> colours;
        size_t colourComponents = 0;
        if (const auto colour = primitive.attributes.find("COLOR_0"); colour != primitive.attributes.end()) {
            colours = accessorValues(gltf_, colour->second, AccessorUse::Colour, where);
            const int type = gltf_.model.accessors[static_cast<size_t>(colour->second)].type;
            colourComponents = static_cast<size_t>(tinygltf::GetNumComponentsInType(static_cast<uint32_t>(type)));
            if (colours.size() / colourComponents != vertexCount) {
                fail(where + ": COLOR_0 has " + std::to_string(colours.size() / colourComponents) +
                     " elements, POSITION " + std::to_string(vertexCount));
            }
        }
        // An index past the vertices leaves out the triangles that use it, with a warning, as
        // assimp does (kIndexOutOfRange marks it until the triangles are made).
        std::vector<uint32_t> vertices;
        if (primitive.indices >= 0) {
            vertices = accessorIndices(gltf_, primitive.indices, vertexCount, where);
        } else {
            for (size_t v = 0; v < vertexCount; ++v) vertices.push_back(static_cast<uint32_t>(v));
        }
        const std::vector<uint32_t> made = triangleCorners(primitive.mode, std::move(vertices), where);
        std::vector<uint32_t> corners;
        for (auto first = made.begin(); first != made.end(); first += 3) {
            if (std::find(first, first + 3, kIndexOutOfRange) == first + 3) corners.insert(corners.end(), first, first + 3);
        }
        if (corners.size() < made.size()) {
            const size_t left = (made.size() - corners.size()) / 3;
            warnOnce(where + ": " + std::to_string(left) + " of " + std::to_string(made.size() / 3) +
                     (left == 1 ? " triangles uses" : " triangles use") + " an index past its " +
                     std::to_string(vertexCount) + " vertices; left out");
            outOfRange_ += left;
        }
        const uint32_t material = materialOf(primitive.material);

        const auto firstVertex = static_cast<uint32_t>(mesh.positions.size());
        if (mesh.positions.size() + vertexCount > std::numeric_limits<uint32_t>::max()) {
            fail("more than 2^32 vertices");
        }
        for (size_t v = 0; v < vertexCount; ++v) {
            const glm::dvec4 p(positions[3 * v], positions[3 * v + 1], positions[3 * v + 2], 1.0);
            mesh.positions.emplace_back(glm::dvec3(world * p));
        }
        const auto firstNormal = static_cast<uint32_t>(mesh.normals.size());
        for (size_t v = 0; v < normals.size() / 3; ++v) {
            const glm::dvec3 n = normalTransform * glm::dvec3(normals[3 * v], normals[3 * v + 1], normals[3 * v + 2]);
            // A zero normal marks its triangles flat below.
            mesh.normals.emplace_back(glm::length(n) > 0.0 ? glm::normalize(n) : glm::dvec3(0.0));
        }
        const auto firstUv = static_cast<uint32_t>(mesh.uvs.size());
        // The material's KHR_texture_transform, in glTF's UV coordinates (gltf_materials.h).
        const glm::dmat3 uvTransform =
            primitive.material >= 0 ? uvTransforms_[static_cast<size_t>(primitive.material)] : glm::dmat3(1.0);
        for (size_t v = 0; v < texCoords.size() / 2; ++v) {
            const glm::dvec3 uv = uvTransform * glm::dvec3(texCoords[2 * v], texCoords[2 * v + 1], 1.0);
            mesh.uvs.emplace_back(static_cast<float>(uv.x), static_cast<float>(1.0 - uv.y));
        }
        const auto firstColour = static_cast<uint32_t>(mesh.colours.size());
        for (size_t v = 0; v < colours.size(); v += colourComponents) {
            mesh.colours.emplace_back(glm::clamp(glm::dvec3(colours[v], colours[v + 1], colours[v + 2]), 0.0, 1.0));
        }
        for (size_t c = 0; c < corners.size(); c += 3) {
            std::array<uint32_t, 3> corner{corners[c], corners[c + 1], corners[c + 2]};
            if (mirrored) std::swap(corner[1], corner[2]);
            const std::array<uint32_t, 3> triangle{firstVertex + corner[0], firstVertex + corner[1],
                                                   firstVertex + corner[2]};
            const glm::vec3& a = mesh.positions[triangle[0]];
            const glm::vec3 n = glm::cross(mesh.positions[triangle[1]] - a, mesh.positions[triangle[2]] - a);
            if (!isFinite(glm::dvec3(n)) || !(glm::dot(n, n) > 0.0f)) {
                ++dropped_;
                continue;
            }
            mesh.triangles.push_back(triangle);
            mesh.triangleMaterials.push_back(material);
            // glTF 2.0, "Meshes": without normals a triangle is flat.
            const std::array<uint32_t, 3> triangleNormals{firstNormal + corner[0], firstNormal + corner[1],
                                                          firstNormal + corner[2]};
            const bool shaded = !normals.empty() &&
                                std::none_of(triangleNormals.begin(), triangleNormals.end(), [&](uint32_t i) {
                                    return mesh.normals[i] == glm::vec3(0.0f);
                                });
            mesh.triangleNormals.push_back(shaded ? triangleNormals : kNoNormals);
            mesh.triangleColours.push_back(colours.empty() ? kNoColours
                                                           : std::array<uint32_t, 3>{firstColour + corner[0],
                                                                                     firstColour + corner[1],
                                                                                     firstColour + corner[2]});
            mesh.triangleUvs.push_back(texCoords.empty() ? kNoUvs
                                                         : std::array<uint32_t, 3>{firstUv + corner[0], firstUv + corner[1],
                                                                                   firstUv + corner[2]});
        }
    }

    // The material of a primitive: its own, or the spec's default for one without ("Materials":
    // base colour 1, metallic 1, roughness 1), added once when first needed.
    uint32_t materialOf(int index) {
        if (index >= 0) {
            element(gltf_.model.materials, index, "material");
            return static_cast<uint32_t>(index);
        }
        if (!defaultMaterial_) {
            defaultMaterial_ = static_cast<uint32_t>(parsed_.mesh.materials.size());
            parsed_.mesh.materials.push_back(gltfDefaultMaterial());
        }
        return *defaultMaterial_;
    }

    GltfModel& gltf_;
    SceneTextures& textures_;
    const SceneBudget& budget_;
    std::vector<MeshNode> meshNodes_;
    std::vector<glm::dmat3> uvTransforms_;  // by material
    ParsedScene parsed_;
    std::optional<uint32_t> defaultMaterial_;
    size_t dropped_ = 0;
    size_t outOfRange_ = 0;  // triangles left out for an index past their vertices
    bool hasPoints_ = false;
    bool hasLines_ = false;
};

}  // namespace

ParsedScene buildGltfScene(GltfModel& gltf, SceneTextures& textures, const SceneBudget& budget, size_t& dropped) {
    SceneBuilder builder(gltf, textures, budget);
    ParsedScene parsed = builder.build();
    dropped = builder.dropped();
    return parsed;
}

}  // namespace strata
