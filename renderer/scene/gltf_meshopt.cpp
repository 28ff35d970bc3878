#include "scene/gltf_meshopt.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string_view>
#include <vector>
#include <meshoptimizer.h>

#include "util/error.h"

namespace strata {
namespace {

constexpr std::array<std::string_view, 2> kNames{"EXT_meshopt_compression", "KHR_meshopt_compression"};

template <typename Extensions>
auto findExtension(const Extensions& extensions) {
    for (std::string_view name : kNames) {
        const auto it = extensions.find(std::string(name));
        if (it != extensions.end()) return it;
    }
    return extensions.end();
}

// One compressed bufferView, decoded (EXT_meshopt_compression, "Decoding").
class MeshoptView {
public:
    MeshoptView(const tinygltf::Model& model, const tinygltf::Value& extension, std::string where)
        : model_(model), extension_(extension), where_(std::move(where)) {}

    std::vector<unsigned char> decode() const {
        const tinygltf::Buffer& source = model_.buffers[bufferIndex()];
        const size_t offset = number("byteOffset", 0);
        const size_t length = number("byteLength");
        if (length > source.data.size() || offset > source.data.size() - length) {
            fail("its byteOffset and byteLength run past the end of buffer " + std::to_string(bufferIndex()));
        }
        const size_t stride = number("byteStride");
        const size_t count = number("count");
        if (stride == 0 || count > std::numeric_limits<uint32_t>::max() / stride) {
            fail("byteStride " + std::to_string(stride) + " x count " + std::to_string(count) +
                 " is not a buffer size");
        }
        const std::string mode = text("mode");
        const std::string filter = text("filter", "NONE");
        const bool attributes = mode == "ATTRIBUTES";
        if (attributes ? stride % 4 != 0 || stride > 256 : stride != 2 && stride != 4) {
            fail("byteStride " + std::to_string(stride) + " is not allowed for mode " + mode);
        }
        if (!attributes && filter != "NONE") fail("filter " + filter + " applies to ATTRIBUTES only");
        std::vector<unsigned char> decoded(stride * count);
        const unsigned char* bytes = source.data.data() + offset;
        int result = 0;
        if (attributes) {
            result = meshopt_decodeVertexBuffer(decoded.data(), count, stride, bytes, length);
        } else if (mode == "TRIANGLES") {
            if (count % 3 != 0) fail("count " + std::to_string(count) + " is not a whole number of triangles");
            result = meshopt_decodeIndexBuffer(decoded.data(), count, stride, bytes, length);
        } else if (mode == "INDICES") {
            result = meshopt_decodeIndexSequence(decoded.data(), count, stride, bytes, length);
        } else {
            fail("unknown mode '" + mode + "' (known: ATTRIBUTES, TRIANGLES, INDICES)");
        }
        if (result != 0) fail("the data does not decode (meshoptimizer error " + std::to_string(result) + ")");
        applyFilter(filter, decoded.data(), count, stride);
        return decoded;
    }

private:
    [[noreturn]] void fail(const std::string& message) const { throw Error(where_ + ": " + message); }

    size_t bufferIndex() const {
        const size_t index = number("buffer");
        if (index >= model_.buffers.size()) fail("buffer " + std::to_string(index) + " does not exist");
        return index;
    }

    size_t number(const char* name, std::optional<size_t> otherwise = std::nullopt) const {
        const tinygltf::Value& value = extension_.Get(name);
        if (!value.IsNumber()) {
            if (otherwise && !extension_.Has(name)) return *otherwise;
            fail(std::string("needs ") + name + " (an integer >= 0)");
        }
        const double v = value.GetNumberAsDouble();
        if (!(v >= 0.0 && v <= static_cast<double>(std::numeric_limits<uint32_t>::max())) || v != std::floor(v)) {
            fail(std::string(name) + " is not an integer >= 0");
        }
        return static_cast<size_t>(v);
    }

    std::string text(const char* name, const char* otherwise = nullptr) const {
        const tinygltf::Value& value = extension_.Get(name);
        if (value.IsString()) return value.Get<std::string>();
        if (otherwise && !extension_.Has(name)) return otherwise;
        fail(std::string("needs ") + name + " (a string)");
    }

    // The filters' element sizes (EXT_meshopt_compression, "Filters"): octahedral 4 or 8 bytes,
    // quaternion 8, exponential a multiple of 4.
    void applyFilter(const std::string& filter, unsigned char* data, size_t count, size_t stride) const {
        if (filter == "NONE") return;
        if (filter == "OCTAHEDRAL") {
            if (stride != 4 && stride != 8) fail("filter OCTAHEDRAL needs byteStride 4 or 8");
            meshopt_decodeFilterOct(data, count, stride);
        } else if (filter == "QUATERNION") {
            if (stride != 8) fail("filter QUATERNION needs byteStride 8");
            meshopt_decodeFilterQuat(data, count, stride);
        } else if (filter == "EXPONENTIAL") {
            meshopt_decodeFilterExp(data, count, stride);
        } else {
            fail("unknown filter '" + filter + "' (known: NONE, OCTAHEDRAL, QUATERNION, EXPONENTIAL)");
        }
    }

    const tinygltf::Model& model_;
    const tinygltf::Value& extension_;
    std::string where_;
};

}  // namespace

bool giveMeshoptFallbacksData(nlohmann::json& document) {
    const auto buffers = document.find("buffers");
    if (buffers == document.end() || !buffers->is_array()) return false;
    bool changed = false;
    for (nlohmann::json& buffer : *buffers) {
        if (!buffer.is_object() || buffer.contains("uri") || !buffer.contains("extensions")) continue;
        const nlohmann::json& extensions = buffer["extensions"];
        if (!extensions.is_object()) continue;
        for (std::string_view name : kNames) {
            const auto it = extensions.find(std::string(name));
            if (it == extensions.end() || !it->is_object() || it->value("fallback", false) != true) continue;
            buffer["uri"] = "data:application/octet-stream;base64,AA==";
            buffer["byteLength"] = 1;
            changed = true;
            break;
        }
    }
    return changed;
}

void decodeMeshoptBufferViews(tinygltf::Model& model, const std::string& path) {
    for (size_t v = 0; v < model.bufferViews.size(); ++v) {
        tinygltf::BufferView& view = model.bufferViews[v];
        const auto it = findExtension(view.extensions);
        if (it == view.extensions.end()) continue;
        const std::string where = path + ": bufferView " + std::to_string(v) + ": " + it->first;
        std::vector<unsigned char> decoded = MeshoptView(model, it->second, where).decode();
        view.buffer = static_cast<int>(model.buffers.size());
        view.byteOffset = 0;
        view.byteLength = decoded.size();
        model.buffers.emplace_back().data = std::move(decoded);
    }
}

}  // namespace strata
