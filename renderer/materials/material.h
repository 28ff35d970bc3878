#pragma once
// A surface's material as scene files give it (MTL, glTF): plain data, turned into a BSDF at each
// hit by MaterialTable (material_table.h). The numbers are the material's constants; each texture,
// where there is one, multiplies its constant at the hit's UV (textures/texture.h's convention).
#include <limits>
#include <memory>
#include <optional>
#include <glm/common.hpp>
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
    // A dielectric's reflectance at normal incidence (KHR_materials_specular, "Implementation"):
    // min(specularColour x the colour texel, 1) x specularFactor x the factor texel, where
    // specularColour is ((ior - 1) / (ior + 1))^2 times specularColorFactor.
    glm::vec3 specularColour{0.04f};
    float specularFactor = 1.0f;
    glm::vec3 dielectricF0(const glm::vec3& colourTexel = glm::vec3(1.0f), float factorTexel = 1.0f) const {
        return glm::min(specularColour * colourTexel, glm::vec3(1.0f)) * (specularFactor * factorTexel);
    }
    // KHR_materials_transmission's factor: the share of the dielectric part (1 - metallic) that
    // transmits.
    float transmission = 0.0f;
};

// glTF's specular-glossiness parameters (KHR_materials_pbrSpecularGlossiness), kept when a texture
// varies them, so that each hit maps its own colours onto Kd and Ks (specular_glossiness.h).
struct SpecularGlossiness {
    glm::vec3 diffuse{1.0f};
    glm::vec3 specular{1.0f};
    float glossiness = 1.0f;
};

struct MaterialTextures {
    // RGB times Kd (MTL map_Kd), or times the base colour (glTF baseColorTexture).
    std::shared_ptr<const Texture> colour;
    // Channel `roughnessChannel` of `roughness` times the roughness, channel `metallicChannel` of
    // `metallic` times metallic: glTF's metallicRoughnessTexture, one texture for both (G and
    // B), or MTL's map_Pr and map_Pm.
    std::shared_ptr<const Texture> roughness;
    int roughnessChannel = 1;
    std::shared_ptr<const Texture> metallic;
    int metallicChannel = 2;
    // RGB times Ke (MTL map_Ke, glTF emissiveTexture).
    std::shared_ptr<const Texture> emission;
    // Coverage: a hit where channel `coverageChannel` is below `alphaCutoff` is no hit at all
    // (glTF alphaMode MASK); the ray goes on through it (scene.h). A blended coverage (glTF
    // alphaMode BLEND, MTL map_d and d) is an opacity instead, times `opacity`: a ray goes on
    // through with probability 1 - opacity (scene/cutout_filter.h), which renders, in
    // expectation, the surface blended over what lies behind it, as Cycles renders a Principled
    // BSDF's alpha.
    std::shared_ptr<const Texture> coverage;
    int coverageChannel = 0;
    float alphaCutoff = 0.5f;
    bool blended = false;
    float opacity = 1.0f;
    // Makes the coverage an opacity: `opacity` times channel `channel` of `texture`, or `opacity`
    // alone where `texture` is null (glTF's BLEND, MTL's map_d and d).
    void blendBy(float opacity, std::shared_ptr<const Texture> texture = nullptr, int channel = 0);
    // A tangent-space normal map, RGB = (x, y, z) * 0.5 + 0.5, x along increasing u, y along
    // increasing v; x and y are scaled by `normalScale` (glTF normalTexture.scale).
    std::shared_ptr<const Texture> normal;
    float normalScale = 1.0f;
    // R times `transmission` (glTF transmissionTexture).
    std::shared_ptr<const Texture> transmission;
    // R times `clearcoat`, G times `clearcoatRoughness` (glTF clearcoatTexture and
    // clearcoatRoughnessTexture).
    std::shared_ptr<const Texture> clearcoat;
    std::shared_ptr<const Texture> clearcoatRoughness;
    // The coat's own tangent-space normal map, as `normal` (glTF clearcoatNormalTexture); without
    // it the coat takes the vertex normals, whatever `normal` does to the base.
    std::shared_ptr<const Texture> clearcoatNormal;
    float clearcoatNormalScale = 1.0f;
    // RGB times the specular colour, A times the glossiness (glTF specularGlossinessTexture).
    std::shared_ptr<const Texture> specularGlossiness;
    // KHR_materials_specular: A times specularFactor (specularTexture), RGB times
    // specularColorFactor (specularColorTexture, sRGB).
    std::shared_ptr<const Texture> specular;
    std::shared_ptr<const Texture> specularColour;
    // KHR_materials_sheen: RGB times `sheenColour` (sheenColorTexture, sRGB), A times
    // `sheenRoughness` (sheenRoughnessTexture).
    std::shared_ptr<const Texture> sheenColour;
    std::shared_ptr<const Texture> sheenRoughness;
};

