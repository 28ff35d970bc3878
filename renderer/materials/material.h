#pragma once
// A surface's material as scene files give it (MTL, glTF): plain data, turned into a BSDF at each
// hit by MaterialTable (material_table.h). The numbers are the material's constants; each texture,
// where there is one, multiplies its constant at the hit's UV (textures/texture.h's convention).
#include <memory>
#include <optional>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <string>

#include "textures/texture.h"

namespace strata {

// glTF's metallic-roughness parameters, kept when a texture varies them over the surface, so
// that each hit maps its own base colour and metallic onto Kd and Ks (metallic_roughness.h).
struct MetallicRoughness {
    glm::vec3 baseColor{1.0f};
    float metallic = 1.0f;
};

struct MaterialTextures {
    // RGB times Kd (MTL map_Kd), or times the base colour (glTF baseColorTexture).
    std::shared_ptr<const Texture> colour;
    // glTF metallicRoughnessTexture: G times the roughness, B times metallic.
    std::shared_ptr<const Texture> roughnessMetallic;
    // RGB times Ke (MTL map_Ke, glTF emissiveTexture).
    std::shared_ptr<const Texture> emission;
    // Coverage: a hit where channel `coverageChannel` is below `alphaCutoff` is no hit at all
    // (MTL map_d, glTF alphaMode MASK); the ray goes on through it (scene.h).
    std::shared_ptr<const Texture> coverage;
    int coverageChannel = 0;
    float alphaCutoff = 0.5f;
    // A tangent-space normal map, RGB = (x, y, z) * 0.5 + 0.5, x along increasing u, y along
    // increasing v; x and y are scaled by `normalScale` (glTF normalTexture.scale).
    std::shared_ptr<const Texture> normal;
    float normalScale = 1.0f;
};

struct Material {
    std::string name;
    glm::vec3 diffuse{0.0f};   // Kd: Lambertian albedo
    glm::vec3 emission{0.0f};  // Ke: radiance emitted on the counter-clockwise (front) side
    glm::vec3 specular{0.0f};  // Ks: Fresnel reflectance at normal incidence of the GGX layer
    float roughness = 1.0f;    // Pr (or converted from Ns): GGX alpha = Pr^2 (microfacet.h)
    // Set by glTF when a texture varies base colour or metallic: Kd and Ks are then mapped from
    // these at each hit, and `diffuse`/`specular` above are their untextured values.
    std::optional<MetallicRoughness> metallicRoughness{};
    MaterialTextures textures{};

    // Whether any texture changes the BSDF from hit to hit (colour or roughness/metallic).
    bool hasReflectanceTextures() const { return textures.colour || textures.roughnessMetallic; }
    // Whether the hit at `uv` is cut out (no surface there).
    bool cutOut(glm::vec2 uv) const {
        return textures.coverage && textures.coverage->lookup(uv)[textures.coverageChannel] < textures.alphaCutoff;
    }
    // Ke at `uv`: the emission texture times Ke, zero where the surface is cut out.
    glm::vec3 emissionAt(glm::vec2 uv) const;
    // The largest Ke component over the surface, and Ke's mean over the emission texture (for
    // the light's power, by which lights are chosen: positive wherever Ke can be).
    float maxEmission() const;
    glm::vec3 meanEmission() const;
};

}  // namespace strata
