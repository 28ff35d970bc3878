#include "scene/gltf_version1.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <optional>
#include <string_view>
#include <utility>
#include <vector>
#include <glm/vec4.hpp>
#include <nlohmann/json.hpp>

#include "materials/microfacet.h"
#include "scene/gltf_binary.h"
#include "util/error.h"
#include "util/little_endian.h"
#include "util/printable.h"

namespace strata {
namespace {

using nlohmann::json;

constexpr std::string_view kBinaryBuffer = "binary_glTF";  // KHR_binary_glTF's name of the body

// A 1.0 file's parts in 2.0's form: its lists keyed by name, read into arrays, and the index of
// each name.
class Upgrade {
public:
    Upgrade(const json& document, std::string path, bool binary)
        : in_(document), path_(std::move(path)), binary_(binary) {}

    json run() {
        for (const char* list : {"accessors", "bufferViews", "buffers", "cameras", "images", "materials", "meshes",
                                 "nodes", "samplers", "scenes", "textures"}) {
            number(list);
        }
        json out = json::object();
        out["asset"] = {{"version", "2.0"}};
        if (const json* generator = find(in_, "asset", "generator"); generator && generator->is_string()) {
            out["asset"]["generator"] = *generator;
        }
        out["buffers"] = buffers();
        out["bufferViews"] = each("bufferViews", [&](const json& view, const std::string& where) {
            json v = {{"buffer", index("buffers", at(view, "buffer", where), where)}};
            copy(view, v, {"byteOffset", "byteLength", "target"});
            return v;
        });
        out["accessors"] = each("accessors", [&](const json& accessor, const std::string& where) {
            return this->accessor(accessor, where, out["bufferViews"]);
        });
        out["images"] = each("images", [&](const json& image, const std::string& where) {
            json i = json::object();
            copy(image, i, {"name", "uri"});
            if (const json* view = find(image, "extensions", "KHR_binary_glTF")) {
                i.erase("uri");
                i["bufferView"] = index("bufferViews", at(*view, "bufferView", where), where);
                copy(*view, i, {"mimeType"});
            }
            return i;
        });
        out["samplers"] = each("samplers", [&](const json& sampler, const std::string&) {
            json s = json::object();
            copy(sampler, s, {"magFilter", "minFilter", "wrapS", "wrapT"});
            return s;
        });
        out["textures"] = each("textures", [&](const json& texture, const std::string& where) {
            json t = {{"source", index("images", at(texture, "source", where), where)}};
            if (texture.contains("sampler")) t["sampler"] = index("samplers", texture["sampler"], where);
            return t;
        });
        out["materials"] = each("materials", [&](const json& m, const std::string& where) { return material(m, where); });
        out["meshes"] = each("meshes", [&](const json& m, const std::string& where) { return mesh(m, where); });
        out["cameras"] = each("cameras", [&](const json& camera, const std::string&) {
            json c = json::object();
            copy(camera, c, {"name", "type", "perspective", "orthographic"});
            return c;
        });
        out["nodes"] = nodes();
        out["scenes"] = each("scenes", [&](const json& scene, const std::string& where) {
            json s = {{"nodes", indices("nodes", scene.value("nodes", json::array()), where)}};
            copy(scene, s, {"name"});
            return s;
        });
        if (in_.contains("scene")) out["scene"] = index("scenes", in_["scene"], "the default scene");
        out["extensionsUsed"] = extensionsUsed();
        for (auto it = out.begin(); it != out.end();) {
            it = it->is_array() && it->empty() ? out.erase(it) : std::next(it);
        }
        return out;
    }

private:
    // What to do for each part of the 1.0 list `list`, in the order `number` gave them indices.
    // A part without a name of its own is named by its 1.0 name, which messages then show.
    template <typename Convert>
    json each(const std::string& list, Convert convert) {
        json out = json::array();
        for (const auto& [name, part] : parts_[list]) {
            const std::string where = singular(list) + " " + quote(name);
            if (!part->is_object()) fail(where + " is not an object");
            json converted = convert(*part, where);
            if (!converted.contains("name")) converted["name"] = name;
            out.push_back(std::move(converted));
        }
        return out;
    }

