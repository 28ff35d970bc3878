#include "scene/gltf_draco.h"

#include <array>
#include <cstdint>
#include <cstring>
#include <set>
#include <utility>
#include <draco/compression/decode.h>

#include "util/error.h"

namespace strata {
namespace {

// The attribute's value at every point as `components` numbers of type T, one point after
// another; libdraco converts its stored type (and normalization) to the accessor's.
template <typename T>
bool convertPoints(const draco::Mesh& mesh, const draco::PointAttribute& attribute, int components,
                   std::vector<unsigned char>& bytes) {
    const size_t pointSize = static_cast<size_t>(components) * sizeof(T);
    bytes.resize(mesh.num_points() * pointSize);
    std::array<T, 4> value{};
    for (draco::PointIndex p(0); p < mesh.num_points(); ++p) {
        if (!attribute.ConvertValue<T>(attribute.mapped_index(p), static_cast<int8_t>(components), value.data())) {
            return false;
        }
        std::memcpy(bytes.data() + p.value() * pointSize, value.data(), pointSize);
    }
    return true;
}

bool convertPoints(int componentType, const draco::Mesh& mesh, const draco::PointAttribute& attribute,
                   int components, std::vector<unsigned char>& bytes) {
    switch (componentType) {
        case TINYGLTF_COMPONENT_TYPE_BYTE: return convertPoints<int8_t>(mesh, attribute, components, bytes);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: return convertPoints<uint8_t>(mesh, attribute, components, bytes);
        case TINYGLTF_COMPONENT_TYPE_SHORT: return convertPoints<int16_t>(mesh, attribute, components, bytes);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: return convertPoints<uint16_t>(mesh, attribute, components, bytes);
        case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: return convertPoints<uint32_t>(mesh, attribute, components, bytes);
        case TINYGLTF_COMPONENT_TYPE_FLOAT: return convertPoints<float>(mesh, attribute, components, bytes);
        default: return false;
    }
}

// `bytes` as a buffer of the model's own, seen through a bufferView of its own, which `accessor`
// now reads from its start.
void pointAccessorAt(tinygltf::Model& model, tinygltf::Accessor& accessor, std::vector<unsigned char> bytes,
                     size_t count) {
    tinygltf::BufferView view;
    view.buffer = static_cast<int>(model.buffers.size());
    view.byteLength = bytes.size();
    model.buffers.emplace_back().data = std::move(bytes);
    model.bufferViews.push_back(view);
    accessor.bufferView = static_cast<int>(model.bufferViews.size() - 1);
    accessor.byteOffset = 0;
    accessor.count = count;
    accessor.sparse.isSparse = false;
}

class DracoPrimitive {
public:
    DracoPrimitive(tinygltf::Model& model, tinygltf::Primitive& primitive, std::string where)
        : model_(model), primitive_(primitive), where_(std::move(where)) {}

    // Decodes the primitive unless its bufferView was decoded already (`decoded`).
    void decode(const tinygltf::Value& extension, std::set<int>& decoded) {
        const tinygltf::Value& viewIndex = extension.Get("bufferView");
        const tinygltf::Value& attributes = extension.Get("attributes");
        if (!viewIndex.IsInt() || !attributes.IsObject()) fail("needs a bufferView and attributes");
        const int index = viewIndex.GetNumberAsInt();
        if (!decoded.insert(index).second) return;
        const std::unique_ptr<draco::Mesh> mesh = decodeMesh(index);
        if (primitive_.indices < 0) fail("a Draco-compressed primitive without indices is not supported");
        std::vector<unsigned char> indices(mesh->num_faces() * 3 * sizeof(uint32_t));
        for (draco::FaceIndex f(0); f < mesh->num_faces(); ++f) {
            const draco::Mesh::Face& face = mesh->face(f);
            for (int c = 0; c < 3; ++c) {
                const uint32_t point = face[c].value();
                std::memcpy(indices.data() + (3 * f.value() + c) * sizeof point, &point, sizeof point);
            }
        }
        tinygltf::Accessor& indexAccessor = accessor(primitive_.indices, "indices");
        indexAccessor.componentType = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
        indexAccessor.normalized = false;
        pointAccessorAt(model_, indexAccessor, std::move(indices), mesh->num_faces() * size_t{3});
        for (const std::string& name : attributes.Keys()) {
            const tinygltf::Value& id = attributes.Get(name);
            const auto it = primitive_.attributes.find(name);
            if (!id.IsInt() || id.GetNumberAsInt() < 0 || it == primitive_.attributes.end()) {
                fail("attribute " + name + " needs a Draco id and an accessor of the primitive");
            }
            const auto unique = static_cast<uint32_t>(id.GetNumberAsInt());
            const draco::PointAttribute* attribute = mesh->GetAttributeByUniqueId(unique);
            if (!attribute) fail("attribute " + name + ": the Draco data has no attribute " + std::to_string(unique));
            tinygltf::Accessor& target = accessor(it->second, name);
            const int components = tinygltf::GetNumComponentsInType(static_cast<uint32_t>(target.type));
            std::vector<unsigned char> bytes;
            if (components < 1 || components > 4 || attribute->num_components() != components ||
                !convertPoints(target.componentType, *mesh, *attribute, components, bytes)) {
                fail("attribute " + name + ": the Draco data's " + std::to_string(attribute->num_components()) +
                     " components do not convert to its accessor's type");
            }
            pointAccessorAt(model_, target, std::move(bytes), mesh->num_points());
        }
    }

private:
    [[noreturn]] void fail(const std::string& message) const {
        throw Error(where_ + ": KHR_draco_mesh_compression: " + message);
    }

