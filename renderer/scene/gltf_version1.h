#pragma once
// glTF 1.0 files (Khronos' first version, 2015-2017: collada2gltf's output, Cesium's and the
// early sample models) read as the glTF 2.0 file that says the same, as far as Strata renders it,
// the way Khronos' gltf-pipeline upgrades them:
//   - every list is an object keyed by name in 1.0, an array in 2.0: names become indices;
//   - an accessor's byteStride moves to a buffer view of its own;
//   - a node's list of meshes becomes a child node per mesh beyond one;
//   - a binary file (KHR_binary_glTF: a 20-byte header, the JSON, the body) becomes a 2.0 .glb
//     whose BIN chunk is the body, and images in the body keep their buffer views;
//   - a material (KHR_materials_common, or a technique's values and their defaults) is
//     Blinn-Phong's diffuse, specular, shininess and emission: read as
//     KHR_materials_pbrSpecularGlossiness's diffuse and specular (F0), the glossiness
//     1 - roughness from the shininess as an MTL's Ns is read (materials/microfacet.h), and the
//     emission as glTF 2.0's.
// Shaders, techniques' programs, skins, animations and KHR_materials_common's lights are not read.
#include <string>
#include <string_view>
#include <nlohmann/json.hpp>

namespace strata {

// Whether `bytes` are a binary glTF 1.0 file, by its header's version.
bool isBinaryGltfVersion1(std::string_view bytes);
// Whether a glTF file's JSON `document` is glTF 1.0's, by its asset's version ("1.0", "1.0.1" or
// the number 1).
bool isGltfVersion1(const nlohmann::json& document);

// The glTF 2.0 file (binary where `bytes` are) that says what the glTF 1.0 file `bytes` says.
// Throws strata::Error naming `path` and what cannot be read: a header or layout that is not
// glTF's, a list that is not an object, a name that names nothing.
std::string upgradeGltfVersion1(const std::string& bytes, const std::string& path);

}  // namespace strata
