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

#include "scene/gltf_nodes.h"
#include "scene/scene_textures.h"
#include "util/error.h"
#include "util/text_file.h"

namespace strata {
namespace {

// The extensions whose every requirement Strata meets; another one in extensionsRequired means
// the file cannot be rendered as its author meant (glTF 2.0, "Specifying Extensions"), except
// KHR_texture_transform: its textures render untransformed, with a warning (the material's).
constexpr std::array<std::string_view, 4> kImplementedExtensions{
    "KHR_lights_punctual", "KHR_materials_emissive_strength", "KHR_mesh_quantization", "KHR_texture_transform"};

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
                          tinygltf::FsCallbacks files, std::vector<std::string>* images) {
    if (bytes.size() > std::numeric_limits<uint32_t>::max()) throw Error(path + ": larger than 4 GB");
    const bool binary = bytes.compare(0, 4, "glTF") == 0;
    checkRequiredExtensions(jsonOf(bytes, binary), path);
    tinygltf::TinyGLTF loader;
    loader.SetFsCallbacks(files);
    loader.SetImageLoader(keepEncodedImage, images);
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
    const tinygltf::Model model = loadModel(
        main.bytes, path, tinygltf::FsCallbacks{bundleFileExists, sameName, readBundleFile, nullptr, files}, &images);
    GltfModel gltf{model, path, images, {}};
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
