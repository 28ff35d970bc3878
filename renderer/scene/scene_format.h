#pragma once
// Scene file formats behind one door. A scene is read in two steps, so that MPI rank 0 can read
// it and every rank parse the same bytes (app/render_job.h):
//   reading: the main file's path -> every file the scene needs, as bytes (a SceneBundle);
//   parsing: a SceneBundle -> MeshData (and the camera a format may carry), from memory only.
// Each format provides the two in its own loader file and is one line of the table in
// scene_format.cpp; the main file's extension picks it.
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "scene/camera.h"
#include "scene/mesh.h"
#include "textures/texture_budget.h"
#include "scene/model_orientation.h"
#include "scene/scene_folder.h"

namespace strata {

struct LoadReport {
    size_t faces = 0;             // triangles read
    size_t droppedTriangles = 0;  // degenerate ones removed (zero area, non-finite vertices)
    size_t nonFiniteVertices = 0; // vertices with a nan/inf coordinate (their triangles dropped)
    uint64_t textureBytes = 0;    // the decoded texels of the materials' textures (texture_budget.h)
    // What was tolerated and how, or what the scene file holds that Strata does not render (yet),
    // one line each naming the file and line where there is one:
    // "cube.obj:12: material 'red' is not defined; using grey Kd 0.8".
    std::vector<std::string> warnings;
};

// What a scene may cost, checked while it is parsed, before its geometry is read into memory: the
// triangles it stores after instancing, each shared mesh's once (mesh.h), plus
// kTrianglesPerInstance for each placement of a shared mesh. Memory follows that count, not the
// triangles placed in the world: a stored triangle costs its vertices, indices, normals and BVH
// share, about 175 bytes (peak RSS of 10^7 flattened grid triangles: 1.75 GB), and a placement an
// Embree instance and its record, about 570 bytes however large its mesh (10^3 to 10^4 instances
// of one 10^4-triangle grid: 17.0 to 22.1 MB; scripts/make_instancing_case.py). The default is
// what a desktop survives: some 9 GB.
//
// Decoded texels, all the scene's textures and its environment map together, are budgeted as
// well (textures/texture_budget.h), refused before the file that would go over is decoded.
struct SceneBudget {
    uint64_t triangles = 50'000'000;                // --max-triangles
    uint64_t textureBytes = kDefaultTextureBudget;  // --texture-budget
    // Texels decoded before the scene's own files (an --env map), which share the budget with them.
    uint64_t textureBytesSpent = 0;
};
inline constexpr uint64_t kTrianglesPerInstance = 3;

// A scene's triangles as the budget counts them (stored and placements) and as its world has
// them (placed, which only the message reports).
struct TriangleCount {
    uint64_t stored = 0;
    uint64_t placements = 0;
    uint64_t placed = 0;
};

// Throws strata::Error "PATH: N triangles after instancing (...) exceed the budget of B
// triangles (--max-triangles N raises it)" when stored + 3 placements is over the budget.
void checkTriangleBudget(const std::string& path, const TriangleCount& count, const SceneBudget& budget);

// What a format's parse gives: the mesh and, for a format that carries cameras (glTF), the pose
// of the scene's own camera, which the scene takes when no description or --camera file gives one;
// and the model's orientation, which the default camera takes otherwise (default_camera.h).
struct ParsedScene {
    MeshData mesh;
    std::optional<CameraPose> camera;
    ModelOrientation orientation = kGltfOrientation;
};

struct SceneFile {
    std::string name;  // relative to the main file's folder, as the scene refers to it
    std::string bytes;
};

// A scene's files, read once and parsed anywhere: the names are relative to the main file's
// folder, so a bundle parses to the same scene on any host.
struct SceneBundle {
    // The main file as it was given where the bundle was read; messages name files by it.
    std::filesystem::path path;
    // The format's files, the main one first (named path.filename()), then those it refers to
    // (an OBJ's MTL files), then those the scene description refers to.
    std::vector<SceneFile> files;
    // NAME.json beside the main file (scene_description.h), when there is one.
    std::optional<SceneFile> description;
    // The --camera file, when one was given, named as given: it need not lie in the folder.
    std::optional<SceneFile> camera;
    // A line for each file read from outside the main file's folder, as
    // SceneReadOptions::allowOutsideFiles allows (scene_folder.h); parseScene reports them among
    // the warnings. Kept where the bundle was read, which is where messages are printed.
    std::vector<std::string> outsideNotes = {};
    // The environment map a front end was given in place of the description's (strata's --env),
    // named as given. parseScene leaves it to that front end, which holds its other settings
    // (the rotation); it travels here so that every MPI rank decodes the bytes rank 0 read.
    std::optional<SceneFile> environmentMap = std::nullopt;

    // The file of that name among `files`; null when there is none.
    const SceneFile* find(std::string_view name) const;
    // A file of `files` or the description as messages name it: the main file's folder / name,
    // printable (util/printable.h).
    std::string pathOf(const std::string& name) const;
};

struct SceneFormat {
    std::vector<std::string_view> extensions;  // lower case, with the dot
    // The main file (`path`, which exists) and every file it refers to, read through `folder`
    // (scene_folder.h: the main file's folder, which refuses references that leave it); throws
    // strata::Error naming a missing or malformed file or a refused reference.
    std::vector<SceneFile> (*read)(const std::filesystem::path& path, SceneFolder& folder);
    // The mesh (and camera) from a bundle's files, its textures within `budget`; throws
    // strata::Error naming the file (and line), or the budget the scene exceeds (triangles before
    // reading its geometry, texels before decoding a texture).
    ParsedScene (*parse)(const SceneBundle& bundle, LoadReport* report, const SceneBudget& budget);
};

// The format of `path` by its extension, in any case; throws strata::Error
// "PATH: unknown scene format '.EXT' (known: .obj, .gltf, .glb)" for one that is not in the table (and names
// the known ones too when there is no extension).
const SceneFormat& sceneFormatOf(const std::filesystem::path& path);

// The extension of `path` in lower case, with the dot, as formats are told by it:
// "ROOM.OBJ" -> ".obj".
std::string lowerCaseExtension(const std::filesystem::path& path);

// The registered extensions, lower case with the dot, in the table's order: what a file chooser
// lists as scene files.
std::vector<std::string_view> sceneExtensions();

// The registered extensions for messages and help: ".obj, .gltf, .glb".
std::string knownSceneExtensions();

// The mesh and camera of `bundle`, parsed by the format of its main file within `budget`.
ParsedScene parseSceneFile(const SceneBundle& bundle, LoadReport* report = nullptr, const SceneBudget& budget = {});

// The mesh alone: parseSceneFile(...).mesh.
MeshData parseSceneMesh(const SceneBundle& bundle, LoadReport* report = nullptr);

}  // namespace strata
