#include "scene/gltf_loader.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string_view>
#include <utility>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>
#include <nlohmann/json.hpp>

#include "util/error.h"
#include "util/text_file.h"

// tinygltf's implementation lives in this file alone. Strata writes no glTF, and every file it
// reads comes through the callbacks below (the bundle, when parsing), never its own file access.
#define TINYGLTF_IMPLEMENTATION
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_FS
#include <fstream>  // tinygltf's writer needs it even with TINYGLTF_NO_FS, and does not include it then
#include <tiny_gltf.h>

namespace strata {
namespace {

// The extensions whose every requirement Strata meets; another one in extensionsRequired means
// the file cannot be rendered as its author meant (glTF 2.0, "Specifying Extensions").
constexpr std::array<std::string_view, 3> kImplementedExtensions{
    "KHR_lights_punctual", "KHR_materials_emissive_strength", "KHR_mesh_quantization"};

// The files of a .gltf's URIs while reading: from its folder, each kept for the bundle.
struct FolderFiles {
    std::filesystem::path folder;
    std::vector<SceneFile> read;
};

bool folderFileExists(const std::string& name, void* files) {
    return std::filesystem::is_regular_file(static_cast<FolderFiles*>(files)->folder / name);
}

bool readFolderFile(std::vector<unsigned char>* out, std::string* err, const std::string& name,
                    void* files) {
    auto& folder = *static_cast<FolderFiles*>(files);
    auto it = std::find_if(folder.read.begin(), folder.read.end(),
                           [&](const SceneFile& file) { return file.name == name; });
    if (it == folder.read.end()) {
        try {
            folder.read.push_back({name, readTextFile(folder.folder / name, "file")});
        } catch (const Error& error) {
            *err = error.what();
            return false;
        }
        it = folder.read.end() - 1;
    }
    out->assign(it->bytes.begin(), it->bytes.end());
    return true;
}

// The same files while parsing: from the bundle only.
bool bundleFileExists(const std::string& name, void* bundle) {
    return static_cast<const SceneBundle*>(bundle)->find(name) != nullptr;
}

bool readBundleFile(std::vector<unsigned char>* out, std::string* /*err*/, const std::string& name,
                    void* bundle) {
    const SceneFile* file = static_cast<const SceneBundle*>(bundle)->find(name);
    if (!file) return false;
    out->assign(file->bytes.begin(), file->bytes.end());
    return true;
}

std::string sameName(const std::string& name, void*) { return name; }

// Images are not decoded until Strata has textures: their bytes are read (so that the bundle
// holds them) and dropped.
bool keepNoImage(tinygltf::Image*, const int, std::string*, std::string*, int, int,
                 const unsigned char*, int, void*) {
    return true;
}

std::string firstLine(const std::string& text) {
    const size_t start = text.find_first_not_of(" \n\r");
    if (start == std::string::npos) return "";
    return text.substr(start, text.find_first_of("\n\r", start) - start);
}

// The JSON of a glTF file: all of it, or a binary file's first chunk (glTF 2.0, "Binary glTF
// Layout": a 12-byte header, then the JSON chunk's length and type).
std::string_view jsonOf(const std::string& bytes, bool binary) {
    if (!binary) return bytes;
    if (bytes.size() < 20) return {};
    uint32_t length;
    std::memcpy(&length, bytes.data() + 12, sizeof length);
    return std::string_view(bytes).substr(20, length);
}

// Refuses a file that requires an extension Strata does not implement, before tinygltf reads
// what the extension encodes (a Draco-compressed primitive's accessors have no buffer view, say)
// and fails with a message that does not name it.
void checkRequiredExtensions(std::string_view json, const std::string& path) {
    const nlohmann::json document = nlohmann::json::parse(json, nullptr, /*allow_exceptions=*/false);
    if (!document.is_object()) return;  // tinygltf says what is wrong with it
    const auto required = document.find("extensionsRequired");
    if (required == document.end() || !required->is_array()) return;
    for (const nlohmann::json& extension : *required) {
        if (!extension.is_string()) continue;
        const auto name = extension.get<std::string>();
        if (std::find(kImplementedExtensions.begin(), kImplementedExtensions.end(), name) ==
            kImplementedExtensions.end()) {
            throw Error(path + ": requires extension " + name + ", which Strata does not implement");
        }
    }
}

// The model of a glTF file's bytes (JSON, or binary by its magic), its URIs read through `files`.
tinygltf::Model loadModel(const std::string& bytes, const std::string& path,
                          tinygltf::FsCallbacks files) {
    if (bytes.size() > std::numeric_limits<uint32_t>::max()) throw Error(path + ": larger than 4 GB");
    const bool binary = bytes.compare(0, 4, "glTF") == 0;
    checkRequiredExtensions(jsonOf(bytes, binary), path);
    tinygltf::TinyGLTF loader;
    loader.SetFsCallbacks(files);
    loader.SetImageLoader(keepNoImage, nullptr);
    tinygltf::Model model;
    std::string error;
    std::string warning;
    const auto size = static_cast<unsigned int>(bytes.size());
    const bool loaded =
        binary ? loader.LoadBinaryFromMemory(&model, &error, &warning,
                                             reinterpret_cast<const unsigned char*>(bytes.data()), size, "")
               : loader.LoadASCIIFromString(&model, &error, &warning, bytes.data(), size, "");
    if (!loaded) {
        const std::string reason = firstLine(error);
        throw Error(path + ": " + (reason.empty() ? "not a glTF file" : reason));
    }
    return model;
}

bool isFinite(const glm::dvec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

bool isFinite(const glm::dmat4& m) {
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) {
            if (!std::isfinite(m[c][r])) return false;
        }
    }
    return true;
}

// What an accessor holds for Strata, and so which component types it may have: float, or the
// integer types KHR_mesh_quantization allows for it (glTF 2.0, "Meshes": attribute types;
// "Accessor Data Types" for indices).
enum class AccessorUse { Position, Normal, Index };

const char* nameOf(AccessorUse use) {
    switch (use) {
        case AccessorUse::Position: return "POSITION";
        case AccessorUse::Normal: return "NORMAL";
        case AccessorUse::Index: return "indices";
    }
    return "";
}

bool allowed(AccessorUse use, int componentType, bool normalized) {
    switch (use) {
        case AccessorUse::Position:
            return componentType == TINYGLTF_COMPONENT_TYPE_FLOAT ? !normalized
                                                                  : componentType >= TINYGLTF_COMPONENT_TYPE_BYTE &&
                                                                        componentType <= TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT;
        case AccessorUse::Normal:
            return componentType == TINYGLTF_COMPONENT_TYPE_FLOAT
                       ? !normalized
                       : normalized && (componentType == TINYGLTF_COMPONENT_TYPE_BYTE ||
                                        componentType == TINYGLTF_COMPONENT_TYPE_SHORT);
        case AccessorUse::Index:
            return !normalized && (componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                                   componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ||
                                   componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT);
    }
    return false;
}

// One component as a number; a normalized integer maps onto [0, 1] or [-1, 1] as glTF 2.0 says
// ("Animations": the equations for normalized integers, which KHR_mesh_quantization uses).
double componentValue(const unsigned char* bytes, int componentType, bool normalized) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_BYTE: {
            int8_t c;
            std::memcpy(&c, bytes, sizeof c);
            return normalized ? std::max(c / 127.0, -1.0) : c;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return normalized ? bytes[0] / 255.0 : bytes[0];
        case TINYGLTF_COMPONENT_TYPE_SHORT: {
            int16_t c;
            std::memcpy(&c, bytes, sizeof c);
            return normalized ? std::max(c / 32767.0, -1.0) : c;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
            uint16_t c;
            std::memcpy(&c, bytes, sizeof c);
            return normalized ? c / 65535.0 : c;
        }
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
            uint32_t c;
            std::memcpy(&c, bytes, sizeof c);
            return c;
        }
        default: {
            float c;
            std::memcpy(&c, bytes, sizeof c);
            return c;
        }
    }
}

