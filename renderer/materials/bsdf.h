#pragma once
// The scattering model at a surface point: one closed type over the concrete models, each a file
// of this folder, so the path tracer and the tests speak to every model through one interface
// (evaluate, sample, pdf over the whole sphere of directions, and the lobes' flags:
// bsdf_sample.h), while the models stay plain values the integrator builds at each hit with no
// allocation and no virtual call. A new model is one file here and one entry in Model.
//
// Every model has evaluate(wo, wi, mode), sample(wo, numbers, mode), pdf(wo, wi, warp), flags()
// and isBlack(). Reflection-only models are written for the side above the normal; Bsdf makes
// them two-sided by mirroring both directions through the surface when wo is below it. Models
// that transmit handle both sides themselves (their two sides differ: inside and outside).
#include <optional>
#include <type_traits>
#include <utility>
#include <variant>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "materials/bsdf_sample.h"
#include "materials/clear_coat.h"
#include "materials/layered_bsdf.h"
#include "materials/rough_dielectric.h"
#include "materials/sheen.h"
#include "materials/smooth_conductor.h"
#include "materials/smooth_dielectric.h"
#include "materials/thin_dielectric.h"
#include "materials/transmission_blend.h"

namespace strata {

class Bsdf {
public:
    using Model = std::variant<LayeredBsdf, SmoothConductor, SmoothDielectric, RoughDielectric, ThinDielectric,
                               Sheened, Coated<LayeredBsdf>, Coated<SmoothConductor>, Coated<Sheened>,
                               TransmissionBlend<SmoothDielectric>, TransmissionBlend<RoughDielectric>,
                               TransmissionBlend<ThinDielectric>>;

private:
    Model model_;
    BsdfFlags flags_;  // the model's, worked out once: every bounce asks for them
    template <class F>
    decltype(auto) visit(F&& f) const {
        // The layered model is nearly every hit's: called directly rather than through the table
        // std::visit dispatches by.
        if (const auto* layered = std::get_if<LayeredBsdf>(&model_)) return f(*layered);
        return visitOthers(std::forward<F>(f));
    }
    // Out of line: inlined into the path tracer's bounce loop (which is flattened), the other
    // models' code cost every bounce of a Lambertian scene registers, 1.8% more instructions on
    // the Cornell box.
    template <class F>
    [[gnu::noinline]] decltype(auto) visitOthers(F&& f) const {
        return std::visit(std::forward<F>(f), model_);
    }

public:
    template <class M>
        requires std::is_constructible_v<Model, M>
    Bsdf(M model)  // NOLINT(google-explicit-constructor): a model is a BSDF
        : model_(model), flags_(model.isBlack() ? BsdfFlags{0} : model.flags()) {}

    // f(wo, wi), every lobe but the specular (delta) ones.
    glm::vec3 evaluate(const glm::vec3& wo, const glm::vec3& wi,
                       TransportMode mode = TransportMode::Radiance) const {
        return visit([&](const auto& m) -> glm::vec3 {
            if (mirrored(wo)) return m.evaluate(flipped(wo), flipped(wi), mode);
            return m.evaluate(wo, wi, mode);
        });
    }
    // A direction by the model's own importance sampling, its diffuse lobe by the warp in
    // `numbers`; empty when the sample is lost (it still counts, with weight 0).
    std::optional<BsdfSample> sample(const glm::vec3& wo, const BsdfNumbers& numbers,
                                     TransportMode mode = TransportMode::Radiance) const {
        return visit([&](const auto& m) -> std::optional<BsdfSample> {
            if (mirrored(wo)) {
                auto s = m.sample(flipped(wo), numbers, mode);
                if (s) s->wi = flipped(s->wi);
                return s;
            }
            return m.sample(wo, numbers, mode);
        });
    }
    // The same with independent numbers, the diffuse lobe by cosine.
    std::optional<BsdfSample> sample(const glm::vec3& wo, glm::vec2 u, float lobeChoice,
                                     TransportMode mode = TransportMode::Radiance) const {
        return sample(wo, BsdfNumbers::independent(u, lobeChoice), mode);
    }
    // The density with which sample() gives wi (its diffuse lobe sampled by `warp`), over the
    // lobes that are not specular; 0 where only a specular lobe could have given it.
    float pdf(const glm::vec3& wo, const glm::vec3& wi, DiffuseWarp warp = DiffuseWarp::Cosine) const {
        return visit([&](const auto& m) -> float {
            if (mirrored(wo)) return m.pdf(flipped(wo), flipped(wi), warp);
            return m.pdf(wo, wi, warp);
        });
    }

    // The union of the lobes' flags; 0 for a model that scatters nothing.
    BsdfFlags flags() const { return flags_; }
    bool isBlack() const { return flags() == 0; }
    // Whether some lobe is not a delta, so that a light sample can find light it reflects.
    bool hasNonSpecularLobe() const { return (flags() & (kDiffuse | kGlossy)) != 0; }
    // Whether sample() reads more than numbers.diffuse (a lobe point or a lobe choice).
    bool readsLobeNumbers() const { return flags() != (kReflection | kDiffuse); }
    // Whether sample() reads numbers.diffuse's stratum and point: only a diffuse lobe does (its
    // warp, which a mixture's density names, is the sampler's whatever the point).
    bool readsDiffuseNumbers() const { return (flags() & kDiffuse) != 0; }

    template <class M>
    const M* as() const { return std::get_if<M>(&model_); }

    // Turns a clear coat's normal to `axis` (clear_coat.h); a model without a coat stays as it is.
    void tiltCoat(const glm::vec3& axis) {
        std::visit(
            [&](auto& m) {
                if constexpr (requires { m.tilt(axis); }) m.tilt(axis);
            },
            model_);
    }

private:
    bool mirrored(const glm::vec3& wo) const { return !isTransmission(flags_) && wo.z < 0.0f; }
    static glm::vec3 flipped(const glm::vec3& w) { return {w.x, w.y, -w.z}; }
};

}  // namespace strata
