#pragma once
// A glTF model's default scene (else the first; without scenes, every root node) as one mesh in
// world space (metres): its node hierarchy applied (glTF 2.0, "Transformations": a matrix or
// T * R * S, normals by the inverse transpose, a mirroring transform keeping the front side),
// each node's mesh primitives appended (triangles, strips and fans, with NORMAL and TEXCOORD_0),
// its materials (gltf_materials.h), its camera and lights (gltf_cameras_lights.h). A primitive
// that several nodes or GPU instances (EXT_mesh_gpu_instancing) use (the same accessors, mode and
// material) is stored once, a shared mesh placed at each of them (mesh.h); one used once is
// flattened into world space.
#include "scene/gltf_model.h"
#include "scene/scene_format.h"
#include "scene/scene_textures.h"

namespace strata {

// `dropped` counts the degenerate triangles left out. Throws strata::Error naming the node, mesh,
// primitive or accessor that cannot be rendered, or the budget the scene's triangles exceed
// (counted from the accessors, before any geometry is read).
ParsedScene buildGltfScene(GltfModel& gltf, SceneTextures& textures, const SceneBudget& budget, size_t& dropped);

}  // namespace strata