struct Material {
    std::string name;
    glm::vec3 diffuse{0.0f};   // Kd: Lambertian albedo
    glm::vec3 emission{0.0f};  // Ke: radiance emitted on the counter-clockwise (front) side
    glm::vec3 specular{0.0f};  // Ks: Fresnel reflectance at normal incidence of the GGX layer
    float roughness = 1.0f;    // Pr (or converted from Ns): GGX alpha = Pr^2 (microfacet.h); 0 is
                               // smooth: a mirror, or a smooth dielectric
    // A dielectric (glass, water): the share of the surface that transmits, 0 (opaque: Kd and Ks
    // above) to 1 (MTL illum 4, 6, 7; glTF KHR_materials_transmission), its index of refraction
    // (Ni, KHR_materials_ior) and transmission filter (Tf; glTF: the base colour).
    float transmission = 0.0f;
    float ior = 1.5f;
    glm::vec3 transmissionFilter{1.0f};
    // A sheet with no inside (a window pane; glTF without KHR_materials_volume or with thickness
    // 0): reflection and straight transmission through both of its faces. Otherwise the surface
    // bounds a volume, which absorbs by Beer-Lambert's law: a path through it keeps
    // attenuationColor after attenuationDistance (KHR_materials_volume; infinity: no absorption).
    bool thinWalled = false;
    glm::vec3 attenuationColor{1.0f};
    float attenuationDistance = std::numeric_limits<float>::infinity();
    // A clear coat over the material (KHR_materials_clearcoat): its weight and roughness.
    float clearcoat = 0.0f;
    float clearcoatRoughness = 0.0f;
    // A surface that shows its colour, Kd times the colour texture and the vertex colour, to every
    // ray that finds it, and reflects nothing (glTF KHR_materials_unlit: scans and art with their
    // lighting baked in). It is no light: next-event estimation does not sample it, and what a
    // path finds there counts at full weight.
    bool unlit = false;
    // A sheen over the material, under its coat (KHR_materials_sheen; sheen.h): its colour (0:
    // none) and roughness.
    glm::vec3 sheenColour{0.0f};
    float sheenRoughness = 0.0f;
    // Set by glTF (and MTL with Pm) when a texture varies base colour or metallic: Kd and Ks are
    // then mapped from these at each hit, and `diffuse`/`specular` above are their untextured
    // values.
    std::optional<MetallicRoughness> metallicRoughness{};
    // Likewise for glTF's specular-glossiness model, when a texture varies it.
    std::optional<SpecularGlossiness> specularGlossiness{};
    MaterialTextures textures{};

    // Whether any texture changes the BSDF from hit to hit.
    bool hasReflectanceTextures() const {
        return textures.colour || textures.roughness || textures.metallic || textures.transmission || textures.clearcoat ||
               textures.clearcoatRoughness || textures.specularGlossiness || textures.specular ||
               textures.specularColour || textures.sheenColour || textures.sheenRoughness;
    }
    // Whether the hit at `uv` is cut out (no surface there): below the cutoff, or, blended, at an
    // opacity no greater than `u`, a number in [0, 1) that the ray and the triangle give (0:
    // where the surface is wholly transparent).
    bool cutOut(glm::vec2 uv, float u = 0.0f) const {
        if (!textures.coverage) return false;
        if (textures.blended) return opacityAt(uv) <= u;
        return textures.coverage->lookup(uv)[textures.coverageChannel] < textures.alphaCutoff;
    }
    // The share of the rays meeting the surface at `uv` that stop there: a blended coverage's
    // opacity, else 1 (a cut-out's hits are all or nothing).
    float opacityAt(glm::vec2 uv) const {
        if (!textures.blended) return 1.0f;
        return textures.coverage->lookup(uv)[textures.coverageChannel] * textures.opacity;
    }
    // Ke at `uv`: the emission texture times Ke, zero where the surface is cut out.
    glm::vec3 emissionAt(glm::vec2 uv) const;
    // The largest Ke component over the surface, and Ke's mean over the emission texture times
    // a blended coverage's mean opacity (for the light's power, by which lights are chosen:
    // positive wherever Ke can be).
    float maxEmission() const;
    glm::vec3 meanEmission() const;
};

}  // namespace strata
