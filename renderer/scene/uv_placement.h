#pragma once
// MTL's texture options -s (scale) and -o (offset) place a texture on its material's faces: the
// texture is looked up at uv * scale + offset, as Blender's importer (a Mapping node) and
// three.js (repeat and offset) read them; -s 4 4 repeats a tile four times across the UV square.
// Strata's textures have no placement of their own (one texture file can serve several
// materials), so a material's placement moves the UVs of its faces, as glTF's
// KHR_texture_transform does (gltf_materials.h): a vt that faces of differently placed materials
// share is copied, once per placement.
#include <glm/vec2.hpp>
#include <vector>

#include "scene/mesh.h"

namespace strata {

struct UvPlacement {
    glm::vec2 scale{1.0f};
    glm::vec2 offset{0.0f};

    bool isIdentity() const { return scale == glm::vec2(1.0f) && offset == glm::vec2(0.0f); }
    bool operator==(const UvPlacement&) const = default;
    glm::vec2 apply(glm::vec2 uv) const { return uv * scale + offset; }
};

// Moves the UVs of every triangle of material m by placements[m] (materials past the end keep
// theirs), copying each vt the first time a placed material uses it.
void placeUvs(MeshData& mesh, const std::vector<UvPlacement>& placements);

}  // namespace strata
