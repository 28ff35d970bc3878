#pragma once
// The scene's materials, ready to become a BSDF at any hit (bsdf.h). Which model a material is
// follows from its parameters (material.h), in one place (MaterialTable::build):
//   transmission > 0      a dielectric: thin-walled (thin_dielectric.h), else smooth at roughness
//                         0 (smooth_dielectric.h) or rough (rough_dielectric.h); blended with the
//                         opaque model below where transmission < 1 (transmission_blend.h);
//   roughness 0 with Ks   a mirror (smooth_conductor.h) where Kd is 0, else a smooth coat of
//                         F0 = Ks over the Lambertian Kd (clear_coat.h): the GGX layer's limit;
//   otherwise             the layered GGX-over-Lambertian model (layered_bsdf.h);
// then, over the layered model, a sheen where its colour is not black (sheen.h; not over the
// dielectrics' or the smooth limits' models), and where clearcoat > 0 a clear coat over it all
// (clear_coat.h).
//
// Whatever a material needs beyond its own numbers is prepared once, when the scene is built: the
// GGX and sheen albedo tables, one per distinct roughness (SpecularLobe, SheenLobe), shared by
// every material of that roughness and kept for the scene's lifetime, so a new integrator on the
// same scene (the viewer restarts one on every camera move) rebuilds nothing.
//
// A material with a texture that changes its BSDF, or a hit with a vertex colour, gets the BSDF
// built at each hit from the texels at the hit's UV and the colour. A textured roughness then
// varies over the surface, but albedo tables cannot be built per hit: a roughness texture's values
// are quantised to kRoughnessLevels evenly spaced roughnesses 0, 1/16, ..., 1, whose lobes are
// built once (a sheen roughness texture's likewise). The roughness used is off by at most 1/32
// (GGX alpha = Pr^2 by at most Pr/16 + 1/1024), which the texture's own 8-bit steps of 1/255 bound
// from below; the BSDF at each quantised roughness is itself exact and energy-conserving.
#include <array>
#include <cstdint>
#include <memory>
#include <vector>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "materials/bsdf.h"
#include "materials/layered_bsdf.h"
#include "materials/material.h"
#include "materials/sheen.h"

namespace strata {

class MaterialTable {
public:
    static constexpr size_t kRoughnessLevels = 17;

    explicit MaterialTable(const std::vector<Material>& materials);

    // The BSDF of `material` at a hit with texture coordinates `uv` and vertex colour `colour`
    // (which multiplies the diffuse or base colour, as a colour texture does), seen from the
    // surface's front (counter-clockwise) side or from behind it. A dielectric's front is its
    // outside: its index of refraction there is the inside's over the outside's, and from behind
    // its inverse. A material whose parameters are constant over its surface keeps its BSDFs made
    // once, and a hit without a vertex colour takes a copy: a few dozen bytes.
    Bsdf bsdf(uint32_t material, glm::vec2 uv = glm::vec2(0.0f), bool front = true,
              const glm::vec3& colour = glm::vec3(1.0f)) const {
        const Entry& entry = entries_[material];
        if (entry.textured || colour != glm::vec3(1.0f)) return variedBsdf(material, uv, front, colour);
        return front ? entry.front : entry.back;
    }
    // Whether the material scatters nothing, so a path that reaches it ends there (textures
    // multiply the constants, so a black material stays black). An unlit material is black.
    bool isBlack(uint32_t material) const { return entries_[material].black; }
    // Whether the material is unlit (material.h), and the colour it shows at a hit with texture
    // coordinates `uv` and vertex colour `colour`.
    bool isUnlit(uint32_t material) const { return materials_[material].unlit; }
    glm::vec3 unlitColour(uint32_t material, glm::vec2 uv, const glm::vec3& colour) const;
    // Whether the material's BSDF at some point of its surface reads the diffuse lobe's numbers
    // (Bsdf::readsDiffuseNumbers), known before a hit's BSDF is built: a path tracer then draws
    // them only for the materials that read them.
    bool readsDiffuseNumbers(uint32_t material) const { return entries_[material].readsDiffuseNumbers; }
    // Whether the material's clear coat has a normal of its own (Scene::coatNormal), which differs
    // from the shading normal: the coat's own normal map, or the base's that the coat does not take.
    bool coatHasOwnNormal(uint32_t material) const { return entries_[material].coatHasOwnNormal; }
    // The absorption coefficient (per unit length, per channel) inside the volume the material
    // bounds: 0 for all but a dielectric with KHR_materials_volume's attenuation.
    const glm::vec3& absorption(uint32_t material) const { return entries_[material].absorption; }
    size_t size() const { return entries_.size(); }
    // The distinct specular lobes built (one per roughness in use, the quantised ones included).
    size_t specularLobes() const { return lobes_.size(); }

private:
    // A material's parameters at one point of its surface: its constants times its textures.
    struct SurfacePoint {
        glm::vec3 diffuse;
        glm::vec3 specular;
        float roughness;
        const SpecularLobe* lobe;  // GGX at `roughness` (null without a specular layer)
        float transmission;
        float ior;
        glm::vec3 transmissionFilter;
        bool thinWalled;
        float clearcoat;
        const SpecularLobe* coatLobe;  // GGX at the coat's roughness; null for a smooth coat
        glm::vec3 sheenColour;
        const SheenLobe* sheenLobe;  // null without a sheen
    };
    struct Entry {
        Bsdf front, back;  // at the constants
        SurfacePoint constants;
        glm::vec3 absorption;
        bool black;
        bool readsDiffuseNumbers;
        bool textured;  // a texture changes the BSDF from hit to hit
        bool coatHasOwnNormal;
    };
    const SpecularLobe* lobeFor(float roughness);
    const SheenLobe* sheenLobeFor(float roughness);
    // The lobe of a texture-modulated roughness, quantised as above (null at roughness 0 when
    // `smoothIsNull`: the coat's smooth limit is a delta, with no lobe).
    const SpecularLobe* quantisedLobe(float roughness, bool smoothIsNull) const;
    static Bsdf build(const SurfacePoint& p, bool front);
    // The BSDF at a hit of a material that a texture or a vertex colour varies.
    Bsdf variedBsdf(uint32_t material, glm::vec2 uv, bool front, const glm::vec3& colour) const;

    std::vector<Entry> entries_;
    std::vector<Material> materials_;
    std::vector<std::unique_ptr<SpecularLobe>> lobes_;
    std::array<const SpecularLobe*, kRoughnessLevels> quantisedLobes_{};
    std::vector<std::unique_ptr<SheenLobe>> sheenLobes_;
    std::array<const SheenLobe*, kRoughnessLevels> quantisedSheenLobes_{};
};

}  // namespace strata
