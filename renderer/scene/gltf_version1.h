#pragma once
// glTF 1.0 files (Khronos' first version, 2015-2017: collada2gltf's output, Cesium's and the
// early sample models) read as the glTF 2.0 file that says the same, as far as Strata renders it.
// The structure is upgraded as Cesium's gltf-pipeline (updateVersion) upgrades it:
//   - every list is an object keyed by name in 1.0, an array in 2.0: names become indices, and a
//     part without a name of its own is named by its 1.0 name;
//   - an accessor's byteStride moves to a buffer view of its own;
//   - a node's list of meshes becomes a child node per mesh beyond one;
//   - TEXCOORD and COLOR without a set index are set 0;
//   - a binary file (KHR_binary_glTF: a 20-byte header, the JSON, the body) becomes a 2.0 .glb
//     whose BIN chunk is the body, and images in the body keep their buffer views.
// The materials are Strata's own reading: a material (KHR_materials_common, or a technique's
// values and their defaults) is Blinn-Phong's diffuse, specular, shininess and emission, read as
// KHR_materials_pbrSpecularGlossiness's diffuse and specular (F0), the glossiness 1 - roughness
// from the shininess as an MTL's Ns is read (materials/microfacet.h), and the emission as glTF
// 2.0's. Shaders, techniques' programs, skins, animations and KHR_materials_common's lights are
// not read.
#include <string>
#include <string_view>
#include <nlohmann/json.hpp>

namespace strata {

// Whether `bytes` are a binary glTF 1.0 file, by its header's version.
bool isBinaryGltfVersion1(std::string_view bytes);

// A binary glTF 1.0 file's parts (KHR_binary_glTF: a 20-byte header, the JSON content, the body),
// views into its bytes; throws strata::Error naming `path` where the header does not fit them.
struct BinaryGltfVersion1 {
    std::string_view content;
    std::string_view body;
};
BinaryGltfVersion1 splitBinaryGltfVersion1(std::string_view bytes, const std::string& path);

// The glTF 2.0 file that says what the glTF 1.0 JSON `document` says: a .glb whose BIN chunk is
// `body` where the file was `binary`, else JSON. Throws strata::Error naming `path` and what
// cannot be read: a document that is not an object, a list that is not an object keyed by name,
// a name that names nothing.
std::string upgradeGltfVersion1(const nlohmann::json& document, std::string_view body, bool binary,
                                const std::string& path);

}  // namespace strata
