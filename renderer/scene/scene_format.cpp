#include "scene/scene_format.h"

#include <algorithm>
#include <cctype>

#include "scene/gltf_loader.h"
#include "scene/obj_loader.h"
#include "util/error.h"

namespace strata {
namespace {

// An OBJ carries no camera, and states no axes: its orientation is read from the model.
ParsedScene parseObjFormat(const SceneBundle& bundle, LoadReport* report, const SceneBudget& budget) {
    ParsedScene parsed{parseObjScene(bundle, report, budget), std::nullopt};
    parsed.orientation = objOrientation(parsed.mesh);
    return parsed;
}

// Every format Strata reads. A new one is its loader and one line here.
const std::vector<SceneFormat>& sceneFormats() {
    static const std::vector<SceneFormat> formats = {
        {{".obj"}, readObjScene, parseObjFormat},
        {{".gltf", ".glb"}, readGltfScene, parseGltfScene},
    };
    return formats;
}

}  // namespace

std::string lowerCaseExtension(const std::filesystem::path& path) {
    std::string extension = path.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension;
}

const SceneFile* SceneBundle::find(std::string_view name) const {
    const auto it = std::find_if(files.begin(), files.end(),
                                 [&](const SceneFile& file) { return file.name == name; });
    return it == files.end() ? nullptr : &*it;
}

std::string SceneBundle::pathOf(const std::string& name) const {
    return (path.parent_path() / name).string();
}

const SceneFormat& sceneFormatOf(const std::filesystem::path& path) {
    const std::string extension = path.extension().string();
    const std::string wanted = lowerCaseExtension(path);
    for (const SceneFormat& format : sceneFormats()) {
        for (std::string_view known : format.extensions) {
            if (known == wanted) return format;
        }
    }
    const std::string known = " (known: " + knownSceneExtensions() + ")";
    if (extension.empty()) throw Error(path.string() + ": no extension to tell the scene format" + known);
    throw Error(path.string() + ": unknown scene format '" + extension + "'" + known);
}

std::vector<std::string_view> sceneExtensions() {
    std::vector<std::string_view> extensions;
    for (const SceneFormat& format : sceneFormats()) {
        extensions.insert(extensions.end(), format.extensions.begin(), format.extensions.end());
    }
    return extensions;
}

std::string knownSceneExtensions() {
    std::string known;
    for (std::string_view extension : sceneExtensions()) {
        if (!known.empty()) known += ", ";
        known += extension;
    }
    return known;
}

namespace {
// Every warning as lines of their own, none empty: a loader's message may carry a library's
// multi-line text or a name read from the file with its control characters.
void splitIntoLines(std::vector<std::string>& warnings, size_t from) {
    std::vector<std::string> lines(warnings.begin(), warnings.begin() + static_cast<std::ptrdiff_t>(from));
    for (size_t i = from; i < warnings.size(); ++i) {
        size_t start = 0;
        const std::string& text = warnings[i];
        while (start <= text.size()) {
            size_t end = text.find_first_of("\r\n", start);
            if (end == std::string::npos) end = text.size();
            if (end > start) lines.push_back(text.substr(start, end - start));
            start = end + 1;
        }
    }
    warnings = std::move(lines);
}
}  // namespace

namespace {
std::string counted(uint64_t n, const std::string& thing) {
    return std::to_string(n) + " " + thing + (n == 1 ? "" : "s");
}
}  // namespace

void checkTriangleBudget(const std::string& path, const TriangleCount& count, const SceneBudget& budget) {
    if (count.stored <= budget.triangles &&
        count.placements <= (budget.triangles - count.stored) / kTrianglesPerInstance) {
        return;
    }
    std::string message = path + ": " + counted(count.stored, "triangle") + " after instancing";
    if (count.placements > 0) {
        message += " and " + counted(count.placements, "instance") + " (counted as " +
                   std::to_string(kTrianglesPerInstance) + " triangles each; " + counted(count.placed, "triangle") +
                   " placed)";
    }
    throw Error(message + " exceed the budget of " + counted(budget.triangles, "triangle") +
                " (--max-triangles N raises it)");
}

ParsedScene parseSceneFile(const SceneBundle& bundle, LoadReport* report, const SceneBudget& budget) {
    const SceneFormat& format = sceneFormatOf(bundle.path);
    if (bundle.files.empty()) throw Error(bundle.path.string() + ": the scene's files are missing");
    const size_t before = report ? report->warnings.size() : 0;
    ParsedScene parsed = format.parse(bundle, report, budget);
    if (report) splitIntoLines(report->warnings, before);
    return parsed;
}

MeshData parseSceneMesh(const SceneBundle& bundle, LoadReport* report) {
    return parseSceneFile(bundle, report).mesh;
}

}  // namespace strata