    // Numbers the parts of `list`, which must be an object (or absent). The body of a binary file
    // comes first among the buffers: a 2.0 .glb's BIN chunk is buffer 0.
    void number(const std::string& list) {
        const auto it = in_.find(list);
        auto& parts = parts_[list];
        if (it == in_.end()) return;
        if (!it->is_object()) fail("\"" + list + "\" is not an object keyed by name, as glTF 1.0's lists are");
        for (const auto& [name, part] : it->items()) {
            if (list == "buffers" && name == kBinaryBuffer) parts.insert(parts.begin(), {name, &part});
            else parts.emplace_back(name, &part);
        }
        for (size_t i = 0; i < parts.size(); ++i) indexOf_[list][parts[i].first] = static_cast<int>(i);
    }

    int index(const std::string& list, const json& name, const std::string& where) {
        if (name.is_string()) {
            const auto& names = indexOf_[list];
            if (const auto it = names.find(name.get<std::string>()); it != names.end()) return it->second;
        }
        fail(where + " names " + singular(list) + " " + printable(name.dump()) + ", which does not exist");
    }

    json indices(const std::string& list, const json& names, const std::string& where) {
        if (!names.is_array()) fail(where + ": a list of names is not an array");
        json out = json::array();
        for (const json& name : names) out.push_back(index(list, name, where));
        return out;
    }

    const json& at(const json& object, const char* key, const std::string& where) {
        const auto it = object.find(key);
        if (it == object.end()) fail(where + " has no \"" + key + "\"");
        return *it;
    }

    static const json* find(const json& object, const char* key, const char* inner) {
        const auto outer = object.find(key);
        if (outer == object.end() || !outer->is_object()) return nullptr;
        const auto it = outer->find(inner);
        return it == outer->end() ? nullptr : &*it;
    }

    static void copy(const json& from, json& to, std::initializer_list<const char*> keys) {
        for (const char* key : keys) {
            if (const auto it = from.find(key); it != from.end()) to[key] = *it;
        }
    }

    static std::string singular(const std::string& list) {
        if (list == "accessors") return "accessor";
        if (list == "bufferViews") return "buffer view";
        if (list == "meshes") return "mesh";
        if (list == "buffers") return "buffer";
        return list.substr(0, list.size() - 1);
    }

    [[noreturn]] void fail(const std::string& what) const { throw Error(path_ + ": glTF 1.0: " + what); }

    // KHR_binary_glTF's body has no URI in 2.0: it is the .glb's BIN chunk, buffer 0 (number).
    json buffers() {
        const auto& buffers = parts_["buffers"];
        const json* body = binary_ && !buffers.empty() && buffers.front().first == kBinaryBuffer
                               ? buffers.front().second
                               : nullptr;
        return each("buffers", [&](const json& buffer, const std::string&) {
            json b = json::object();
            copy(buffer, b, {"byteLength", "uri"});
            if (&buffer == body) b.erase("uri");
            return b;
        });
    }

    // A 1.0 accessor strides through its buffer view itself; in 2.0 the view does, so an accessor
    // whose stride is not its element's size reads through a copy of its view with that stride.
    json accessor(const json& accessor, const std::string& where, json& views) {
        json a = json::object();
        copy(accessor, a, {"byteOffset", "componentType", "count", "type", "min", "max", "name"});
        if (!accessor.contains("bufferView")) return a;
        const int view = index("bufferViews", accessor["bufferView"], where);
        a["bufferView"] = view;
        const uint64_t stride = accessor.value("byteStride", json(0)).is_number_unsigned()
                                    ? accessor.value("byteStride", json(0)).get<uint64_t>()
                                    : 0;
        const uint64_t element = elementSize(accessor);
        if (stride == 0 || element == 0 || stride == element) return a;
        const auto key = std::make_pair(view, stride);
        auto it = stridedViews_.find(key);
        if (it == stridedViews_.end()) {
            json copy = views[static_cast<size_t>(view)];
            copy["byteStride"] = stride;
            views.push_back(std::move(copy));
            it = stridedViews_.emplace(key, static_cast<int>(views.size() - 1)).first;
        }
        a["bufferView"] = it->second;
        return a;
    }

    static uint64_t elementSize(const json& accessor) {
        static const std::map<int, uint64_t> componentBytes{{5120, 1}, {5121, 1}, {5122, 2}, {5123, 2}, {5125, 4}, {5126, 4}};
        static const std::map<std::string, uint64_t> components{{"SCALAR", 1}, {"VEC2", 2}, {"VEC3", 3}, {"VEC4", 4},
                                                                {"MAT2", 4},   {"MAT3", 9}, {"MAT4", 16}};
        const json type = accessor.value("type", json());
        const json component = accessor.value("componentType", json());
        if (!type.is_string() || !component.is_number_integer()) return 0;
        const auto c = componentBytes.find(component.get<int>());
        const auto n = components.find(type.get<std::string>());
        return c == componentBytes.end() || n == components.end() ? 0 : c->second * n->second;
    }

