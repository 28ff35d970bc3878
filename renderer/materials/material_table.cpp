#include "materials/material_table.h"

#include "materials/microfacet.h"

namespace strata {
namespace {
bool isZero(const glm::vec3& v) { return v.x == 0.0f && v.y == 0.0f && v.z == 0.0f; }
}  // namespace

MaterialTable::MaterialTable(const std::vector<Material>& materials) {
    entries_.reserve(materials.size());
    for (const Material& m : materials) {
        const SpecularLobe* lobe = nullptr;
        if (!isZero(m.specular)) {
            const float alpha = ggxAlphaFromRoughness(m.roughness);
            for (const auto& existing : lobes_) {
                if (existing->distribution.alpha() == alpha) lobe = existing.get();
            }
            if (!lobe) lobe = lobes_.emplace_back(std::make_unique<SpecularLobe>(alpha)).get();
        }
        entries_.push_back({LayeredBsdf(m.diffuse, m.specular, lobe), isZero(m.diffuse) && isZero(m.specular)});
    }
}

}  // namespace strata
