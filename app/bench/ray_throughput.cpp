#include "bench/ray_throughput.h"

#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <time.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "util/constants.h"
#include "sampling/random.h"

namespace strata {
namespace {

constexpr size_t kRayCount = size_t{1} << 18;  // 6 MB of rays, reused every round
constexpr size_t kBlock = 256;                  // rays per task; a multiple of 16

struct RaySet {
    std::vector<float> origin[3];
    std::vector<float> direction[3];
};

RaySet randomRays(const Scene& scene, uint64_t seed) {
    RaySet set;
    for (int a = 0; a < 3; ++a) {
        set.origin[a].resize(kRayCount);
        set.direction[a].resize(kRayCount);
    }
    const glm::vec3 lo = scene.boundsMin();
    const glm::vec3 extent = scene.boundsMax() - lo;
    for (size_t i = 0; i < kRayCount; ++i) {
        const uint64_t key = hashCombine(seed, i);
        for (int a = 0; a < 3; ++a) set.origin[a][i] = lo[a] + extent[a] * uniformFloat(mixBits(key + a));
        const float z = 1.0f - 2.0f * uniformFloat(mixBits(key + 3));
        const float phi = 2.0f * kPi * uniformFloat(mixBits(key + 4));
        const float r = std::sqrt(std::fmax(0.0f, 1.0f - z * z));
        set.direction[0][i] = r * std::cos(phi);
        set.direction[1][i] = r * std::sin(phi);
        set.direction[2][i] = z;
    }
    return set;
}

RTCIntersectContext incoherentContext() {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    context.flags = RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
    return context;
}

void fillRay(RTCRayHit& r, const RaySet& set, size_t i) {
    r = RTCRayHit{};
    r.ray.org_x = set.origin[0][i];
    r.ray.org_y = set.origin[1][i];
    r.ray.org_z = set.origin[2][i];
    r.ray.dir_x = set.direction[0][i];
    r.ray.dir_y = set.direction[1][i];
    r.ray.dir_z = set.direction[2][i];
    r.ray.tfar = std::numeric_limits<float>::infinity();
    r.ray.mask = ~0u;
    r.hit.geomID = RTC_INVALID_GEOMETRY_ID;
}

// Packets of N rays in Embree's SoA layout; returns the hits.
template <int N, typename Packet, typename Intersect>
uint64_t tracePackets(RTCScene scene, const RaySet& set, size_t begin, Intersect intersect) {
    uint64_t hits = 0;
    RTCIntersectContext context = incoherentContext();
    alignas(64) int valid[N];
    for (int k = 0; k < N; ++k) valid[k] = -1;
    for (size_t base = begin; base < begin + kBlock; base += N) {
        Packet p{};
        for (int k = 0; k < N; ++k) {
            p.ray.org_x[k] = set.origin[0][base + k];
            p.ray.org_y[k] = set.origin[1][base + k];
            p.ray.org_z[k] = set.origin[2][base + k];
            p.ray.dir_x[k] = set.direction[0][base + k];
            p.ray.dir_y[k] = set.direction[1][base + k];
            p.ray.dir_z[k] = set.direction[2][base + k];
            p.ray.tfar[k] = std::numeric_limits<float>::infinity();
            p.ray.mask[k] = ~0u;
            p.hit.geomID[k] = RTC_INVALID_GEOMETRY_ID;
        }
        intersect(valid, scene, &context, &p);
        for (int k = 0; k < N; ++k) hits += p.hit.geomID[k] != RTC_INVALID_GEOMETRY_ID;
    }
    return hits;
}

uint64_t traceBlock(RTCScene scene, RayQuery query, const RaySet& set, size_t begin) {
    switch (query) {
        case RayQuery::Single: {
            uint64_t hits = 0;
            RTCIntersectContext context = incoherentContext();
            for (size_t i = begin; i < begin + kBlock; ++i) {
                RTCRayHit r;
                fillRay(r, set, i);
                rtcIntersect1(scene, &context, &r);
                hits += r.hit.geomID != RTC_INVALID_GEOMETRY_ID;
            }
            return hits;
        }
        case RayQuery::Packet4:
            return tracePackets<4, RTCRayHit4>(scene, set, begin, rtcIntersect4);
        case RayQuery::Packet8:
            return tracePackets<8, RTCRayHit8>(scene, set, begin, rtcIntersect8);
        case RayQuery::Packet16:
            return tracePackets<16, RTCRayHit16>(scene, set, begin, rtcIntersect16);
        case RayQuery::Stream: {
            std::vector<RTCRayHit> rays(kBlock);
            for (size_t k = 0; k < kBlock; ++k) fillRay(rays[k], set, begin + k);
            RTCIntersectContext context = incoherentContext();
            rtcIntersect1M(scene, &context, rays.data(), kBlock, sizeof(RTCRayHit));
            uint64_t hits = 0;
            for (const auto& r : rays) hits += r.hit.geomID != RTC_INVALID_GEOMETRY_ID;
            return hits;
        }
    }
    return 0;
}

}  // namespace

double processCpuSeconds() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

std::string_view rayQueryName(RayQuery query) {
    switch (query) {
        case RayQuery::Single: return "rtcIntersect1";
        case RayQuery::Packet4: return "rtcIntersect4";
        case RayQuery::Packet8: return "rtcIntersect8";
        case RayQuery::Packet16: return "rtcIntersect16";
        case RayQuery::Stream: return "rtcIntersect1M";
    }
    return "unknown";
}

RayThroughput measureRandomRays(const Scene& scene, RayQuery query, int threads, double minSeconds,
                                uint64_t seed) {
    const RaySet set = randomRays(scene, seed);
    tbb::task_arena arena = threads > 0 ? tbb::task_arena(threads) : tbb::task_arena();
    RayThroughput result;
    std::atomic<uint64_t> hits{0};
    const double cpuStart = processCpuSeconds();
    const auto start = std::chrono::steady_clock::now();
    do {
        arena.execute([&] {
            tbb::parallel_for(size_t{0}, kRayCount / kBlock, [&](size_t block) {
                hits.fetch_add(traceBlock(scene.embreeScene(), query, set, block * kBlock),
                               std::memory_order_relaxed);
            });
        });
        result.rays += kRayCount;
        result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    } while (result.seconds < minSeconds);
    result.cpuSeconds = processCpuSeconds() - cpuStart;
    result.hits = hits.load();
    return result;
}

}  // namespace strata
