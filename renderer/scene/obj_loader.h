#pragma once
// The OBJ format (+ MTL) through tinyobjloader. tinyobjloader accepts almost anything (a malformed
// number reads as 0), so each file is first checked line by line: a bad line is reported as
// "FILE:LINE: what is wrong" rather than rendered as silently wrong geometry. What other tools
// open is opened too, with a warning line in the LoadReport: a usemtl of a material no MTL
// defines, an empty usemtl or a missing mtllib file give grey Kd 0.8, a vn without a direction
// shades its triangles flat.
#include <filesystem>
#include <string>
#include <vector>

#include "scene/mesh.h"
#include "scene/scene_folder.h"
#include "scene/scene_format.h"

namespace strata {

// The format's reading (scene_format.h): `path` and, through `folder` (scene_folder.h), the MTL
// files its `mtllib` lines name and the textures they name (relative to their folders) that
// exist. Throws strata::Error naming the file and line of a malformed OBJ line, or of a reference
// that `folder` refuses.
std::vector<SceneFile> readObjScene(const std::filesystem::path& path, SceneFolder& folder);

// The format's parsing: the bundle's first file as the OBJ and, from the others, the MTL files its
// `mtllib` lines name; a library not among them is a warning. Fills `triangleNormals` from the vn
// of faces that give one on every corner. Throws strata::Error naming the file and line on
// malformed input, or the budget its faces exceed (counted before any is read into the mesh), or
// a texture that would take the scene's textures over `budget`.
MeshData parseObjScene(const SceneBundle& bundle, LoadReport* report = nullptr, const SceneBudget& budget = {});

// readObjScene then parseObjScene.
MeshData loadObjFile(const std::filesystem::path& path, LoadReport* report = nullptr);

// One OBJ from text, with the checks and the mesh of parseObjScene: `mtlText` is what its mtllib
// lines load, whatever they name (materials are read only when the OBJ has an mtllib line, as from
// files); `objName`/`mtlName` are used in messages. For an OBJ and MTL written inline (tests).
MeshData parseObj(const std::string& objText, const std::string& objName,
                  const std::string& mtlText, const std::string& mtlName,
                  LoadReport* report = nullptr);

}  // namespace strata