    // A material's Blinn-Phong value `name`: KHR_materials_common's, else the material's own, else
    // its technique's default; null where none is given.
    json phongValue(const json& material, const char* name) const {
        if (const auto extensions = material.find("extensions");
            extensions != material.end() && extensions->is_object() && extensions->contains("KHR_materials_common")) {
            const json& common = (*extensions)["KHR_materials_common"];
            const json* value = common.is_object() ? find(common, "values", name) : nullptr;
            return value ? *value : json();
        }
        if (const json* own = find(material, "values", name)) return *own;
        const auto technique = material.find("technique");
        const auto techniques = in_.find("techniques");
        if (technique == material.end() || !technique->is_string() || techniques == in_.end() ||
            !techniques->is_object()) {
            return json();
        }
        const auto it = techniques->find(technique->get<std::string>());
        if (it == techniques->end() || !it->is_object()) return json();
        const json* parameter = find(*it, "parameters", name);
        return parameter && parameter->is_object() ? parameter->value("value", json()) : json();
    }

    // A colour of 3 or 4 finite numbers (alpha 1 when absent), or nothing.
    static std::optional<glm::vec4> colourOf(const json& value) {
        if (!value.is_array() || value.size() < 3 || value.size() > 4) return std::nullopt;
        glm::vec4 colour(1.0f);
        for (size_t i = 0; i < value.size(); ++i) {
            if (!value[i].is_number() || !std::isfinite(value[i].get<float>())) return std::nullopt;
            colour[static_cast<int>(i)] = value[i].get<float>();
        }
        return colour;
    }

    // Blinn-Phong's colours are reflectances that old exporters let stray outside 0..1, where
    // specular-glossiness's are not: clamped.
    static json unit(glm::vec4 colour, int components) {
        json out = json::array();
        for (int i = 0; i < components; ++i) out.push_back(std::clamp(colour[i], 0.0f, 1.0f));
        return out;
    }

    json material(const json& m, const std::string& where) {
        json sg = json::object();
        const json diffuse = phongValue(m, "diffuse");
        if (diffuse.is_string()) {
            sg["diffuseTexture"] = {{"index", index("textures", diffuse, where + ": diffuse")}};
        } else {
            // KHR_materials_common's default is black.
            sg["diffuseFactor"] = unit(colourOf(diffuse).value_or(glm::vec4(0.0f, 0.0f, 0.0f, 1.0f)), 4);
        }
        sg["specularFactor"] = unit(colourOf(phongValue(m, "specular")).value_or(glm::vec4(0.0f)), 3);
        const json shininess = phongValue(m, "shininess");
        const bool exponent = shininess.is_number() && !std::isnan(shininess.get<float>());
        sg["glossinessFactor"] = 1.0f - roughnessFromShininess(exponent ? std::max(shininess.get<float>(), 0.0f) : 0.0f);
        json out = {{"extensions", {{"KHR_materials_pbrSpecularGlossiness", sg}}}};
        copy(m, out, {"name"});
        // An emission above 1 keeps its brightness as KHR_materials_emissive_strength.
        const json emission = phongValue(m, "emission");
        if (emission.is_string()) {
            out["emissiveTexture"] = {{"index", index("textures", emission, where + ": emission")}};
            out["emissiveFactor"] = {1.0, 1.0, 1.0};
        } else if (const auto e = colourOf(emission); e && std::max({e->r, e->g, e->b}) > 0.0f) {
            const float strength = std::max({e->r, e->g, e->b, 1.0f});
            out["emissiveFactor"] = unit(*e / strength, 3);
            if (strength > 1.0f) {
                out["extensions"]["KHR_materials_emissive_strength"] = {{"emissiveStrength", strength}};
                emissiveStrength_ = true;
            }
        }
        return out;
    }

