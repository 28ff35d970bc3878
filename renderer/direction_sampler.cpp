#include "direction_sampler.h"

#include "hemisphere.h"
#include "name_table.h"
#include "strata24.h"

namespace strata {
namespace {
constexpr NameTable<SamplerKind, 2> kSamplers{{{{"uniform", SamplerKind::Uniform},
                                                {"strata24", SamplerKind::Strata24}}}};
}  // namespace

std::optional<SamplerKind> parseSamplerKind(std::string_view name) { return kSamplers.parse(name); }
std::string_view samplerName(SamplerKind kind) { return kSamplers.name(kind); }
std::string samplerNames() { return kSamplers.joined(); }

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