// A glTF model flattened into Strata's mesh: the scene's nodes visited once each, their meshes'
// primitives appended in world space, their camera and lights taken.
class SceneBuilder {
public:
    SceneBuilder(const tinygltf::Model& model, std::string path)
        : model_(model), path_(std::move(path)) {}

    ParsedScene build(LoadReport* report) {
        for (size_t i = 0; i < model_.materials.size(); ++i) {
            parsed_.mesh.materials.push_back(convertMaterial(model_.materials[i], i));
        }
        visitNodes();
        // A flat scene keeps no per-triangle normal indices (mesh.h).
        if (parsed_.mesh.normals.empty()) parsed_.mesh.triangleNormals.clear();
        if (parsed_.camera) aimAtScene(*parsed_.camera);
        if (report) {
            report->faces = parsed_.mesh.triangles.size();
            report->droppedTriangles = dropped_;
            report->warnings.insert(report->warnings.end(), warnings_.begin(), warnings_.end());
        }
        return std::move(parsed_);
    }

private:
    [[noreturn]] void fail(const std::string& message) const { throw Error(path_ + ": " + message); }

    void warnOnce(const std::string& message) {
        const std::string line = path_ + ": " + message;
        if (std::find(warnings_.begin(), warnings_.end(), line) == warnings_.end()) warnings_.push_back(line);
    }

