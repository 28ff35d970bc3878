#include "scene/cutout_filter.h"

namespace strata {
namespace {

// Embree 3's filter callback for N rays at once: a lane set to 0 in `valid` rejects its hit.
void rejectCutOutHits(const RTCFilterFunctionNArguments* args) {
    const auto& triangles = *static_cast<const CutoutTriangles*>(args->geometryUserPtr);
    for (unsigned i = 0; i < args->N; ++i) {
        if (args->valid[i] == 0) continue;
        const unsigned prim = RTCHitN_primID(args->hit, args->N, i);
        const float b1 = RTCHitN_u(args->hit, args->N, i);
        const float b2 = RTCHitN_v(args->hit, args->N, i);
        const auto& uv = triangles.uvs[prim];
        if (triangles.materials[prim]->cutOut((1.0f - b1 - b2) * uv[0] + b1 * uv[1] + b2 * uv[2])) {
            args->valid[i] = 0;
        }
    }
}

}  // namespace

void attachCutoutFilter(RTCGeometry geometry, const CutoutTriangles& triangles) {
    rtcSetGeometryUserData(geometry, const_cast<CutoutTriangles*>(&triangles));
    rtcSetGeometryIntersectFilterFunction(geometry, rejectCutOutHits);
    rtcSetGeometryOccludedFilterFunction(geometry, rejectCutOutHits);
}

}  // namespace strata
