#pragma once
// What every scattering model (bsdf.h) speaks: the kinds of lobe, the random numbers a sample
// reads and the sample it returns. Directions are in the local shading frame (normal +z) and may
// lie anywhere on the sphere: wo.z < 0 is the side below the normal, and a transmitted wi lies on
// the other side of the surface from wo. As pbrt-v4's BSDFSample and Mitsuba 3's BSDFSample3f.
#include <cstdint>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "sampling/diffuse_warp.h"

namespace strata {

// A lobe's kind, as flags: which side of the surface it sends light to and how it spreads it.
enum BsdfFlag : uint8_t {
    kReflection = 1,
    kTransmission = 2,
    kDiffuse = 4,
    kGlossy = 8,
    kSpecular = 16,  // a Dirac delta: no light sample can find its direction
};
using BsdfFlags = uint8_t;

constexpr bool isSpecular(BsdfFlags flags) { return (flags & kSpecular) != 0; }
constexpr bool isTransmission(BsdfFlags flags) { return (flags & kTransmission) != 0; }

// Which quantity a path carries. Refraction compresses radiance by 1/eta^2 (Veach 1997, 5.2) but
// not importance, so a BSDF that refracts differs between the two; camera paths carry radiance.
enum class TransportMode { Radiance, Importance };

// The numbers one sample reads: the diffuse lobe's (warp, stratum, point), which the direction
// sampler chooses (sampling/direction_sampler.h), a point for any other lobe and a number that
// chooses among the lobes, both uniform on [0,1).
struct BsdfNumbers {
    DiffuseSampling diffuse;
    glm::vec2 lobePoint{0.0f};
    float lobeChoice = 0.0f;

    // Plain importance sampling with independent numbers: the diffuse lobe by cosine.
    static BsdfNumbers independent(glm::vec2 u, float lobeChoice) {
        return {{DiffuseWarp::Cosine, -1, u}, u, lobeChoice};
    }
};

struct BsdfSample {
    glm::vec3 wi;      // unit
    glm::vec3 f;       // f(wo, wi); for a specular lobe the delta's factor, weight * pdf / |cos|
    float pdf;         // density of wi over every lobe the BSDF samples (marginal over the
                       // stratum); for a specular lobe the probability of choosing it
    glm::vec3 weight;  // f |cos(theta_i)| / pdf, what the path's throughput is multiplied by
    BsdfFlags flags;   // the lobe sampled
    float eta;         // relative index of refraction crossed (1 for reflection)
    int stratum;       // the diffuse lobe's stratum, -1 for another lobe or an unstratified warp
};

}  // namespace strata
