#pragma once
// What `strata bench --vs-cycles` writes for Blender so that Cycles reads a scene's files as
// Strata does: textures decoded by Strata's own code into linear float EXRs (Blender then filters
// the values Strata filters), the rotation that takes Strata's latitude-longitude convention to
// Cycles' equirectangular one, and a glTF model whose materials are all one conductor Cycles can
// express.
#include <filesystem>
#include <glm/mat3x3.hpp>

#include "scene/mesh.h"
#include "textures/texture.h"

namespace strata {

// Writes `texture`'s texels as Strata's lookups read them (8-bit colour codes through the sRGB
// table, linear values as they are) to a float EXR, top row first, RGB (grey widened).
// Cycles 3.4 filters an 8-bit sRGB image before decoding it, Strata decodes each texel first;
// given the decoded floats as a linear image, both blend the same values.
void writeLinearTexture(const Texture& texture, const std::filesystem::path& exr);

// The rotation M such that Cycles' equirectangular lookup of M d (Z up, the image's centre along
// +x, u growing from +x toward -y) reads the texel Strata's map turned by `rotationDegrees` about
// +y reads along the world direction d (lights/environment_map_light.h: +y up, the centre along
// -z, phi growing toward +x). The script turns the whole scene by M rather than the lookup, so
// that Cycles' importance map of the world, laid out in its own equirectangular cells, falls on
// the map's texels (a turned lookup would blur the sun over cells that miss it: fireflies).
glm::mat3 cyclesEnvironmentFrame(float rotationDegrees);

// Writes the mesh as Strata holds it, every shared mesh drawn at each of its placements, to an
// OBJ in world coordinates (per-corner positions, normals and texture coordinates; a flat
// triangle's normal is its own) with a MTL of its material names beside it (NAME.mtl), for
// Blender's OBJ importer: any format Strata reads reaches Cycles with Strata's triangles, and
// Blender's glTF importer (which needs numpy) is not involved.
void writeMeshObj(const MeshData& mesh, const std::filesystem::path& obj);

// Copies the binary glTF `glb` to `out` with every primitive given one material: glTF's
// metallic-roughness model at base colour 1, metallic 1 and `roughness`. Its only lobe is then
// GGX with Schlick's F at F0 = 1, that is F = 1: what Cycles 3.4's Glossy BSDF (GGX, no Fresnel)
// computes. Throws strata::Error naming `glb` when it is not a binary glTF.
void writeWhiteMetalGlb(const std::filesystem::path& glb, const std::filesystem::path& out, float roughness);

}  // namespace strata
