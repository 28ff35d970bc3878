#include "materials/material_table.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>

#include "materials/metallic_roughness.h"
#include "materials/microfacet.h"

namespace strata {
namespace {
bool isZero(const glm::vec3& v) { return v.x == 0.0f && v.y == 0.0f && v.z == 0.0f; }

// A texel as a factor of reflectance: in [0, 1] (an EXR texture may hold more, which would
// create energy), NaN read as 0.
float unitClamped(float v) { return v >= 0.0f ? std::min(v, 1.0f) : 0.0f; }
glm::vec3 unitClamped(const glm::vec3& v) { return {unitClamped(v.x), unitClamped(v.y), unitClamped(v.z)}; }
}  // namespace

const SpecularLobe* MaterialTable::lobeFor(float roughness) {
    const float alpha = ggxAlphaFromRoughness(roughness);
    for (const auto& existing : lobes_) {
        if (existing->distribution.alpha() == alpha) return existing.get();
    }
    return lobes_.emplace_back(std::make_unique<SpecularLobe>(alpha)).get();
}

MaterialTable::MaterialTable(const std::vector<Material>& materials) {
    entries_.reserve(materials.size());
    for (const Material& m : materials) {
        const bool black = isZero(m.diffuse) && isZero(m.specular);
        const SpecularLobe* lobe = isZero(m.specular) && !m.metallicRoughness ? nullptr : lobeFor(m.roughness);
        int32_t textured = -1;
        if (m.hasReflectanceTextures() && !black) {
            textured = static_cast<int32_t>(textured_.size());
            textured_.push_back(m);
            if (m.textures.roughnessMetallic && !quantisedLobes_[0]) {
                for (int level = 0; level < kRoughnessLevels; ++level) {
                    quantisedLobes_[static_cast<size_t>(level)] =
                        lobeFor(static_cast<float>(level) / (kRoughnessLevels - 1));
                }
            }
        }
        entries_.push_back({LayeredBsdf(m.diffuse, m.specular, lobe), lobe, black, textured});
    }
}

Bsdf MaterialTable::texturedBsdf(const Entry& entry, glm::vec2 uv) const {
    const Material& m = textured_[static_cast<size_t>(entry.textured)];
    const glm::vec3 colour =
        m.textures.colour ? unitClamped(glm::vec3(m.textures.colour->lookup(uv))) : glm::vec3(1.0f);
    if (!m.metallicRoughness) {
        // MTL: map_Kd times Kd; Ks and the roughness stay constant.
        return LayeredBsdf(m.diffuse * colour, m.specular, entry.lobe);
    }
    float metallic = m.metallicRoughness->metallic;
    const SpecularLobe* lobe = entry.lobe;
    if (m.textures.roughnessMetallic) {
        const glm::vec4 texel = m.textures.roughnessMetallic->lookup(uv);
        metallic *= unitClamped(texel.b);
        const float roughness = m.roughness * unitClamped(texel.g);
        const auto level = static_cast<size_t>(std::lround(roughness * (kRoughnessLevels - 1)));
        lobe = quantisedLobes_[level];
    }
    const LayeredReflectance r = fromMetallicRoughness(m.metallicRoughness->baseColor * colour, metallic);
    return LayeredBsdf(r.diffuse, r.specular, lobe);
}

}  // namespace strata