    tinygltf::Accessor& accessor(int index, const std::string& name) {
        if (index < 0 || static_cast<size_t>(index) >= model_.accessors.size()) {
            fail(name + " accessor " + std::to_string(index) + " does not exist");
        }
        return model_.accessors[static_cast<size_t>(index)];
    }

    std::unique_ptr<draco::Mesh> decodeMesh(int viewIndex) {
        if (viewIndex < 0 || static_cast<size_t>(viewIndex) >= model_.bufferViews.size()) {
            fail("bufferView " + std::to_string(viewIndex) + " does not exist");
        }
        const tinygltf::BufferView& view = model_.bufferViews[static_cast<size_t>(viewIndex)];
        if (view.buffer < 0 || static_cast<size_t>(view.buffer) >= model_.buffers.size()) {
            fail("bufferView " + std::to_string(viewIndex) + " has no buffer");
        }
        const std::vector<unsigned char>& data = model_.buffers[static_cast<size_t>(view.buffer)].data;
        if (view.byteLength > data.size() || view.byteOffset > data.size() - view.byteLength) {
            fail("bufferView " + std::to_string(viewIndex) + " runs past the end of its buffer");
        }
        draco::DecoderBuffer buffer;
        buffer.Init(reinterpret_cast<const char*>(data.data() + view.byteOffset), view.byteLength);
        draco::Decoder decoder;
        auto result = decoder.DecodeMeshFromBuffer(&buffer);
        if (!result.ok() || !result.value()) {
            fail("the data does not decode (" + result.status().error_msg_string() + ")");
        }
        return std::move(result).value();
    }

    tinygltf::Model& model_;
    tinygltf::Primitive& primitive_;
    std::string where_;
};

}  // namespace

bool giveDracoIndicesAView(nlohmann::json& document) {
    const auto meshes = document.find("meshes");
    const auto accessors = document.find("accessors");
    if (meshes == document.end() || !meshes->is_array() || accessors == document.end() || !accessors->is_array()) {
        return false;
    }
    bool changed = false;
    for (const nlohmann::json& mesh : *meshes) {
        const auto primitives = mesh.is_object() ? mesh.find("primitives") : mesh.end();
        if (!mesh.is_object() || primitives == mesh.end() || !primitives->is_array()) continue;
        for (const nlohmann::json& primitive : *primitives) {
            if (!primitive.is_object()) continue;
            const nlohmann::json* view = nullptr;
            const auto extensions = primitive.find("extensions");
            if (extensions != primitive.end() && extensions->is_object()) {
                const auto draco = extensions->find("KHR_draco_mesh_compression");
                if (draco != extensions->end() && draco->is_object() && draco->contains("bufferView")) {
                    view = &(*draco)["bufferView"];
                }
            }
            const auto indices = primitive.find("indices");
            if (!view || indices == primitive.end() || !indices->is_number_unsigned() ||
                indices->get<size_t>() >= accessors->size()) {
                continue;
            }
            nlohmann::json& accessor = (*accessors)[indices->get<size_t>()];
            if (accessor.is_object() && !accessor.contains("bufferView")) {
                accessor["bufferView"] = *view;
                changed = true;
            }
        }
    }
    return changed;
}

void decodeDracoPrimitives(tinygltf::Model& model, const std::string& path) {
    std::set<int> decoded;
    for (size_t m = 0; m < model.meshes.size(); ++m) {
        tinygltf::Mesh& mesh = model.meshes[m];
        for (size_t p = 0; p < mesh.primitives.size(); ++p) {
            tinygltf::Primitive& primitive = mesh.primitives[p];
            const auto it = primitive.extensions.find("KHR_draco_mesh_compression");
            if (it == primitive.extensions.end()) continue;
            const std::string where = path + ": mesh '" + mesh.name + "' (" + std::to_string(m) + ") primitive " +
                                      std::to_string(p);
            DracoPrimitive(model, primitive, where).decode(it->second, decoded);
        }
    }
}

}  // namespace strata
