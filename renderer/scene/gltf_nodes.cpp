#include "scene/gltf_nodes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <utility>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/matrix.hpp>

#include "scene/gltf_accessors.h"
#include "scene/gltf_cameras_lights.h"
#include "scene/gltf_materials.h"

namespace strata {
namespace {

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

// glTF 2.0, "Transformations": a node's matrix, else T * R * S (rotation a unit quaternion
// x, y, z, w).
glm::dmat4 localTransform(const GltfModel& gltf, const tinygltf::Node& node, int index) {
    const std::string name = "node " + std::to_string(index);
    if (!node.matrix.empty()) {
        if (node.matrix.size() != 16) gltf.fail(name + ": matrix needs 16 numbers");
        return glm::make_mat4(node.matrix.data());  // column-major, as glm's
    }
    glm::dmat4 transform(1.0);
    if (!node.translation.empty()) {
        if (node.translation.size() != 3) gltf.fail(name + ": translation needs 3 numbers");
        transform = glm::translate(transform, glm::make_vec3(node.translation.data()));
    }
    if (!node.rotation.empty()) {
        if (node.rotation.size() != 4) gltf.fail(name + ": rotation needs 4 numbers");
        const glm::dquat q(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
        if (!(glm::length(q) > 0.0)) gltf.fail(name + ": rotation is not a unit quaternion");
        transform *= glm::mat4_cast(glm::normalize(q));
    }
    if (!node.scale.empty()) {
        if (node.scale.size() != 3) gltf.fail(name + ": scale needs 3 numbers");
        transform = glm::scale(transform, glm::make_vec3(node.scale.data()));
    }
    return transform;
}

// The scene's nodes visited once each, their meshes' primitives appended in world space, their
// camera and lights taken.
class SceneBuilder {
public:
    SceneBuilder(GltfModel& gltf, SceneTextures& textures) : gltf_(gltf), textures_(textures) {}

    ParsedScene build() {
        for (size_t i = 0; i < gltf_.model.materials.size(); ++i) {
            parsed_.mesh.materials.push_back(gltfMaterial(gltf_, textures_, i));
        }
        visitNodes();
        // A flat scene keeps no per-triangle normal indices, one without UVs none (mesh.h).
        if (parsed_.mesh.normals.empty()) parsed_.mesh.triangleNormals.clear();
        if (parsed_.mesh.uvs.empty()) parsed_.mesh.triangleUvs.clear();
        if (parsed_.camera) aimGltfCameraAtScene(*parsed_.camera, parsed_.mesh.positions);
        return std::move(parsed_);
    }

    size_t dropped() const { return dropped_; }

private:
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
            if (node.mesh >= 0) addMesh(node.mesh, world);
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
    // of each mode); points and lines have no surface to render.
    std::vector<uint32_t> triangleCorners(int mode, const std::vector<uint32_t>& vertices,
                                          const std::string& where) const {
        std::vector<uint32_t> corners;
        const size_t n = vertices.size();
        switch (mode) {
            case TINYGLTF_MODE_TRIANGLES:
                if (n % 3 != 0) fail(where + ": " + std::to_string(n) + " vertices do not make whole triangles");
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
            default: {
                static const std::array<const char*, 4> names{"points", "lines", "line loop", "line strip"};
                const std::string name = mode >= 0 && mode < 4 ? names[static_cast<size_t>(mode)] : "unknown";
                fail(where + ": mode " + std::to_string(mode) + " (" + name +
                     ") is not a surface; Strata renders triangles, strips and fans");
            }
        }
    }

    void addMesh(int meshIndex, const glm::dmat4& world) {
        const tinygltf::Mesh& gltfMesh = element(gltf_.model.meshes, meshIndex, "mesh");
        // glTF 2.0, "Transformations" and "Meshes": normals go by the inverse transpose, and a
        // negative determinant turns counter-clockwise into clockwise.
        const glm::dmat3 linear(world);
        const glm::dmat3 normalTransform = glm::transpose(glm::inverse(linear));
        const bool mirrored = glm::determinant(linear) < 0.0;
        MeshData& mesh = parsed_.mesh;
        for (size_t p = 0; p < gltfMesh.primitives.size(); ++p) {
            const tinygltf::Primitive& primitive = gltfMesh.primitives[p];
            const std::string where = "mesh '" + gltfMesh.name + "' (" + std::to_string(meshIndex) +
                                      ") primitive " + std::to_string(p);
            const auto position = primitive.attributes.find("POSITION");
            if (position == primitive.attributes.end()) {
                // glTF 2.0, "Meshes": a primitive without positions should not be rendered.
                warnOnce("primitives without POSITION are skipped");
                continue;
            }
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
            std::vector<uint32_t> vertices;
            if (primitive.indices >= 0) {
                vertices = accessorIndices(gltf_, primitive.indices, vertexCount, where);
            } else {
                for (size_t v = 0; v < vertexCount; ++v) vertices.push_back(static_cast<uint32_t>(v));
            }
            const std::vector<uint32_t> corners = triangleCorners(primitive.mode, vertices, where);
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
            for (size_t v = 0; v < texCoords.size() / 2; ++v) {
                mesh.uvs.emplace_back(static_cast<float>(texCoords[2 * v]), static_cast<float>(1.0 - texCoords[2 * v + 1]));
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
                mesh.triangleUvs.push_back(texCoords.empty() ? kNoUvs
                                                             : std::array<uint32_t, 3>{firstUv + corner[0], firstUv + corner[1],
                                                                                       firstUv + corner[2]});
            }
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
    ParsedScene parsed_;
    std::optional<uint32_t> defaultMaterial_;
    size_t dropped_ = 0;
};

}  // namespace

ParsedScene flattenGltfScene(GltfModel& gltf, SceneTextures& textures, size_t& dropped) {
    SceneBuilder builder(gltf, textures);
    ParsedScene parsed = builder.build();
    dropped = builder.dropped();
    return parsed;
}

}  // namespace strata
