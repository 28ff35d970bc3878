#include "materials/material_table.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>
#include <glm/exponential.hpp>

#include "materials/metallic_roughness.h"
#include "materials/microfacet.h"
#include "materials/specular_glossiness.h"
#include "util/components.h"

namespace strata {
namespace {

// A texel as a factor of reflectance: in [0, 1] (an EXR texture may hold more, which would
// create energy), NaN read as 0.
float unitClamped(float v) { return v >= 0.0f ? std::min(v, 1.0f) : 0.0f; }
glm::vec3 unitClamped(const glm::vec3& v) { return {unitClamped(v.x), unitClamped(v.y), unitClamped(v.z)}; }

// Beer-Lambert: a path that goes `distance` through the volume keeps `colour`.
glm::vec3 absorptionOf(const Material& m) {
    if (m.transmission <= 0.0f || m.thinWalled || !(m.attenuationDistance < std::numeric_limits<float>::infinity())) {
        return glm::vec3(0.0f);
    }
    const glm::vec3 colour = glm::clamp(m.attenuationColor, glm::vec3(1e-6f), glm::vec3(1.0f));
    return -glm::log(colour) / std::max(m.attenuationDistance, 1e-30f);
}

// The layered model's two layers from a material's colour constants (MTL's Kd and Ks directly,
// glTF's through its metallic-roughness or specular-glossiness mapping), the textures' colour,
// metallic and specular colour at the hit applied.
LayeredReflectance reflectanceOf(const Material& m, const glm::vec3& colour, float metallicFactor,
                                 const glm::vec3& specularColour, float specularFactor) {
    if (m.specularGlossiness) {
        const SpecularGlossiness& sg = *m.specularGlossiness;
        return fromSpecularGlossiness(sg.diffuse * colour, sg.specular * specularColour);
    }
    if (!m.metallicRoughness) return {m.diffuse * colour, m.specular};
    const MetallicRoughness& mr = *m.metallicRoughness;
    return fromMetallicRoughness(mr.baseColor * colour, mr.metallic * metallicFactor,
                                 mr.dielectricF0(specularColour, specularFactor));
}

// The lobe (GGX or sheen) of `alpha` among `lobes`, built the first time a material asks for it.
template <class Lobe>
const Lobe* sharedLobe(std::vector<std::unique_ptr<Lobe>>& lobes, float alpha) {
    for (const auto& existing : lobes) {
        if (existing->alpha() == alpha) return existing.get();
    }
    return lobes.emplace_back(std::make_unique<Lobe>(alpha)).get();
}

// A texture-modulated roughness's quantisation level (material_table.h), and a level's roughness.
size_t roughnessLevel(float roughness) {
    return static_cast<size_t>(std::lround(unitClamped(roughness) * (MaterialTable::kRoughnessLevels - 1)));
}
float levelRoughness(size_t level) {
    return static_cast<float>(level) / (MaterialTable::kRoughnessLevels - 1);
}
}  // namespace

const SpecularLobe* MaterialTable::lobeFor(float roughness) {
    return sharedLobe(lobes_, ggxAlphaFromRoughness(roughness));
}

const SheenLobe* MaterialTable::sheenLobeFor(float roughness) {
    return sharedLobe(sheenLobes_, sheenAlphaFromRoughness(roughness));
}

const SpecularLobe* MaterialTable::quantisedLobe(float roughness, bool smoothIsNull) const {
    const size_t level = roughnessLevel(roughness);
    return level == 0 && smoothIsNull ? nullptr : quantisedLobes_[level];
}

MaterialTable::MaterialTable(const std::vector<Material>& materials) {
    entries_.reserve(materials.size());
    for (const Material& m : materials) {
        const bool black = m.unlit || (isZero(m.diffuse) && isZero(m.specular) && m.transmission <= 0.0f &&
                                       m.clearcoat <= 0.0f && isZero(m.sheenColour));
        const bool specularLayer = !isZero(m.specular) || m.metallicRoughness || m.transmission > 0.0f;
        const SurfacePoint constants{m.diffuse,
                                     m.specular,
                                     m.roughness,
                                     specularLayer ? lobeFor(m.roughness) : nullptr,
                                     m.transmission,
                                     m.ior,
                                     m.transmissionFilter,
                                     m.thinWalled,
                                     m.clearcoat,
                                     m.clearcoat > 0.0f && m.clearcoatRoughness > 0.0f ? lobeFor(m.clearcoatRoughness)
                                                                                       : nullptr,
                                     m.sheenColour,
                                     isZero(m.sheenColour) ? nullptr : sheenLobeFor(m.sheenRoughness)};
        const bool textured = m.hasReflectanceTextures() && !black;
        materials_.push_back(m);
        if (textured) {
            const bool variesRoughness =
                m.textures.roughness || m.textures.clearcoatRoughness || m.textures.specularGlossiness;
            if (variesRoughness && !quantisedLobes_[0]) {
                for (size_t level = 0; level < kRoughnessLevels; ++level) {
                    quantisedLobes_[level] = lobeFor(levelRoughness(level));
                }
            }
            if (m.textures.sheenRoughness && !isZero(m.sheenColour) && !quantisedSheenLobes_[0]) {
                for (size_t level = 0; level < kRoughnessLevels; ++level) {
                    quantisedSheenLobes_[level] = sheenLobeFor(levelRoughness(level));
                }
            }
        }
        const Bsdf front = build(constants, true);
        const Bsdf back = build(constants, false);
        // A texture can give a diffuse base where the constants have none (a metallic texture
        // under a metallic factor of 1), so a textured material is taken to read them.
        const bool readsDiffuseNumbers = textured || front.readsDiffuseNumbers() || back.readsDiffuseNumbers();
        // Only the opaque models take the coat (build).
        const bool coatHasOwnNormal = m.clearcoat > 0.0f && m.transmission <= 0.0f &&
                                      (m.textures.normal || m.textures.clearcoatNormal);
        entries_.push_back(
            {front, back, constants, absorptionOf(m), black, readsDiffuseNumbers, textured, coatHasOwnNormal});
    }
}

glm::vec3 MaterialTable::unlitColour(uint32_t material, glm::vec2 uv, const glm::vec3& colour) const {
    const Material& m = materials_[material];
    const glm::vec3 texel = m.textures.colour ? glm::vec3(m.textures.colour->lookup(uv)) : glm::vec3(1.0f);
    return m.diffuse * unitClamped(texel) * unitClamped(colour);
}

Bsdf MaterialTable::build(const SurfacePoint& p, bool front) {
    const LayeredBsdf layered(p.diffuse, p.specular, p.lobe);
    if (p.transmission > 0.0f) {
        const glm::vec3& filter = p.transmissionFilter;
        const float eta = front ? p.ior : 1.0f / p.ior;
        const auto blended = [&](const auto& dielectric) -> Bsdf {
            if (p.transmission >= 1.0f) return dielectric;
            return TransmissionBlend(layered, dielectric, p.transmission);
        };
        if (p.thinWalled) return blended(ThinDielectric(p.ior, filter));
        if (p.roughness == 0.0f) return blended(SmoothDielectric(eta, filter));
        return blended(RoughDielectric(eta, ggxAlphaFromRoughness(p.roughness), filter));
    }
    const bool smoothSpecular = p.roughness == 0.0f && !isZero(p.specular);
    const CoatLayer coat{p.clearcoat, glm::vec3(0.04f), p.coatLobe};
    if (smoothSpecular && isZero(p.diffuse)) {
        const SmoothConductor mirror(p.specular);
        if (p.clearcoat > 0.0f) return Coated(coat, mirror);
        return mirror;
    }
    if (smoothSpecular && p.clearcoat <= 0.0f) {
        return Coated(CoatLayer{1.0f, p.specular, nullptr}, LayeredBsdf(p.diffuse, glm::vec3(0.0f), nullptr));
    }
    // (A smooth specular layer under a clear coat keeps the GGX layer's sharpest lobe.)
    if (p.sheenLobe && !isZero(p.sheenColour)) {
        const Sheened sheened(SheenLayer{p.sheenColour, p.sheenLobe}, layered);
        if (p.clearcoat > 0.0f) return Coated(coat, sheened);
        return sheened;
    }
    if (p.clearcoat > 0.0f) return Coated(coat, layered);
    return layered;
}

Bsdf MaterialTable::variedBsdf(uint32_t material, glm::vec2 uv, bool front, const glm::vec3& vertexColour) const {
    const Entry& entry = entries_[material];
    const Material& m = materials_[material];
    const auto channel = [&](const std::shared_ptr<const Texture>& texture, int c) {
        return texture ? unitClamped(texture->lookup(uv)[c]) : 1.0f;
    };
    SurfacePoint p = entry.constants;
    glm::vec3 colour = unitClamped(vertexColour);
    if (m.textures.colour) colour *= unitClamped(glm::vec3(m.textures.colour->lookup(uv)));
    // glTF keeps roughness and metallic in one texture: one lookup for both.
    const auto& roughnessMap = m.textures.roughness;
    const auto& metallicMap = m.textures.metallic;
    const glm::vec4 roughnessTexel = roughnessMap ? roughnessMap->lookup(uv) : glm::vec4(1.0f);
    const glm::vec4 metallicTexel =
        metallicMap == roughnessMap ? roughnessTexel : metallicMap ? metallicMap->lookup(uv) : glm::vec4(1.0f);
    const float metallic = unitClamped(metallicTexel[m.textures.metallicChannel]);
    glm::vec3 specularColour(1.0f);
    std::optional<float> texturedRoughness;
    if (roughnessMap) texturedRoughness = m.roughness * unitClamped(roughnessTexel[m.textures.roughnessChannel]);
    if (m.textures.specularGlossiness) {
        const glm::vec4 texel = m.textures.specularGlossiness->lookup(uv);
        specularColour = unitClamped(glm::vec3(texel));
        texturedRoughness = 1.0f - (1.0f - m.roughness) * unitClamped(texel.a);
    }
    if (texturedRoughness) {
        p.lobe = quantisedLobe(*texturedRoughness, false);
        // The quantised roughness, so that its limit 0 is the smooth one.
        p.roughness = levelRoughness(roughnessLevel(*texturedRoughness));
    }
    // KHR_materials_specular's textures scale the dielectric's F0, as specularGlossiness's the F0.
    float specularFactor = 1.0f;
    if (m.textures.specular) specularFactor = unitClamped(m.textures.specular->lookup(uv).a);
    if (m.textures.specularColour) specularColour = unitClamped(glm::vec3(m.textures.specularColour->lookup(uv)));
    const LayeredReflectance r = reflectanceOf(m, colour, metallic, specularColour, specularFactor);
    p.diffuse = r.diffuse;
    p.specular = r.specular;
    if (m.metallicRoughness) {
        const MetallicRoughness& mr = *m.metallicRoughness;
        p.transmissionFilter = mr.baseColor * colour;
        p.transmission = mr.transmission * (1.0f - mr.metallic * metallic);
    }
    p.transmission *= channel(m.textures.transmission, 0);
    p.clearcoat *= channel(m.textures.clearcoat, 0);
    if (m.textures.clearcoatRoughness) {
        p.coatLobe = quantisedLobe(m.clearcoatRoughness * channel(m.textures.clearcoatRoughness, 1), true);
    }
    if (m.textures.sheenColour) p.sheenColour *= unitClamped(glm::vec3(m.textures.sheenColour->lookup(uv)));
    if (m.textures.sheenRoughness && p.sheenLobe) {
        p.sheenLobe = quantisedSheenLobes_[roughnessLevel(m.sheenRoughness * channel(m.textures.sheenRoughness, 3))];
    }
    return build(p, front);
}

}  // namespace strata