    template <typename T>
    const T& element(const std::vector<T>& list, int index, const std::string& what) const {
        if (index < 0 || static_cast<size_t>(index) >= list.size()) {
            fail(what + " " + std::to_string(index) + " does not exist (there are " +
                 std::to_string(list.size()) + ")");
        }
        return list[static_cast<size_t>(index)];
    }

    // glTF 2.0, "Materials" ("Metallic-Roughness Material", "Additional Textures") onto Strata's
    // layered material (material.h), factors only:
    //   diffuse   Kd = baseColor (1 - metallic): a metal has no diffuse lobe;
    //   specular  Ks = lerp(0.04, baseColor, metallic): the Fresnel reflectance at normal
    //             incidence, 0.04 for a dielectric (the spec's "Appendix B: BRDF Implementation");
    //   roughness Pr = roughnessFactor: glTF's GGX alpha is roughness^2, as Strata's is Pr^2;
    //   emission  Ke = emissiveFactor x KHR_materials_emissive_strength (1 without it), from
    //             the front (counter-clockwise) side only, as Strata emits; glTF's emission has no
    //             side, so a double-sided emitter lights only from its front here.
    // doubleSided needs nothing: Strata reflects on both sides of every triangle.
    Material convertMaterial(const tinygltf::Material& m, size_t index) {
        const std::string name = "material '" + m.name + "' (" + std::to_string(index) + ")";
        const auto& pbr = m.pbrMetallicRoughness;
        const auto inUnitRange = [](double v) { return v >= 0.0 && v <= 1.0; };
        if (pbr.baseColorFactor.size() != 4 ||
            !std::all_of(pbr.baseColorFactor.begin(), pbr.baseColorFactor.end(), inUnitRange)) {
            fail(name + ": baseColorFactor needs 4 numbers in 0..1");
        }
        if (!inUnitRange(pbr.metallicFactor)) fail(name + ": metallicFactor outside 0..1");
        if (!inUnitRange(pbr.roughnessFactor)) fail(name + ": roughnessFactor outside 0..1");
        if (m.emissiveFactor.size() != 3 ||
            !std::all_of(m.emissiveFactor.begin(), m.emissiveFactor.end(), inUnitRange)) {
            fail(name + ": emissiveFactor needs 3 numbers in 0..1");
        }
        double strength = 1.0;
        if (const auto it = m.extensions.find("KHR_materials_emissive_strength"); it != m.extensions.end()) {
            const tinygltf::Value& value = it->second.Get("emissiveStrength");
            if (value.IsNumber()) strength = value.GetNumberAsDouble();
            if (!(strength >= 0.0) || !std::isfinite(strength)) {
                fail(name + ": emissiveStrength is not a finite number >= 0");
            }
        }
        if (pbr.baseColorTexture.index >= 0 || pbr.metallicRoughnessTexture.index >= 0 ||
            m.normalTexture.index >= 0 || m.occlusionTexture.index >= 0 || m.emissiveTexture.index >= 0) {
            warnOnce("textures are ignored for now (materials render with their factors alone)");
        }
        if (m.alphaMode == "MASK" || m.alphaMode == "BLEND") {
            warnOnce("alphaMode MASK and BLEND are ignored for now (rendered opaque)");
        }
        return pbrMaterial(m.name, glm::dvec3(pbr.baseColorFactor[0], pbr.baseColorFactor[1], pbr.baseColorFactor[2]),
                           pbr.metallicFactor, pbr.roughnessFactor,
                           strength * glm::dvec3(m.emissiveFactor[0], m.emissiveFactor[1], m.emissiveFactor[2]));
    }

