#pragma once
// glTF files written by the tests: a document built accessor by accessor over one buffer, as a
// .gltf (a base64 data: buffer) or a .glb (assembled in memory), and the bundle that parses it.
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>
#include <vector>
#include <nlohmann/json.hpp>

#include "scene/gltf_loader.h"
#include "scene/scene_format.h"
#include "util/error.h"

namespace strata::test {

inline std::string base64(const std::string& bytes) {
    static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string text;
    for (size_t i = 0; i < bytes.size(); i += 3) {
        const size_t n = std::min<size_t>(3, bytes.size() - i);
        uint32_t group = 0;
        for (size_t j = 0; j < 3; ++j) {
            group = group << 8 | (j < n ? static_cast<unsigned char>(bytes[i + j]) : 0u);
        }
        for (size_t j = 0; j < 4; ++j) text += j <= n ? digits[(group >> (18 - 6 * j)) & 63] : '=';
    }
    return text;
}

template <typename T>
inline void append(std::string& bytes, const std::vector<T>& values) {
    const size_t start = bytes.size();
    bytes.resize(start + values.size() * sizeof(T));
    std::memcpy(bytes.data() + start, values.data(), values.size() * sizeof(T));
    while (bytes.size() % 4) bytes += '\0';
}

// A glTF document built accessor by accessor over buffer 0, `bin`; the buffers `doc` holds
// itself (a data-less fallback, say) follow it as buffers 1, 2, ...
struct Model {
    using json = nlohmann::json;
    json doc = {{"asset", {{"version", "2.0"}}}};
    std::string bin;

    json withBuffer0(json buffer0) const {
        json d = doc;
        d["buffers"] = json::array({std::move(buffer0)});
        for (const json& buffer : doc.value("buffers", json::array())) d["buffers"].push_back(buffer);
        return d;
    }

    template <typename T>
    int accessor(const std::vector<T>& values, const char* type, int componentType, size_t count) {
        doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", bin.size()},
                                      {"byteLength", values.size() * sizeof(T)}});
        append(bin, values);
        doc["accessors"].push_back({{"bufferView", doc["bufferViews"].size() - 1},
                                    {"componentType", componentType}, {"count", count}, {"type", type}});
        return static_cast<int>(doc["accessors"].size() - 1);
    }
    int positions(const std::vector<float>& xyz) { return accessor(xyz, "VEC3", 5126, xyz.size() / 3); }

    // A mesh of one primitive, on a node of its own in scene 0; returns the node.
    int meshNode(json primitive, json node = json::object()) {
        doc["meshes"].push_back({{"name", "m" + std::to_string(doc["meshes"].size())},
                                 {"primitives", json::array({primitive})}});
        node["mesh"] = doc["meshes"].size() - 1;
        return addNode(node);
    }
    int addNode(const json& node, bool root = true) {
        doc["nodes"].push_back(node);
        const int index = static_cast<int>(doc["nodes"].size() - 1);
        if (root) doc["scenes"][0]["nodes"].push_back(index);
        return index;
    }

    std::string gltf() const {
        return withBuffer0({{"byteLength", bin.size()}, {"uri", "data:application/octet-stream;base64," + base64(bin)}})
            .dump();
    }
    std::string glb() const {
        std::string text = withBuffer0({{"byteLength", bin.size()}}).dump();
        while (text.size() % 4) text += ' ';
        std::string out = "glTF";
        const auto word = [&](uint32_t v) { append(out, std::vector<uint32_t>{v}); };
        word(2);
        word(static_cast<uint32_t>(12 + 8 + text.size() + 8 + bin.size()));
        word(static_cast<uint32_t>(text.size()));
        word(0x4E4F534A);  // JSON
        out += text;
        word(static_cast<uint32_t>(bin.size()));
        word(0x004E4942);  // BIN
        out += bin;
        return out;
    }
};

inline SceneBundle bundleOf(const std::string& bytes, const std::string& name = "model.gltf") {
    return SceneBundle{"mem/" + name, {{name, bytes}}, std::nullopt, std::nullopt};
}

// The one line that parsing `bytes` as the file `name` throws, or "(loaded)".
inline std::string errorOf(const std::string& bytes, const std::string& name = "model.gltf") {
    try {
        parseGltfScene(bundleOf(bytes, name));
    } catch (const Error& error) {
        return error.what();
    }
    return "(loaded)";
}

// The same for `model` as a .gltf.
inline std::string errorOf(const Model& model) { return errorOf(model.gltf()); }

}  // namespace strata::test
