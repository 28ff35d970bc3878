#include "sampling/direction_sampler.h"

#include <array>

#include "util/name_table.h"

namespace strata {
namespace {

struct SamplerEntry {
    SamplerKind kind;
    SamplerChoice choice;
};
constexpr std::array<SamplerEntry, kSamplerKinds.size()> kChoices{{
    {SamplerKind::Uniform, {PointSet::Independent, DiffuseWarp::Uniform}},
    {SamplerKind::Strata24, {PointSet::Independent, DiffuseWarp::Strata24}},
    {SamplerKind::Cosine, {PointSet::Independent, DiffuseWarp::Cosine}},
    {SamplerKind::Strata24Cosine, {PointSet::Independent, DiffuseWarp::Strata24Cosine}},
    {SamplerKind::Strata24Qmc, {PointSet::StratumSequence, DiffuseWarp::Strata24}},
    {SamplerKind::Strata24CosineQmc, {PointSet::StratumSequence, DiffuseWarp::Strata24Cosine}},
    {SamplerKind::Strata24Bsdf, {PointSet::StratumSequence, DiffuseWarp::WarpedStrata}},
    {SamplerKind::Bsdf, {PointSet::Independent, DiffuseWarp::Cosine}},
}};
// samplerChoice indexes the table by the kind, and kSamplerKinds lists the kinds in that order.
static_assert([] {
    for (size_t i = 0; i < kChoices.size(); ++i) {
        if (static_cast<size_t>(kChoices[i].kind) != i || kSamplerKinds[i] != kChoices[i].kind) return false;
    }
    return true;
}());

constexpr NameTable<SamplerKind, kSamplerKinds.size()> kSamplers{{{{"uniform", SamplerKind::Uniform},
                                                {"strata24", SamplerKind::Strata24},
                                                {"cosine", SamplerKind::Cosine},
                                                {"strata24-cosine", SamplerKind::Strata24Cosine},
                                                {"strata24-qmc", SamplerKind::Strata24Qmc},
                                                {"strata24-cosine-qmc", SamplerKind::Strata24CosineQmc},
                                                {"strata24-bsdf", SamplerKind::Strata24Bsdf},
                                                {"bsdf", SamplerKind::Bsdf}}}};

}  // namespace

SamplerChoice samplerChoice(SamplerKind kind) { return kChoices[static_cast<size_t>(kind)].choice; }

std::optional<SamplerKind> parseSamplerKind(std::string_view name) { return kSamplers.parse(name); }
std::string_view samplerName(SamplerKind kind) { return kSamplers.name(kind); }
std::string samplerNames() { return kSamplers.joined(); }

bool stratifies(SamplerKind kind) { return stratifies(samplerChoice(kind).warp); }

DiffuseSampling diffuseNumbers(SamplerKind kind, const PathSamples& samples, int bounce) {
    const SamplerChoice choice = samplerChoice(kind);
    if (choice.points == PointSet::StratumSequence) {
        const auto [stratum, point] = samples.stratumSequencePoint(bounce);
        return {choice.warp, stratum, point};
    }
    // The paper's estimators: a plain random point, in the schedule's stratum where there is one.
    const int stratum = stratifies(choice.warp) ? samples.stratum(bounce) : -1;
    return {choice.warp, stratum, samples.bouncePoint(bounce)};
}

SampledDirection sampleDirection(SamplerKind kind, const PathSamples& samples, int bounce) {
    const DiffuseSampling numbers = diffuseNumbers(kind, samples, bounce);
    return {warpDiffuse(numbers).direction, numbers.stratum};
}

}  // namespace strata
