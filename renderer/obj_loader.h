#pragma once
// OBJ + MTL scenes through tinyobjloader. tinyobjloader accepts almost anything (a malformed
// number reads as 0), so each file is first checked line by line: a bad line is reported as
// "FILE:LINE: what is wrong" rather than rendered as silently wrong geometry.
#include <filesystem>
#include <string>

#include "mesh.h"

namespace strata {

struct ObjLoadReport {
    size_t faces = 0;             // triangles read
    size_t droppedTriangles = 0;  // degenerate ones removed (zero area, non-finite vertices)
    size_t nonFiniteVertices = 0; // vertices with a nan/inf coordinate (their triangles dropped)
};

// Loads `path` and the MTL files its `mtllib` lines name (relative to its folder). Throws
// strata::Error naming the file and line on malformed input, a missing file or material.
MeshData loadObjFile(const std::filesystem::path& path, ObjLoadReport* report = nullptr);

// The same from memory: `objName`/`mtlName` are used in messages. Used by loadObjFile and the
// loader fuzzer, so both exercise one code path.
MeshData parseObj(const std::string& objText, const std::string& objName,
                  const std::string& mtlText, const std::string& mtlName,
                  ObjLoadReport* report = nullptr);

}  // namespace strata
