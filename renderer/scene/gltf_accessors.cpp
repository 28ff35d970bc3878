#include "scene/gltf_accessors.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

namespace strata {
namespace {

// The element types glTF allows for each use, as tinygltf's TINYGLTF_TYPE_ values.
std::vector<int> typesOf(AccessorUse use) {
    switch (use) {
        case AccessorUse::Index: return {TINYGLTF_TYPE_SCALAR};
        case AccessorUse::TexCoord: return {TINYGLTF_TYPE_VEC2};
        case AccessorUse::Colour: return {TINYGLTF_TYPE_VEC3, TINYGLTF_TYPE_VEC4};
        case AccessorUse::InstanceRotation: return {TINYGLTF_TYPE_VEC4};
        default: return {TINYGLTF_TYPE_VEC3};
    }
}

const char* typeName(int type) {
    switch (type) {
        case TINYGLTF_TYPE_SCALAR: return "SCALAR";
        case TINYGLTF_TYPE_VEC2: return "VEC2";
        case TINYGLTF_TYPE_VEC3: return "VEC3";
        default: return "VEC4";
    }
}

const char* nameOf(AccessorUse use) {
    switch (use) {
        case AccessorUse::Position: return "POSITION";
        case AccessorUse::Normal: return "NORMAL";
        case AccessorUse::TexCoord: return "TEXCOORD_0";
        case AccessorUse::Colour: return "COLOR_0";
        case AccessorUse::Index: return "indices";
        case AccessorUse::InstanceTranslation: return "TRANSLATION";
        case AccessorUse::InstanceRotation: return "ROTATION";
        case AccessorUse::InstanceScale: return "SCALE";
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
        case AccessorUse::InstanceRotation:
            return componentType == TINYGLTF_COMPONENT_TYPE_FLOAT
                       ? !normalized
                       : normalized && (componentType == TINYGLTF_COMPONENT_TYPE_BYTE ||
                                        componentType == TINYGLTF_COMPONENT_TYPE_SHORT);
        case AccessorUse::TexCoord:
        case AccessorUse::Colour:
            return componentType == TINYGLTF_COMPONENT_TYPE_FLOAT
                       ? !normalized
                       : normalized && (componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                                        componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT);
        case AccessorUse::Index:
            return !normalized && (componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
                                   componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ||
                                   componentType == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT);
        // EXT_mesh_gpu_instancing: float, or with KHR_mesh_quantization signed bytes and shorts,
        // normalized or not.
        case AccessorUse::InstanceTranslation:
        case AccessorUse::InstanceScale:
            return componentType == TINYGLTF_COMPONENT_TYPE_FLOAT ? !normalized
                                                                  : componentType == TINYGLTF_COMPONENT_TYPE_BYTE ||
                                                                        componentType == TINYGLTF_COMPONENT_TYPE_SHORT;
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

}  // namespace

// An accessor's elements, `components` numbers each, checked against its buffer view and
// buffer so that no read leaves them.
std::vector<double> accessorValues(const GltfModel& gltf, int index, AccessorUse use, const std::string& where) {
    const tinygltf::Accessor& accessor = gltf.element(gltf.model.accessors, index, where + ": accessor");
    const std::string what = where + ": " + nameOf(use) + " accessor " + std::to_string(index);
    const std::vector<int> types = typesOf(use);
    if (std::find(types.begin(), types.end(), accessor.type) == types.end()) {
        std::string wanted = typeName(types[0]);
        for (size_t t = 1; t < types.size(); ++t) wanted += std::string(" or ") + typeName(types[t]);
        gltf.fail(what + " is not a " + wanted);
    }
    const auto components = static_cast<size_t>(tinygltf::GetNumComponentsInType(static_cast<uint32_t>(accessor.type)));
    if (!allowed(use, accessor.componentType, accessor.normalized)) {
        gltf.fail(what + " has component type " + std::to_string(accessor.componentType) +
             (accessor.normalized ? " (normalized)" : "") + ", which glTF does not allow for it");
    }
    if (accessor.sparse.isSparse) gltf.fail(what + " is sparse, which Strata does not read yet");
    if (accessor.count == 0) return {};
    if (accessor.bufferView < 0) gltf.fail(what + " has no bufferView (zero-filled accessors are not supported)");
    const tinygltf::BufferView& view = gltf.element(gltf.model.bufferViews, accessor.bufferView, what + ": bufferView");
    const tinygltf::Buffer& buffer = gltf.element(gltf.model.buffers, view.buffer, what + ": buffer");
    if (view.byteLength > buffer.data.size() || view.byteOffset > buffer.data.size() - view.byteLength) {
        gltf.fail(what + ": bufferView " + std::to_string(accessor.bufferView) + " runs past the end of buffer " +
             std::to_string(view.buffer));
    }
    const auto componentSize = static_cast<size_t>(tinygltf::GetComponentSizeInBytes(
        static_cast<uint32_t>(accessor.componentType)));
    const size_t elementSize = componentSize * components;
    const size_t stride = view.byteStride ? view.byteStride : elementSize;
    if (stride < elementSize) gltf.fail(what + ": byteStride " + std::to_string(stride) + " is smaller than an element");
    if (accessor.byteOffset > view.byteLength || elementSize > view.byteLength - accessor.byteOffset ||
        accessor.count - 1 > (view.byteLength - accessor.byteOffset - elementSize) / stride) {
        gltf.fail(what + ": " + std::to_string(accessor.count) + " elements run past the end of bufferView " +
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
        gltf.fail(what + " holds a non-finite number");
    }
    return values;
}

std::vector<uint32_t> accessorIndices(const GltfModel& gltf, int index, size_t vertexCount,
                                      const std::string& where) {
    const std::vector<double> values = accessorValues(gltf, index, AccessorUse::Index, where);
    std::vector<uint32_t> indices(values.size());
    for (size_t i = 0; i < values.size(); ++i) {
        const bool inRange = values[i] < static_cast<double>(vertexCount);
        indices[i] = inRange ? static_cast<uint32_t>(values[i]) : kIndexOutOfRange;
    }
    return indices;
}

}  // namespace strata
