#include "scene/cutout_filter.h"

#include <bit>
#include <cstdint>

#include "sampling/random.h"

namespace strata {
namespace {

// The number in [0, 1) that decides whether ray i of the filter's packet goes on through the
// blended surface it meets: a hash of the ray and of the placed triangle, so the same ray meets
// the same answer (in a packet or alone), and the layers along one ray answer independently (two
// of opacity 0.5 let a quarter through).
float passNumber(const RTCFilterFunctionNArguments* args, unsigned i) {
    const unsigned n = args->N;
    uint64_t key = hashCombine(RTCHitN_primID(args->hit, n, i), RTCHitN_instID(args->hit, n, i, 0));
    for (const float coordinate : {RTCRayN_org_x(args->ray, n, i), RTCRayN_org_y(args->ray, n, i),
                                   RTCRayN_org_z(args->ray, n, i), RTCRayN_dir_x(args->ray, n, i),
                                   RTCRayN_dir_y(args->ray, n, i), RTCRayN_dir_z(args->ray, n, i)}) {
        key = hashCombine(key, std::bit_cast<uint32_t>(coordinate));
    }
    return uniformFloat(mixBits(key));
}

// Embree 3's filter callback for N rays at once: a lane set to 0 in `valid` rejects its hit.
void rejectCutOutHits(const RTCFilterFunctionNArguments* args) {
    const auto& triangles = *static_cast<const CutoutTriangles*>(args->geometryUserPtr);
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] == 0) continue;
        const unsigned prim = RTCHitN_primID(args->hit, args->N, i);
        const float b1 = RTCHitN_u(args->hit, args->N, i);
        const float b2 = RTCHitN_v(args->hit, args->N, i);
        const auto& uv = triangles.uvs[prim];
        const Material& material = *triangles.materials[prim];
        const float u = material.textures.blended ? passNumber(args, i) : 0.0f;
        if (material.cutOut((1.0f - b1 - b2) * uv[0] + b1 * uv[1] + b2 * uv[2], u)) args->valid[i] = 0;
    }
}

}  // namespace

void attachCutoutFilter(RTCGeometry geometry, const CutoutTriangles& triangles) {
    rtcSetGeometryUserData(geometry, const_cast<CutoutTriangles*>(&triangles));
    rtcSetGeometryIntersectFilterFunction(geometry, rejectCutOutHits);
    rtcSetGeometryOccludedFilterFunction(geometry, rejectCutOutHits);
}

}  // namespace strata
