#pragma once
// glTF 2.0 materials ("Materials": metallic-roughness, "Additional Textures") onto Strata's
// layered material (material.h, metallic_roughness.h):
//   base colour     baseColorFactor x baseColorTexture (sRGB; its alpha is coverage for MASK);
//   metallic, roughness  the factors x metallicRoughnessTexture's B and G (linear);
//   emission        emissiveFactor x emissiveTexture (sRGB) x KHR_materials_emissive_strength,
//                   from the front (counter-clockwise) side only, as Strata emits; glTF's
//                   emission has no side, so a double-sided emitter lights only from its front;
//   normalTexture   a tangent-space normal map with its `scale`; the tangents come from the
//                   UVs (a TANGENT attribute is not read), the bitangent toward +v as the map's +y;
//   alphaMode MASK  cut out where base colour alpha < alphaCutoff (default 0.5); BLEND makes the
//                   alpha an opacity (material.h), OPAQUE ignores alpha;
//   KHR_materials_ior, KHR_materials_specular  the dielectric reflectance at normal incidence,
//                   ((ior - 1) / (ior + 1))^2 x specularColorFactor x specularColorTexture's RGB
//                   (sRGB), at most 1, x specularFactor x specularTexture's A (linear), and the
//                   index of refraction;
//   KHR_materials_transmission  factor x transmissionTexture's R of the dielectric part
//                   (1 - metallic) is a dielectric of that index and the material's roughness,
//                   tinted by the base colour; metallic 1 at roughness 0 is a perfect mirror;
//   KHR_materials_volume  a closed volume with Beer-Lambert absorption (attenuationColor kept
//                   after attenuationDistance) where thicknessFactor > 0, else (absent too) a thin
//                   wall (a rough thin wall transmits smooth: a warning);
//   KHR_materials_clearcoat  a coat of index 1.5 over the material, factor x clearcoatTexture's R,
//                   roughness x clearcoatRoughnessTexture's G (clearcoatNormalTexture is not
//                   applied: a warning);
//   KHR_materials_sheen  a Charlie sheen (sheen.h) between the base and the coat, colour
//                   sheenColorFactor x sheenColorTexture's RGB (sRGB), roughness
//                   sheenRoughnessFactor x sheenRoughnessTexture's A; not over a transmitting or a
//                   perfectly smooth material (a warning);
//   KHR_materials_unlit  the base colour (factor x texture x COLOR_0) shown as it is to every ray
//                   that finds it, reflecting nothing and lighting nothing by itself (material.h);
//                   only the alpha mode is read besides;
//   KHR_materials_pbrSpecularGlossiness  in place of the metallic-roughness parameters, which are
//                   then a fallback not read (specular_glossiness.h): diffuseFactor x
//                   diffuseTexture (sRGB; its alpha as base colour's for MASK), specularFactor x
//                   specularGlossinessTexture's RGB (sRGB), glossinessFactor x its A (linear).
// doubleSided needs nothing: Strata reflects on both sides of every triangle. occlusionTexture is
// not read: a path tracer finds occlusion itself. Only TEXCOORD_0 is read; a texture on another
// set is a warning. KHR_texture_transform's offset, rotation and scale move the UVs of the
// material's primitives (gltfTextureTransform), and its texCoord overrides the reference's. A
// texture that is missing or does not decode is a warning and its factor is used alone.
#include <cstddef>
#include <glm/mat3x3.hpp>

#include "materials/material.h"
#include "scene/gltf_model.h"
#include "scene/scene_textures.h"

namespace strata {

// The material `index` of the model; throws strata::Error naming it for a factor outside its range.
Material gltfMaterial(GltfModel& gltf, SceneTextures& textures, size_t index);

// KHR_texture_transform of the material's textures as a matrix on homogeneous glTF UVs (v down):
// T * R * S, rotation counter-clockwise in UV space. Strata has one UV set per primitive, so the
// material's textures share one transform: the first textured slot's (base colour, then
// metallic-roughness, or specular-glossiness's diffuse and specular-glossiness; then emissive,
// normal), with a warning when another slot's differs.
glm::dmat3 gltfTextureTransform(GltfModel& gltf, size_t index);

// The material of a primitive without one ("Materials": base colour 1, metallic 1, roughness 1).
Material gltfDefaultMaterial();

}  // namespace strata
