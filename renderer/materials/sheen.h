#pragma once
// A sheen over the layered model (glTF KHR_materials_sheen; velvet, cloth, dust): the back-scatter
// of fibres standing out of a surface, strongest at grazing angles, above everything the layered
// model reflects (a clear coat, if any, lies above the sheen: clear_coat.h).
//
// The lobe is Estevez & Kulla's "Charlie" microfibre distribution (2017, "Production Friendly
// Microfacet Sheen BRDF"), as KHR_materials_sheen specifies it, at alpha = sheenRoughness^2:
//   D(h) = (2 + 1/alpha) sin(theta_h)^(1/alpha) / (2 pi),
// with their fitted Smith Lambda (the same paper, section 3, with its terminator softening:
// mirrored about cos theta = 1/2), G2 = 1 / (1 + Lambda(mu_o) + Lambda(mu_i)), and
//   f_sheen = sheenColour D G2 / (4 mu_o mu_i).
// The layers are combined as the clear coat's are, symmetrically so that f stays reciprocal:
//   f = f_sheen + (1 - s E(mu_o)) (1 - s E(mu_i)) f_base,   s = max component of sheenColour,
// E being the lobe's directional albedo (tabulated once per roughness); glTF's albedo scaling
// takes the smaller of the two factors instead of their product. Either way the total albedo,
// at most s E + (1 - s E) A_base, stays at or under 1 wherever the base's A_base does.
//
// Sampling takes the sheen with probability by its albedo at wo against the base's, with
// numbers.lobeChoice (rescaled for the base's own choice), and its direction uniformly over the
// hemisphere from numbers.lobePoint: the lobe is broad, and its peak lies toward the horizon,
// where a cosine density would draw least.
#include <array>
#include <optional>
#include <glm/vec3.hpp>

#include "materials/bsdf_sample.h"
#include "materials/layered_bsdf.h"

namespace strata {

// The smallest sheen alpha used: a sheen roughness of 0 (glTF's default) becomes a lobe of
// fibres lying flat, finite, whose light reaches only the horizon.
inline constexpr float kMinSheenAlpha = 1e-4f;

// alpha = roughness^2, clamped to [kMinSheenAlpha, 1].
float sheenAlphaFromRoughness(float roughness);

// The Charlie lobe of one alpha (sheenAlphaFromRoughness) and its directional albedo table.
class SheenLobe {
public:
    explicit SheenLobe(float alpha);

    float alpha() const { return alpha_; }
    // D(h), normalised so that the integral of D(h) h.z over the hemisphere is 1.
    float density(const glm::vec3& h) const;
    // The fitted Smith Lambda at mu = cos(theta) in (0, 1].
    float lambda(float mu) const;
    // D G2 / (4 mu_o mu_i) (white sheen); 0 unless both directions are above the surface.
    float reflectance(const glm::vec3& wo, const glm::vec3& wi) const;
    // E(mu) = integral of reflectance(wo, wi) wi.z over wi, mu = wo.z in [0, 1], from the table.
    float albedo(float mu) const;

private:
    static constexpr int kEntries = 32;  // at mu = i / (kEntries - 1)
    float alpha_;
    std::array<float, 5> lambdaFit_{};  // the fit's a, b, c, d, e at this alpha
    std::array<float, kEntries> table_{};
};

struct SheenLayer {
    glm::vec3 colour{0.0f};
    const SheenLobe* lobe = nullptr;

    // colour E(mu): the light the sheen itself reflects, per channel.
    glm::vec3 albedo(float mu) const;
    // 1 - s E(mu): the share that passes the sheen, to the base and back out.
    float passing(float mu) const;
};

class Sheened {
public:
    Sheened(const SheenLayer& sheen, const LayeredBsdf& base) : sheen_(sheen), base_(base) {}

    bool isBlack() const { return false; }
    BsdfFlags flags() const { return static_cast<BsdfFlags>(base_.flags() | kReflection | kGlossy); }
    glm::vec3 evaluate(const glm::vec3& wo, const glm::vec3& wi, TransportMode mode = TransportMode::Radiance) const;
    std::optional<BsdfSample> sample(const glm::vec3& wo, const BsdfNumbers& numbers,
                                     TransportMode mode = TransportMode::Radiance) const;
    float pdf(const glm::vec3& wo, const glm::vec3& wi, DiffuseWarp warp) const;
    // colour E(mu_o) + (1 - s E(mu_o)) A_base(wo): at least the true albedo (the way back through
    // the sheen left out), as the clear coat's; it only weighs the lobe choice.
    glm::vec3 albedo(const glm::vec3& wo) const;

    const LayeredBsdf& base() const { return base_; }

private:
    // The probability of sampling the sheen at wo.
    float sheenProbability(const glm::vec3& wo) const;

    SheenLayer sheen_;
    LayeredBsdf base_;
};

}  // namespace strata
