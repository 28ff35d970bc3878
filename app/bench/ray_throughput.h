#pragma once
// The ceiling for a path tracer: how many incoherent rays per second Embree itself traces on a
// scene, with no shading, sampling or accumulation around it. Rays start uniformly inside the
// scene's bounding box and go in uniformly random directions, which is as incoherent as a path
// tracer's bounces. Each of Embree 3's query forms is measured: one ray at a time (rtcIntersect1,
// what the path tracer uses), packets of 4/8/16 rays (rtcIntersect4/8/16) and a stream
// (rtcIntersect1M). The rays are generated before the clock starts.
#include <cstdint>
#include <string_view>
#include <vector>

#include "scene/scene.h"

namespace strata {

enum class RayQuery { Single, Packet4, Packet8, Packet16, Stream };
inline constexpr RayQuery kRayQueries[] = {RayQuery::Single, RayQuery::Packet4, RayQuery::Packet8,
                                           RayQuery::Packet16, RayQuery::Stream};
std::string_view rayQueryName(RayQuery query);  // "rtcIntersect1", ...

struct RayThroughput {
    uint64_t rays = 0;
    uint64_t hits = 0;
    double seconds = 0.0;     // wall
    double cpuSeconds = 0.0;  // the process's CPU time: on a shared machine, the robust measure
    double raysPerSecond() const { return seconds > 0.0 ? rays / seconds : 0.0; }
    double raysPerCpuSecond() const { return cpuSeconds > 0.0 ? rays / cpuSeconds : 0.0; }
};

// CPU time used so far by all threads of this process.
double processCpuSeconds();

// Traces rounds of random rays with `threads` threads (0: all) until `minSeconds` have passed.
RayThroughput measureRandomRays(const Scene& scene, RayQuery query, int threads, double minSeconds,
                                uint64_t seed = 0);

}  // namespace strata
