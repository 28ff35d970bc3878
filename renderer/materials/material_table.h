#pragma once
// The scene's materials, ready to become a BSDF at any hit. Whatever a material needs beyond its
// own numbers is prepared here once, when the scene is built: the GGX albedo tables, one per
// distinct roughness (SpecularLobe), shared by every material of that roughness and kept for the
// scene's lifetime, so a new integrator on the same scene (the viewer restarts one on every camera
// move) rebuilds nothing.
#include <cstdint>
#include <memory>
#include <vector>

#include "materials/layered_bsdf.h"
#include "materials/material.h"

namespace strata {

class MaterialTable {
public:
    explicit MaterialTable(const std::vector<Material>& materials);

    // The BSDF of `material` at a hit. A material whose parameters are constant over its
    // surface keeps its BSDF made once, and a hit takes a copy: a few dozen bytes.
    LayeredBsdf bsdf(uint32_t material) const { return entries_[material].bsdf; }
    // Whether the material reflects nothing, so a path that reaches it ends there.
    bool isBlack(uint32_t material) const { return entries_[material].black; }
    size_t size() const { return entries_.size(); }
    // The distinct specular lobes built (one per roughness in use).
    size_t specularLobes() const { return lobes_.size(); }

private:
    struct Entry {
        LayeredBsdf bsdf;
        bool black;
    };
    std::vector<Entry> entries_;
    std::vector<std::unique_ptr<SpecularLobe>> lobes_;
};

}  // namespace strata
