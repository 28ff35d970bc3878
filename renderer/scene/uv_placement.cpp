#include "scene/uv_placement.h"

#include <algorithm>
#include <cstdint>
#include <unordered_map>

namespace strata {

void placeUvs(MeshData& mesh, const std::vector<UvPlacement>& placements) {
    if (std::all_of(placements.begin(), placements.end(), [](const UvPlacement& p) { return p.isIdentity(); })) return;
    // The index of each placed copy, by (material, shared vt): as many entries as copies made.
    std::unordered_map<uint64_t, uint32_t> copies;
    for (size_t t = 0; t < mesh.triangleUvs.size(); ++t) {
        const uint32_t material = mesh.triangleMaterials[t];
        if (material >= placements.size() || placements[material].isIdentity() || mesh.triangleUvs[t] == kNoUvs) {
            continue;
        }
        for (uint32_t& uv : mesh.triangleUvs[t]) {
            const auto [copy, isNew] =
                copies.try_emplace(uint64_t{material} << 32 | uv, static_cast<uint32_t>(mesh.uvs.size()));
            if (isNew) mesh.uvs.push_back(placements[material].apply(mesh.uvs[uv]));
            uv = copy->second;
        }
    }
}

}  // namespace strata
