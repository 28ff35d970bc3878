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
#include <limits>
#include <optional>
#include <string_view>
#include <utility>
#include <nlohmann/json.hpp>

#include "scene/gltf_binary.h"
#include "scene/gltf_draco.h"
#include "scene/gltf_meshopt.h"
#include "scene/gltf_nodes.h"
#include "scene/gltf_version1.h"
#include "scene/scene_textures.h"
#include "util/error.h"
#include "util/little_endian.h"
#include "util/printable.h"
#include "util/text_file.h"

namespace strata {
namespace {

// The extensions Strata reads (gltf_materials.h says how far for the materials'); another one in
// extensionsRequired means the file cannot be rendered as its author meant (glTF 2.0, "Specifying
// Extensions"), and one in extensionsUsed only is a warning. The compressions are decoded
// (gltf_meshopt.h, gltf_draco.h) before the model is read.
constexpr std::array<std::string_view, 17> kImplementedExtensions{
    "EXT_mesh_gpu_instancing",
    "EXT_meshopt_compression",
    "EXT_texture_webp",
    "KHR_draco_mesh_compression",
    "KHR_lights_punctual",
    "KHR_materials_clearcoat",
    "KHR_materials_emissive_strength",
    "KHR_materials_ior",
    "KHR_materials_pbrSpecularGlossiness",
    "KHR_materials_sheen",
    "KHR_materials_specular",
    "KHR_materials_transmission",
    "KHR_materials_unlit",
    "KHR_materials_volume",
    "KHR_mesh_quantization",
    "KHR_meshopt_compression",
    "KHR_texture_transform"};

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

// The files of a glTF's URIs while reading, through the scene's folder, each kept for the bundle.
// A refusal cannot leave through tinygltf as an exception: it is kept, the file reported missing,
// and thrown once tinygltf returns.
struct FolderFiles {
    SceneFolder& folder;
    std::string where;  // "PATH: URI", starting the folder's messages
    std::vector<SceneFile> read;
    std::optional<Error> refusal;

