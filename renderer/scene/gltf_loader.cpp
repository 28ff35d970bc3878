#include "scene/gltf_loader.h"

// tinygltf's implementation lives in this file alone (configured in gltf_model.h). Strata writes
// no glTF, and every file it reads comes through the callbacks below (the bundle, when parsing),
// never its own file access.
#define TINYGLTF_IMPLEMENTATION
#include "scene/gltf_model.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string_view>
#include <utility>
#include <nlohmann/json.hpp>

#include "scene/gltf_draco.h"
#include "scene/gltf_meshopt.h"
#include "scene/gltf_nodes.h"
#include "scene/scene_textures.h"
#include "util/error.h"
#include "util/text_file.h"

namespace strata {
namespace {

// The extensions Strata reads (gltf_materials.h says how far for the materials'); another one in
// extensionsRequired means the file cannot be rendered as its author meant (glTF 2.0, "Specifying
// Extensions"), and one in extensionsUsed only is a warning. The compressions are decoded
// (gltf_meshopt.h, gltf_draco.h) before the model is read.
constexpr std::array<std::string_view, 12> kImplementedExtensions{
    "EXT_meshopt_compression",         "KHR_draco_mesh_compression", "KHR_lights_punctual",
    "KHR_materials_clearcoat",         "KHR_materials_emissive_strength", "KHR_materials_ior",
    "KHR_materials_specular",          "KHR_materials_transmission", "KHR_materials_volume",
    "KHR_mesh_quantization",           "KHR_meshopt_compression",    "KHR_texture_transform"};

bool implemented(const std::string& extension) {
    return std::find(kImplementedExtensions.begin(), kImplementedExtensions.end(), extension) !=
           kImplementedExtensions.end();
}

// A warning for each extension the file uses that Strata does not read.
void warnUnreadExtensions(GltfModel& gltf) {
    for (const std::string& extension : gltf.model.extensionsUsed) {
        if (!implemented(extension)) gltf.warnOnce("uses extension " + extension + ", which Strata does not read; ignored");
    }
}

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

// Images are decoded by Strata (scene_textures.h), not by tinygltf, since only a material tells
// whether one is sRGB colour or linear data: the callback keeps each image's encoded bytes,
// wherever they come from (a file, a data: URI, a .glb buffer view), by image index.
bool keepEncodedImage(tinygltf::Image*, const int index, std::string*, std::string*, int, int,
                      const unsigned char* bytes, int size, void* images) {
    auto& encoded = *static_cast<std::vector<std::string>*>(images);
    if (index < 0) return true;
    if (encoded.size() <= static_cast<size_t>(index)) encoded.resize(static_cast<size_t>(index) + 1);
    encoded[static_cast<size_t>(index)].assign(reinterpret_cast<const char*>(bytes), static_cast<size_t>(size));
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
// what the extension encodes (a compressed primitive's accessors have no buffer view, say) and
// fails with a message that does not name it.
void checkRequiredExtensions(const nlohmann::json& document, const std::string& path) {
    const auto required = document.find("extensionsRequired");
    if (required == document.end() || !required->is_array()) return;
    for (const nlohmann::json& extension : *required) {
        if (!extension.is_string()) continue;
        const auto name = extension.get<std::string>();
        if (!implemented(name)) {
            throw Error(path + ": requires extension " + name + ", which Strata does not implement");
        }
    }
}

// tinygltf passes over a property of the wrong JSON type as if it were absent (a mesh whose
// "primitives" is an object has no primitives), so that the file would fail later for a reason
// it does not name, or render less: the arrays Strata reads through are checked here.
void checkArrays(const nlohmann::json& document, const std::string& path) {
    const auto needArray = [&](const nlohmann::json& object, const char* key, const std::string& where) {
        const auto it = object.find(key);
        if (it != object.end() && !it->is_array()) {
            throw Error(path + ": " + where + "\"" + key + "\" is not an array (it is " + it->type_name() + ")");
        }
    };
    for (const char* key : {"accessors", "bufferViews", "buffers", "cameras", "images", "materials", "meshes",
                            "nodes", "scenes", "textures"}) {
        needArray(document, key, "");
    }
    const auto forEachObject = [&](const char* list, const char* what, auto check) {
        const auto it = document.find(list);
        if (it == document.end() || !it->is_array()) return;
        for (size_t i = 0; i < it->size(); ++i) {
            if ((*it)[i].is_object()) check((*it)[i], std::string(what) + " " + std::to_string(i) + ": ");
        }
    };
    forEachObject("meshes", "mesh", [&](const nlohmann::json& mesh, const std::string& where) {
        needArray(mesh, "primitives", where);
    });
    forEachObject("nodes", "node", [&](const nlohmann::json& node, const std::string& where) {
        needArray(node, "children", where);
    });
    forEachObject("scenes", "scene", [&](const nlohmann::json& scene, const std::string& where) {
        needArray(scene, "nodes", where);
    });
}

// The file's bytes with its JSON replaced by `json` (a binary file's other chunks kept).
std::string withJson(const std::string& bytes, bool binary, const std::string& json) {
    if (!binary) return json;
    std::string chunk = json;
    while (chunk.size() % 4) chunk += ' ';
    const size_t rest = std::min(bytes.size(), 20 + jsonOf(bytes, binary).size());
    std::string out = bytes.substr(0, 12);
    const auto word = [&](uint32_t v) { out.append(reinterpret_cast<const char*>(&v), sizeof v); };
    word(static_cast<uint32_t>(chunk.size()));
    word(0x4E4F534A);  // JSON
    out += chunk;
    out.append(bytes, rest, std::string::npos);
    const auto length = static_cast<uint32_t>(out.size());
    std::memcpy(out.data() + 8, &length, sizeof length);
    return out;
}

// The model of a glTF file's bytes (JSON, or binary by its magic), its URIs read through `files`.
tinygltf::Model loadModel(const std::string& bytes, const std::string& path,
                          tinygltf::FsCallbacks files, std::vector<std::string>* images) {
    if (bytes.size() > std::numeric_limits<uint32_t>::max()) throw Error(path + ": larger than 4 GB");
    const bool binary = bytes.compare(0, 4, "glTF") == 0;
    nlohmann::json document = nlohmann::json::parse(jsonOf(bytes, binary), nullptr, /*allow_exceptions=*/false);
    std::string rewritten;  // the bytes tinygltf reads when they differ from the file's
    if (document.is_object()) {  // else tinygltf says what is wrong with it
        checkRequiredExtensions(document, path);
        checkArrays(document, path);
        bool changed = giveMeshoptFallbacksData(document);
        changed = giveDracoIndicesAView(document) || changed;
        if (changed) rewritten = withJson(bytes, binary, document.dump());
    }
    const std::string& read = rewritten.empty() ? bytes : rewritten;
    tinygltf::TinyGLTF loader;
    loader.SetFsCallbacks(files);
    loader.SetImageLoader(keepEncodedImage, images);
    tinygltf::Model model;
    std::string error;
    std::string warning;
    const auto size = static_cast<unsigned int>(read.size());
    const bool loaded =
        binary ? loader.LoadBinaryFromMemory(&model, &error, &warning,
                                             reinterpret_cast<const unsigned char*>(read.data()), size, "")
               : loader.LoadASCIIFromString(&model, &error, &warning, read.data(), size, "");
    if (!loaded) {
        const std::string reason = firstLine(error);
        throw Error(path + ": " + (reason.empty() ? "not a glTF file" : reason));
    }
    return model;
}

}  // namespace

std::vector<SceneFile> readGltfScene(const std::filesystem::path& path) {
    std::vector<SceneFile> files{{path.filename().string(), readTextFile(path, "scene")}};
    FolderFiles folder{path.parent_path(), {}};
    std::vector<std::string> images;
    loadModel(files.front().bytes, path.string(),
              tinygltf::FsCallbacks{folderFileExists, sameName, readFolderFile, nullptr, &folder}, &images);
    files.insert(files.end(), std::make_move_iterator(folder.read.begin()),
                 std::make_move_iterator(folder.read.end()));
    return files;
}

ParsedScene parseGltfScene(const SceneBundle& bundle, LoadReport* report, const SceneBudget& budget) {
    const SceneFile& main = bundle.files.front();
    const std::string path = bundle.pathOf(main.name);
    // tinygltf takes a non-const user pointer; the bundle callbacks only read through it.
    auto* files = const_cast<SceneBundle*>(&bundle);
    std::vector<std::string> images;
    tinygltf::Model model = loadModel(
        main.bytes, path, tinygltf::FsCallbacks{bundleFileExists, sameName, readBundleFile, nullptr, files}, &images);
    decodeMeshoptBufferViews(model, path);
    decodeDracoPrimitives(model, path);
    GltfModel gltf{model, path, images, {}};
    warnUnreadExtensions(gltf);
    std::vector<std::string> textureWarnings;
    SceneTextures textures(bundle, textureWarnings, TextureBudget(budget.textureBytes));
    size_t dropped = 0;
    ParsedScene parsed = buildGltfScene(gltf, textures, budget, dropped);
    if (report) {
        report->faces = parsed.mesh.triangles.size();
        report->droppedTriangles = dropped;
        report->textureBytes = textures.budget().used();
        report->warnings.insert(report->warnings.end(), gltf.warnings.begin(), gltf.warnings.end());
        report->warnings.insert(report->warnings.end(), textureWarnings.begin(), textureWarnings.end());
    }
    return parsed;
}

}  // namespace strata