    static Material pbrMaterial(const std::string& name, const glm::dvec3& baseColor, double metallic,
                                double roughness, const glm::dvec3& emission) {
        Material material;
        material.name = name;
        material.diffuse = glm::vec3(baseColor * (1.0 - metallic));
        material.specular = glm::vec3(glm::mix(glm::dvec3(0.04), baseColor, metallic));
        material.roughness = static_cast<float>(roughness);
        material.emission = glm::vec3(emission);
        return material;
    }

    // The material of a primitive: its own, or the spec's default for one without ("Materials":
    // base colour 1, metallic 1, roughness 1), added once when first needed.
    uint32_t materialOf(int index) {
        if (index >= 0) {
            element(model_.materials, index, "material");
            return static_cast<uint32_t>(index);
        }
        if (!defaultMaterial_) {
            defaultMaterial_ = static_cast<uint32_t>(parsed_.mesh.materials.size());
            parsed_.mesh.materials.push_back(pbrMaterial("(glTF default)", glm::dvec3(1.0), 1.0, 1.0, glm::dvec3(0.0)));
        }
        return *defaultMaterial_;
    }

    // An accessor's elements, `components` numbers each, checked against its buffer view and
    // buffer so that no read leaves them.
    std::vector<double> accessorValues(int index, AccessorUse use, const std::string& where) const {
        const tinygltf::Accessor& accessor = element(model_.accessors, index, where + ": accessor");
        const std::string what = where + ": " + nameOf(use) + " accessor " + std::to_string(index);
        const int wantedType = use == AccessorUse::Index ? TINYGLTF_TYPE_SCALAR : TINYGLTF_TYPE_VEC3;
        if (accessor.type != wantedType) {
            fail(what + " is not a " + (use == AccessorUse::Index ? "SCALAR" : "VEC3"));
        }
        if (!allowed(use, accessor.componentType, accessor.normalized)) {
            fail(what + " has component type " + std::to_string(accessor.componentType) +
                 (accessor.normalized ? " (normalized)" : "") + ", which glTF does not allow for it");
        }
        if (accessor.sparse.isSparse) fail(what + " is sparse, which Strata does not read yet");
        if (accessor.count == 0) return {};
        if (accessor.bufferView < 0) fail(what + " has no bufferView (zero-filled accessors are not supported)");
        const tinygltf::BufferView& view = element(model_.bufferViews, accessor.bufferView, what + ": bufferView");
        const tinygltf::Buffer& buffer = element(model_.buffers, view.buffer, what + ": buffer");
        if (view.byteLength > buffer.data.size() || view.byteOffset > buffer.data.size() - view.byteLength) {
            fail(what + ": bufferView " + std::to_string(accessor.bufferView) + " runs past the end of buffer " +
                 std::to_string(view.buffer));
        }
        const auto componentSize = static_cast<size_t>(tinygltf::GetComponentSizeInBytes(
            static_cast<uint32_t>(accessor.componentType)));
        const size_t components = use == AccessorUse::Index ? 1 : 3;
        const size_t elementSize = componentSize * components;
        const size_t stride = view.byteStride ? view.byteStride : elementSize;
        if (stride < elementSize) fail(what + ": byteStride " + std::to_string(stride) + " is smaller than an element");
        if (accessor.byteOffset > view.byteLength || elementSize > view.byteLength - accessor.byteOffset ||
            accessor.count - 1 > (view.byteLength - accessor.byteOffset - elementSize) / stride) {
            fail(what + ": " + std::to_string(accessor.count) + " elements run past the end of bufferView " +
                 std::to_string(accessor.bufferView));
        }
        const unsigned char* start = buffer.data.data() + view.byteOffset + accessor.byteOffset;
        std::vector<double> values(accessor.count * components);
        for (size_t i = 0; i < accessor.count; ++i) {
            for (size_t c = 0; c < components; ++c) {
                values[i * components + c] =
                    componentValue(start + i * stride + c * componentSize, accessor.componentType, accessor.normalized);
            }
        }
        // glTF 2.0, "Accessor Data Types": NaN and infinities must not be present.
        if (!std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); })) {
            fail(what + " holds a non-finite number");
        }
        return values;
    }

    // The scene's root nodes: the default scene's, else the first scene's; without scenes, every
    // node that is no other's child (glTF 2.0, "Scenes": a file need not say which to show).
    std::vector<int> rootNodes() const {
        if (model_.defaultScene >= 0) return element(model_.scenes, model_.defaultScene, "default scene").nodes;
        if (!model_.scenes.empty()) return model_.scenes.front().nodes;
        std::vector<bool> isChild(model_.nodes.size(), false);
        for (const tinygltf::Node& node : model_.nodes) {
            for (int child : node.children) {
                if (child >= 0 && static_cast<size_t>(child) < isChild.size()) isChild[static_cast<size_t>(child)] = true;
            }
        }
        std::vector<int> roots;
        for (size_t i = 0; i < model_.nodes.size(); ++i) {
            if (!isChild[i]) roots.push_back(static_cast<int>(i));
        }
        return roots;
    }

    // glTF 2.0, "Transformations": a node's matrix, else T * R * S (rotation a unit quaternion
    // x, y, z, w).
    glm::dmat4 localTransform(const tinygltf::Node& node, int index) const {
        const std::string name = "node " + std::to_string(index);
        if (!node.matrix.empty()) {
            if (node.matrix.size() != 16) fail(name + ": matrix needs 16 numbers");
            return glm::make_mat4(node.matrix.data());  // column-major, as glm's
        }
        glm::dmat4 transform(1.0);
        if (!node.translation.empty()) {
            if (node.translation.size() != 3) fail(name + ": translation needs 3 numbers");
            transform = glm::translate(transform, glm::make_vec3(node.translation.data()));
        }
        if (!node.rotation.empty()) {
            if (node.rotation.size() != 4) fail(name + ": rotation needs 4 numbers");
            const glm::dquat q(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
            if (!(glm::length(q) > 0.0)) fail(name + ": rotation is not a unit quaternion");
            transform *= glm::mat4_cast(glm::normalize(q));
        }
        if (!node.scale.empty()) {
            if (node.scale.size() != 3) fail(name + ": scale needs 3 numbers");
            transform = glm::scale(transform, glm::make_vec3(node.scale.data()));
        }
        return transform;
    }

    // Depth first from the roots with a stack of its own, so that no depth of hierarchy can
    // overflow the call stack. glTF 2.0, "Nodes and Hierarchy": the nodes form disjoint strict
    // trees, so a node reached twice (a cycle, or two parents) is an error.
    void visitNodes() {
        const std::vector<int> roots = rootNodes();
        std::vector<std::pair<int, glm::dmat4>> pending;
        for (auto it = roots.rbegin(); it != roots.rend(); ++it) pending.emplace_back(*it, glm::dmat4(1.0));
        std::vector<bool> visited(model_.nodes.size(), false);
        while (!pending.empty()) {
            const auto [index, parent] = pending.back();
            pending.pop_back();
            const tinygltf::Node& node = element(model_.nodes, index, "node");
            if (visited[static_cast<size_t>(index)]) {
                fail("node " + std::to_string(index) + " is reached twice: the node hierarchy is not a tree");
            }
            visited[static_cast<size_t>(index)] = true;
            const glm::dmat4 world = parent * localTransform(node, index);
            if (!isFinite(world)) fail("node " + std::to_string(index) + " has a non-finite transform");
            if (node.mesh >= 0) addMesh(node.mesh, world);
            if (node.camera >= 0) takeCamera(node.camera, world);
            if (const auto it = node.extensions.find("KHR_lights_punctual"); it != node.extensions.end()) {
                const tinygltf::Value& light = it->second.Get("light");
                if (!light.IsInt()) fail("node " + std::to_string(index) + ": KHR_lights_punctual needs a light index");
                addLight(light.GetNumberAsInt(), world);
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
        const tinygltf::Mesh& gltfMesh = element(model_.meshes, meshIndex, "mesh");
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
            const std::vector<double> positions = accessorValues(position->second, AccessorUse::Position, where);
            const size_t vertexCount = positions.size() / 3;
            std::vector<double> normals;
            if (const auto normal = primitive.attributes.find("NORMAL"); normal != primitive.attributes.end()) {
                normals = accessorValues(normal->second, AccessorUse::Normal, where);
                if (normals.size() != positions.size()) {
                    fail(where + ": NORMAL has " + std::to_string(normals.size() / 3) + " elements, POSITION " +
                         std::to_string(vertexCount));
                }
            }
            std::vector<uint32_t> vertices;
            if (primitive.indices >= 0) {
                for (double index : accessorValues(primitive.indices, AccessorUse::Index, where)) {
                    if (index >= static_cast<double>(vertexCount)) {
                        fail(where + ": index " + std::to_string(static_cast<uint64_t>(index)) +
                             " out of range (" + std::to_string(vertexCount) + " vertices)");
                    }
                    vertices.push_back(static_cast<uint32_t>(index));
                }
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
            }
        }
    }

    // glTF 2.0, "Cameras": a camera looks down its node's local -Z, +Y up; the first perspective
    // one reached becomes the scene's. yfov is in radians; aspectRatio and the clip planes give
    // way to Strata's image size and unbounded rays.
    void takeCamera(int index, const glm::dmat4& world) {
        const tinygltf::Camera& camera = element(model_.cameras, index, "camera");
        if (camera.type != "perspective") {
            warnOnce("orthographic cameras are not supported (the scene is framed instead)");
            return;
        }
        if (parsed_.camera) return;
        const double yfov = camera.perspective.yfov;
        if (!(yfov > 0.0 && yfov < glm::pi<double>())) fail("camera " + std::to_string(index) + ": yfov outside (0, pi)");
        const glm::dvec3 position(world * glm::dvec4(0.0, 0.0, 0.0, 1.0));
        const glm::dvec3 forward(world * glm::dvec4(0.0, 0.0, -1.0, 0.0));
        const glm::dvec3 up(world * glm::dvec4(0.0, 1.0, 0.0, 0.0));
        if (!(glm::length(glm::cross(forward, up)) > 0.0)) {
            warnOnce("camera " + std::to_string(index) + " is degenerate (the scene is framed instead)");
            return;
        }
        CameraPose pose;
        pose.position = glm::vec3(position);
        pose.lookAt = glm::vec3(position + glm::normalize(forward));
        pose.up = glm::vec3(glm::normalize(up));
        pose.fovYDegrees = static_cast<float>(glm::degrees(yfov));
        parsed_.camera = pose;
    }

    // The camera's look-at point straight ahead at the distance of the scene's centre, so that a
    // viewer orbiting it turns about the scene (the direction stays the file's).
    void aimAtScene(CameraPose& pose) const {
        const auto& positions = parsed_.mesh.positions;
        if (positions.empty()) return;
        glm::vec3 lower(std::numeric_limits<float>::infinity());
        glm::vec3 upper = -lower;
        for (const glm::vec3& p : positions) {
            lower = glm::min(lower, p);
            upper = glm::max(upper, p);
        }
        const float distance = glm::length(0.5f * (lower + upper) - pose.position);
        if (distance > 0.0f && std::isfinite(distance)) {
            pose.lookAt = pose.position + distance * glm::normalize(pose.lookAt - pose.position);
        }
    }

    // KHR_lights_punctual. Its intensities are photometric (candela for point and spot lights,
    // lux for directional ones); Strata takes them as radiometric without conversion: candela x
    // color as W/sr, lux x color as W/m^2. `range` is ignored (the light falls off as 1/r^2
    // everywhere, as the extension allows). A spot light lights as a point light (its cone is
    // not rendered yet). A light points down its node's local -Z.
    void addLight(int index, const glm::dmat4& world) {
        const tinygltf::Light& light = element(model_.lights, index, "KHR_lights_punctual light");
        const std::string name = "light '" + light.name + "' (" + std::to_string(index) + ")";
        glm::dvec3 color(1.0);
        if (!light.color.empty()) {
            if (light.color.size() != 3) fail(name + ": color needs 3 numbers");
            color = glm::make_vec3(light.color.data());
        }
        if (!(glm::min(glm::min(color.x, color.y), color.z) >= 0.0) || !isFinite(color) ||
            !(light.intensity >= 0.0) || !std::isfinite(light.intensity)) {
            fail(name + ": color and intensity must be finite and not negative");
        }
        const glm::vec3 emitted(light.intensity * color);
        if (light.type == "directional") {
            const glm::dvec3 direction(world * glm::dvec4(0.0, 0.0, -1.0, 0.0));
            if (!(glm::length(direction) > 0.0)) fail(name + ": its node's transform has no direction");
            parsed_.mesh.directionalLights.emplace_back(glm::vec3(glm::normalize(direction)), emitted);
            return;
        }
        if (light.type == "spot") {
            warnOnce("spot lights light as point lights for now (their cones are ignored)");
        } else if (light.type != "point") {
            fail(name + ": unknown type '" + light.type + "' (known: point, spot, directional)");
        }
        parsed_.mesh.pointLights.emplace_back(glm::vec3(world * glm::dvec4(0.0, 0.0, 0.0, 1.0)), emitted);
    }

    const tinygltf::Model& model_;
    std::string path_;
    ParsedScene parsed_;
    std::optional<uint32_t> defaultMaterial_;
    size_t dropped_ = 0;
    std::vector<std::string> warnings_;
};

}  // namespace

std::vector<SceneFile> readGltfScene(const std::filesystem::path& path) {
    std::vector<SceneFile> files{{path.filename().string(), readTextFile(path, "scene")}};
    FolderFiles folder{path.parent_path(), {}};
    loadModel(files.front().bytes, path.string(),
              tinygltf::FsCallbacks{folderFileExists, sameName, readFolderFile, nullptr, &folder});
    files.insert(files.end(), std::make_move_iterator(folder.read.begin()),
                 std::make_move_iterator(folder.read.end()));
    return files;
}

ParsedScene parseGltfScene(const SceneBundle& bundle, LoadReport* report) {
    const SceneFile& main = bundle.files.front();
    const std::string path = bundle.pathOf(main.name);
    // tinygltf takes a non-const user pointer; the bundle callbacks only read through it.
    auto* files = const_cast<SceneBundle*>(&bundle);
    const tinygltf::Model model =
        loadModel(main.bytes, path, tinygltf::FsCallbacks{bundleFileExists, sameName, readBundleFile, nullptr, files});
    return SceneBuilder(model, path).build(report);
}

}  // namespace strata