    const SceneFile* find(const std::string& name) const {
        const auto it =
            std::find_if(read.begin(), read.end(), [&](const SceneFile& file) { return file.name == name; });
        return it == read.end() ? nullptr : &*it;
    }
};

// tinygltf asks for a URI's file here before reading it (by the URI %-decoded, then by
// "./" and that), so the file is read now.
bool folderFileExists(const std::string& name, void* user) {
    auto& files = *static_cast<FolderFiles*>(user);
    if (files.refusal) return false;
    if (files.find(name)) return true;
    try {
        std::optional<std::string> bytes = files.folder.read(name, files.where);
        if (!bytes) return false;
        files.read.push_back({name, std::move(*bytes)});
        return true;
    } catch (const Error& error) {
        files.refusal = error;
        return false;
    }
}

bool readFolderFile(std::vector<unsigned char>* out, std::string* /*err*/, const std::string& name,
                    void* user) {
    const SceneFile* file = static_cast<FolderFiles*>(user)->find(name);
    if (!file) return false;
    out->assign(file->bytes.begin(), file->bytes.end());
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

// A binary glTF's layout against its size (glTF 2.0, "Binary glTF Layout"): the 12-byte header
// (magic, version 2, the total length), then chunks of an 8-byte header (length, type) and their
// data, all within the length and the length within the file. tinygltf 2.7 does not check all of
// it (a BIN chunk whose length counts its header's 8 bytes as data is read 8 bytes past the end).
void checkBinaryLayout(std::string_view bytes, const std::string& path) {
    const auto fail = [&](const std::string& what) { throw Error(path + ": " + what); };
    if (bytes.size() < 12) fail("shorter than a binary glTF's 12-byte header");
    if (const uint32_t version = littleEndian32(bytes, 4); version != 2) {
        fail("binary glTF version " + std::to_string(version) + "; Strata reads version 2");
    }
    const size_t length = littleEndian32(bytes, 8);
    if (length > bytes.size()) {
        fail("the binary glTF header gives a length of " + std::to_string(length) + " bytes, the file has " +
             std::to_string(bytes.size()));
    }
    size_t chunk = 0;
    for (size_t offset = 12; offset < length; ++chunk) {
        const std::string name = "binary glTF chunk " + std::to_string(chunk);
        if (length - offset < 8) fail(name + "'s 8-byte header runs past the end of the file");
        const size_t data = littleEndian32(bytes, offset);
        if (data > length - offset - 8) {
            fail(name + " claims " + std::to_string(data) + " bytes, " + std::to_string(length - offset - 8) +
                 " are left");
        }
        offset += 8 + data;
    }
}

// The JSON of a glTF file: all of it, or a binary file's first chunk (checkBinaryLayout's).
std::string_view jsonOf(const std::string& bytes, bool binary) {
    if (!binary) return bytes;
    if (bytes.size() < 20) return {};
    return std::string_view(bytes).substr(20, littleEndian32(bytes, 12));
}

// The asset's version as written ("2.0", or a number such as the 1 some exporters wrote), or ""
// where it gives none.
std::string versionOf(const nlohmann::json& document) {
    const auto asset = document.find("asset");
    if (asset == document.end() || !asset->is_object()) return "";
    const auto version = asset->find("version");
    if (version == asset->end() || !(version->is_string() || version->is_number())) return "";
    return version->is_string() ? version->get<std::string>() : version->dump();
}

std::string majorOf(const std::string& version) { return version.substr(0, version.find('.')); }

// Refuses a version other than 1 (upgraded, gltf_version1.h) and 2; a later minor version of 2 is
// read.
void checkVersion(const std::string& version, const std::string& path) {
    if (version.empty() || majorOf(version) == "2") return;
    throw Error(path + ": glTF version " + printable(version) + "; Strata reads version 2");
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
            throw Error(path + ": requires extension " + printable(name) + ", which Strata does not implement");
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

// Refuses an image whose buffer view runs past the end of its buffer (glTF 2.0, "Buffers and
// Buffer Views": byteOffset + byteLength <= the buffer's byteLength): tinygltf 2.7 hands such a
// view to the image callback unchecked, reading past the buffer's data. Other views are checked
// where an accessor reads them (gltf_accessors.h), and malformed numbers are left to tinygltf,
// which names them.
void checkImageViews(const nlohmann::json& document, const std::string& path) {
    const auto list = [&](const char* key) -> const nlohmann::json* {
        const auto it = document.find(key);
        return it != document.end() && it->is_array() ? &*it : nullptr;
    };
    const nlohmann::json* images = list("images");
    const nlohmann::json* views = list("bufferViews");
    const nlohmann::json* buffers = list("buffers");
    if (!images || !views || !buffers) return;
    const auto whole = [](const nlohmann::json& object, const char* key, uint64_t otherwise) -> std::optional<uint64_t> {
        if (!object.is_object()) return std::nullopt;
        const auto it = object.find(key);
        if (it == object.end()) return otherwise;
        if (it->is_number_unsigned()) return it->get<uint64_t>();
        return std::nullopt;
    };
    for (size_t i = 0; i < images->size(); ++i) {
        // An image without a view (a URI's) reads as the view one past the last: none.
        const auto v = whole((*images)[i], "bufferView", views->size());
        if (!v || *v >= views->size()) continue;
        const nlohmann::json& view = (*views)[*v];
        const auto b = whole(view, "buffer", buffers->size());
        if (!b || *b >= buffers->size()) continue;
        const auto offset = whole(view, "byteOffset", 0);
        const auto length = whole(view, "byteLength", 0);
        const auto size = whole((*buffers)[*b], "byteLength", 0);
        if (!offset || !length || !size) continue;
        if (*offset > *size || *length > *size - *offset) {
            throw Error(path + ": image " + std::to_string(i) + ": bufferView " + std::to_string(*v) + " (byteOffset " +
                        std::to_string(*offset) + ", byteLength " + std::to_string(*length) +
                        ") runs past the end of buffer " + std::to_string(*b) + " (" + std::to_string(*size) +
                        " bytes)");
        }
    }
}

// The file's bytes with its JSON replaced by `json` (a binary file's other chunks kept).
std::string withJson(const std::string& bytes, bool binary, const std::string& json) {
    if (!binary) return json;
    const size_t rest = std::min(bytes.size(), 20 + jsonOf(bytes, binary).size());
    return glbOf(json, std::string_view(bytes).substr(rest));
}

constexpr const char* kUpgradedNote =
    "glTF 1.0, read as 2.0: its Blinn-Phong materials as specular-glossiness ones; shaders, skins, "
    "animations and lights not read";

// The model of a glTF file's bytes (JSON, or binary by its magic), its URIs read through `files`;
// a glTF 1.0 file's is its upgrade's, with kUpgradedNote in `notes`.
tinygltf::Model loadModel(const std::string& bytes, const std::string& path, tinygltf::FsCallbacks files,
                          std::vector<std::string>* images, std::vector<std::string>& notes) {
    if (bytes.size() > std::numeric_limits<uint32_t>::max()) throw Error(path + ": larger than 4 GB");
    const bool binary = bytes.compare(0, 4, "glTF") == 0;
    const auto upgraded = [&](const nlohmann::json& document, std::string_view body) {
        notes.push_back(kUpgradedNote);
        return loadModel(upgradeGltfVersion1(document, body, binary, path), path, files, images, notes);
    };
    if (binary && isBinaryGltfVersion1(bytes)) {
        const BinaryGltfVersion1 parts = splitBinaryGltfVersion1(bytes, path);
        return upgraded(nlohmann::json::parse(parts.content, nullptr, /*allow_exceptions=*/false), parts.body);
    }
    if (binary) checkBinaryLayout(bytes, path);
    nlohmann::json document = nlohmann::json::parse(jsonOf(bytes, binary), nullptr, /*allow_exceptions=*/false);
    std::string rewritten;  // the bytes tinygltf reads when they differ from the file's
    if (document.is_object()) {  // else tinygltf says what is wrong with it
        const std::string version = versionOf(document);
        if (majorOf(version) == "1") return upgraded(document, {});
        checkVersion(version, path);
        checkRequiredExtensions(document, path);
        checkArrays(document, path);
        checkImageViews(document, path);
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
        // tinygltf's text may quote the file: a name, a whole data: URI.
        throw Error(path + ": " + (reason.empty() ? "not a glTF file" : printable(reason, reason.size())));
    }
    return model;
}

}  // namespace

std::vector<SceneFile> readGltfScene(const std::filesystem::path& path, SceneFolder& folder) {
    std::vector<SceneFile> files{{path.filename().string(), readTextFile(path, "scene")}};
    const std::string name = printable(path.string());
    FolderFiles uris{folder, name + ": URI", {}, std::nullopt};
    std::vector<std::string> images;
    std::vector<std::string> notes;  // given when the bundle is parsed
    try {
        loadModel(files.front().bytes, name,
                  tinygltf::FsCallbacks{folderFileExists, sameName, readFolderFile, nullptr, &uris}, &images,
                  notes);
    } catch (const Error&) {
        if (!uris.refusal) throw;
    }
    // Refused, the file was missing to tinygltf, which may have gone on or failed for it.
    if (uris.refusal) throw *uris.refusal;
    files.insert(files.end(), std::make_move_iterator(uris.read.begin()),
                 std::make_move_iterator(uris.read.end()));
    return files;
}

ParsedScene parseGltfScene(const SceneBundle& bundle, LoadReport* report, const SceneBudget& budget) {
    const SceneFile& main = bundle.files.front();
    const std::string path = bundle.pathOf(main.name);
    // tinygltf takes a non-const user pointer; the bundle callbacks only read through it.
    auto* files = const_cast<SceneBundle*>(&bundle);
    std::vector<std::string> images;
    std::vector<std::string> notes;
    tinygltf::Model model =
        loadModel(main.bytes, path, tinygltf::FsCallbacks{bundleFileExists, sameName, readBundleFile, nullptr, files},
                  &images, notes);
    decodeMeshoptBufferViews(model, path);
    decodeDracoPrimitives(model, path);
    GltfModel gltf{model, path, images, {}};
    for (const std::string& note : notes) gltf.warnOnce(note);
    warnUnreadExtensions(gltf);
    std::vector<std::string> textureWarnings;
    SceneTextures textures(bundle, textureWarnings, TextureBudget(budget.textureBytes, budget.textureBytesSpent));
    size_t dropped = 0;
    ParsedScene parsed = buildGltfScene(gltf, textures, budget, dropped);
    if (report) {
        report->faces = parsed.mesh.triangles.size();
        report->droppedTriangles = dropped;
        report->textureBytes = textures.budget().used() - budget.textureBytesSpent;
        report->warnings.insert(report->warnings.end(), gltf.warnings.begin(), gltf.warnings.end());
        report->warnings.insert(report->warnings.end(), textureWarnings.begin(), textureWarnings.end());
    }
    return parsed;
}

}  // namespace strata
