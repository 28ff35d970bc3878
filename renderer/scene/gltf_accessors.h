#pragma once
// glTF accessors read into numbers, checked against their buffer views and buffers so that no
// read leaves them, and against the component types glTF 2.0 allows for each use ("Meshes":
// attribute types, KHR_mesh_quantization's integer ones; "Accessor Data Types" for indices).
#include <cstdint>
#include <string>
#include <vector>

#include "scene/gltf_model.h"

namespace strata {

// What an accessor holds for Strata: POSITION and NORMAL are VEC3, TEXCOORD_0 VEC2, COLOR_0 VEC3
// or VEC4 (RGB or RGBA), indices SCALAR; EXT_mesh_gpu_instancing's TRANSLATION and SCALE are VEC3,
// its ROTATION a VEC4 quaternion (x, y, z, w).
enum class AccessorUse { Position, Normal, TexCoord, Colour, Index, InstanceTranslation, InstanceRotation, InstanceScale };

// The accessor's elements, their components one after another (3 or 4 per COLOR_0 element, as its
// type says; a normalized integer mapped onto [0, 1] or [-1, 1]); throws strata::Error naming
// `where` and the accessor on anything malformed.
std::vector<double> accessorValues(const GltfModel& gltf, int index, AccessorUse use, const std::string& where);

// Marks an index past the primitive's vertices among accessorIndices' answer.
constexpr uint32_t kIndexOutOfRange = UINT32_MAX;

// A primitive's indices (accessor `index`) into its `vertexCount` vertices, one out of range as
// kIndexOutOfRange: its value never goes further, since it is bytes of a buffer file, which may be
// any file (one read with --allow-outside-files, say).
std::vector<uint32_t> accessorIndices(const GltfModel& gltf, int index, size_t vertexCount,
                                      const std::string& where);

}  // namespace strata