    // The attributes 2.0 knows by the same names, TEXCOORD and COLOR without a set index taken as
    // set 0; 1.0's JOINT and WEIGHT (skins) are not read.
    json mesh(const json& m, const std::string& where) {
        json primitives = json::array();
        const json list = m.value("primitives", json::array());
        if (!list.is_array()) fail(where + ": \"primitives\" is not an array");
        for (const json& p : list) {
            if (!p.is_object()) fail(where + ": a primitive is not an object");
            json attributes = json::object();
            if (p.contains("attributes") && p["attributes"].is_object()) {
                for (const auto& [given, accessor] : p["attributes"].items()) {
                    const std::string semantic = given == "TEXCOORD" || given == "COLOR" ? given + "_0" : given;
                    if (semantic == "POSITION" || semantic == "NORMAL" || semantic.rfind("TEXCOORD_", 0) == 0 ||
                        semantic.rfind("COLOR_", 0) == 0) {
                        attributes[semantic] = index("accessors", accessor, where + ": " + given);
                    }
                }
            }
            json primitive = {{"attributes", attributes}};
            if (p.contains("indices")) primitive["indices"] = index("accessors", p["indices"], where + ": indices");
            if (p.contains("material")) primitive["material"] = index("materials", p["material"], where);
            copy(p, primitive, {"mode"});
            primitives.push_back(std::move(primitive));
        }
        json out = {{"primitives", primitives}};
        copy(m, out, {"name"});
        return out;
    }

    // 1.0 nodes, then a child node for each mesh of a node beyond its first.
    json nodes() {
        json out = each("nodes", [&](const json& node, const std::string& where) {
            json n = json::object();
            copy(node, n, {"name", "matrix", "translation", "rotation", "scale"});
            if (node.contains("camera")) n["camera"] = index("cameras", node["camera"], where);
            if (node.contains("children")) n["children"] = indices("nodes", node["children"], where);
            return n;
        });
        for (size_t i = 0; i < parts_["nodes"].size(); ++i) {
            const auto& [name, node] = parts_["nodes"][i];
            if (!node->contains("meshes")) continue;
            const json meshes = indices("meshes", (*node)["meshes"], "node " + quote(name));
            if (meshes.empty()) continue;
            out[i]["mesh"] = meshes[0];
            for (size_t k = 1; k < meshes.size(); ++k) {
                // out[i] is looked up after each push, which may move the nodes.
                out.push_back({{"mesh", meshes[k]}});
                out[i]["children"].push_back(out.size() - 1);
            }
        }
        return out;
    }

    // 1.0 extensions that change nothing Strata reads are left out; any other is named, so that the
    // loader warns that it is not read.
    json extensionsUsed() const {
        json out = json::array();
        if (!parts_.at("materials").empty()) out.push_back("KHR_materials_pbrSpecularGlossiness");
        if (emissiveStrength_) out.push_back("KHR_materials_emissive_strength");
        const auto used = in_.find("extensionsUsed");
        if (used == in_.end() || !used->is_array()) return out;
        for (const json& extension : *used) {
            if (extension.is_string() && extension != "KHR_binary_glTF" && extension != "KHR_materials_common") {
                out.push_back(extension);
            }
        }
        return out;
    }

    const json& in_;
    std::string path_;
    bool binary_;
    std::map<std::string, std::vector<std::pair<std::string, const json*>>> parts_;
    std::map<std::string, std::map<std::string, int>> indexOf_;
    std::map<std::pair<int, uint64_t>, int> stridedViews_;
    bool emissiveStrength_ = false;
};

}  // namespace

bool isBinaryGltfVersion1(std::string_view bytes) {
    return bytes.size() >= 8 && bytes.substr(0, 4) == "glTF" && littleEndian32(bytes, 4) == 1;
}

BinaryGltfVersion1 splitBinaryGltfVersion1(std::string_view bytes, const std::string& path) {
    const auto fail = [&](const std::string& what) { throw Error(path + ": glTF 1.0: " + what); };
    // Magic, version 1, the total length, the content's length and format (0: JSON).
    if (bytes.size() < 20) fail("shorter than a binary glTF 1.0's 20-byte header");
    const size_t length = littleEndian32(bytes, 8);
    if (length > bytes.size() || length < 20) {
        fail("the binary header gives a length of " + std::to_string(length) + " bytes, the file has " +
             std::to_string(bytes.size()));
    }
    const size_t contentLength = littleEndian32(bytes, 12);
    if (contentLength > length - 20) fail("the binary header's content runs past the end of the file");
    if (littleEndian32(bytes, 16) != 0) fail("the binary content is not JSON (format 0)");
    return {bytes.substr(20, contentLength), bytes.substr(20 + contentLength, length - 20 - contentLength)};
}

std::string upgradeGltfVersion1(const json& document, std::string_view body, bool binary, const std::string& path) {
    if (!document.is_object()) throw Error(path + ": glTF 1.0: its JSON is not an object");
    const std::string upgraded = Upgrade(document, path, binary).run().dump();
    if (!binary) return upgraded;
    return glbOf(upgraded, body.empty() ? std::string() : glbChunk(kGlbBinChunk, body, '\0'));
}

}  // namespace strata
