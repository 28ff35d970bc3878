#include "direction_sampler.h"

#include <array>

#include "hemisphere.h"
#include "strata24.h"

namespace strata {
namespace {
struct NamedSampler {
    std::string_view name;
    SamplerKind kind;
};
constexpr std::array kSamplers{NamedSampler{"uniform", SamplerKind::Uniform},
                               NamedSampler{"strata24", SamplerKind::Strata24}};
}  // namespace

std::optional<SamplerKind> parseSamplerKind(std::string_view name) {
    for (const auto& s : kSamplers) {
        if (s.name == name) return s.kind;
    }
    return std::nullopt;
}

std::string_view samplerName(SamplerKind kind) {
    for (const auto& s : kSamplers) {
        if (s.kind == kind) return s.name;
    }
    return "unknown";
}

std::string samplerNames() {
    std::string names;
    for (const auto& s : kSamplers) {
        if (!names.empty()) names += '|';
        names += s.name;
    }
    return names;
}

SampledDirection sampleDirection(SamplerKind kind, const PathSamples& samples, int bounce) {
    const glm::vec2 u = samples.bouncePoint(bounce);
    if (kind == SamplerKind::Strata24) {
        const int id = samples.stratum(bounce);
        const glm::vec3 d = sampleStratum(id, u);
        return {d, d.z * kHemisphereSolidAngle, id};
    }
    const glm::vec3 d = sampleUniformHemisphere(u);
    return {d, d.z * kHemisphereSolidAngle, -1};
}

}  // namespace strata
