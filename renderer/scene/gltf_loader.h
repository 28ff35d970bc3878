#pragma once
// The glTF 2.0 format (.gltf with its buffers and images, .glb) through tinygltf. The default
// scene's node hierarchy becomes one mesh in world space (metres, gltf_nodes.h), a primitive
// that several nodes use stored once and placed at each:
// triangle primitives with their normals and UVs, the metallic-roughness materials and their
// textures (gltf_materials.h), the first camera and the KHR_lights_punctual lights
// (gltf_cameras_lights.h). tinygltf checks the JSON; the accessors, indices and node references
// it does not check are checked here (gltf_accessors.h), each failure one line naming the file and
// what is wrong.
//
// Not rendered yet, noted once in LoadReport::warnings: spot lights' cones (they light as point
// lights).
#include <filesystem>
#include <vector>

#include "scene/scene_folder.h"
#include "scene/scene_format.h"

namespace strata {

// The format's reading (scene_format.h): `path` and, through `folder` (scene_folder.h), every
// buffer and image file it refers to by URI (data: URIs are inside it), named by their URIs as
// tinygltf %-decodes them, relative to its folder; a missing image is left out (parsing warns
// and uses the material's factors alone). Throws strata::Error naming a malformed file, a
// missing buffer or a URI that `folder` refuses.
std::vector<SceneFile> readGltfScene(const std::filesystem::path& path, SceneFolder& folder);

// The format's parsing: the bundle's first file as the glTF (JSON or binary), its URIs resolved
// among the bundle's files and never on the file system. Throws strata::Error naming the file
// and the mesh, node, accessor, material or extension that Strata cannot render, or the budget
// its triangles exceed, or the texture that would take the scene's textures over `budget`.
ParsedScene parseGltfScene(const SceneBundle& bundle, LoadReport* report = nullptr, const SceneBudget& budget = {});

}  // namespace strata
