#pragma once
// The scene's materials, ready to become a BSDF at any hit. Whatever a material needs beyond its
// own numbers is prepared here once, when the scene is built: the GGX albedo tables, one per
// distinct roughness (SpecularLobe), shared by every material of that roughness and kept for the
// scene's lifetime, so a new integrator on the same scene (the viewer restarts one on every camera
// move) rebuilds nothing.
//
// A material with a colour or roughness/metallic texture gets its BSDF built at each hit from the
// texel at the hit's UV. Its roughness then varies over the surface, but albedo tables cannot be
// built per hit: a roughness texture's values are quantised to kRoughnessLevels evenly spaced
// roughnesses 0, 1/16, ..., 1, whose lobes are built once. The roughness used is off by at most
// 1/32 (GGX alpha = Pr^2 by at most Pr/16 + 1/1024), which the texture's own 8-bit steps of 1/255
// bound from below; the BSDF at each quantised roughness is itself exact and energy-conserving.
#include <array>
#include <cstdint>
#include <memory>
#include <vector>
#include <glm/vec2.hpp>

#include "materials/bsdf.h"
#include "materials/layered_bsdf.h"
#include "materials/material.h"

namespace strata {

class MaterialTable {
public:
    static constexpr int kRoughnessLevels = 17;

    explicit MaterialTable(const std::vector<Material>& materials);

    // The BSDF of `material` at a hit with texture coordinates `uv`. A material whose
    // parameters are constant over its surface keeps its BSDF made once, and a hit takes a copy:
    // a few dozen bytes.
    Bsdf bsdf(uint32_t material, glm::vec2 uv = glm::vec2(0.0f)) const {
        const Entry& entry = entries_[material];
        return entry.textured < 0 ? entry.bsdf : texturedBsdf(entry, uv);
    }
    // Whether the material reflects nothing, so a path that reaches it ends there (textures
    // multiply the constants, so a black material stays black).
    bool isBlack(uint32_t material) const { return entries_[material].black; }
    size_t size() const { return entries_.size(); }
    // The distinct specular lobes built (one per roughness in use, the quantised ones included).
    size_t specularLobes() const { return lobes_.size(); }

private:
    struct Entry {
        Bsdf bsdf;  // at the constants
        const SpecularLobe* lobe;  // the specular layer's at the material's roughness, or null
        bool black;
        int32_t textured;  // index in textured_, -1 for a material without reflectance textures
    };
    const SpecularLobe* lobeFor(float roughness);
    Bsdf texturedBsdf(const Entry& entry, glm::vec2 uv) const;

    std::vector<Entry> entries_;
    std::vector<Material> textured_;
    std::vector<std::unique_ptr<SpecularLobe>> lobes_;
    std::array<const SpecularLobe*, kRoughnessLevels> quantisedLobes_{};
};

}  // namespace strata
