#pragma once
// OBJ + MTL scenes through tinyobjloader. tinyobjloader accepts almost anything (a malformed
// number reads as 0), so each file is first checked line by line: a bad line is reported as
// "FILE:LINE: what is wrong" rather than rendered as silently wrong geometry.
#include <filesystem>
#include <string>

#include "scene/mesh.h"

namespace strata {

struct ObjLoadReport {
    size_t faces = 0;             // triangles read
    size_t droppedTriangles = 0;  // degenerate ones removed (zero area, non-finite vertices)
    size_t nonFiniteVertices = 0; // vertices with a nan/inf coordinate (their triangles dropped)
};

// The text of an OBJ and of the MTL files its `mtllib` lines name (joined), with the names used in
// messages: read once (e.g. on MPI rank 0) and parsed anywhere with parseObj.
struct ObjFiles {
    std::string objText;
    std::string objName;
    std::string mtlText;
    std::string mtlName;
};

// Reads `path` and its MTL files (relative to its folder), checking each file line by line.
// Throws strata::Error naming the file and line on malformed input or a missing file.
ObjFiles readObjFiles(const std::filesystem::path& path);

// Loads `path` and the MTL files its `mtllib` lines name (relative to its folder). Throws
// strata::Error naming the file and line on malformed input, a missing file or material.
MeshData loadObjFile(const std::filesystem::path& path, ObjLoadReport* report = nullptr);

// The same from memory: `mtlText` is what the OBJ's mtllib lines load (materials are read only
// when the OBJ has an mtllib line, as from files); `objName`/`mtlName` are used in messages. Used by loadObjFile and the
// loader fuzzer, so both exercise one code path.
MeshData parseObj(const std::string& objText, const std::string& objName,
                  const std::string& mtlText, const std::string& mtlName,
                  ObjLoadReport* report = nullptr);

}  // namespace strata
