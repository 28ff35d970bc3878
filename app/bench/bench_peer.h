#pragma once
// `strata bench --vs-embree`: Strata against Embree's own tutorial path tracer (Debian's
// embree-tools `pathtracer`) on the point-lit Cornell box, same size, spp and path length, the two
// programs run alternately as separate processes and timed from start to exit (load, BVH build,
// render and write for both).
#include <cstdint>
#include <filesystem>
#include <string>

namespace strata {

struct PeerSettings {
    std::filesystem::path scene;  // an OBJ with a JSON sidecar holding the camera and point lights
    // Strata's K, and Embree's --max-path-length: the tutorial's L hits each take a light sample,
    // so it renders the light of up to L bounces, as Strata does at depth K = L.
    int depth = 6;
    int width = 256;
    int height = 256;
    int spp = 24;
    int repeats = 3;
    int threads = 0;
    std::filesystem::path outDir;
};

// Returns the markdown section for the summary (or a note why it could not run).
std::string runPeerComparison(const PeerSettings& settings);

}  // namespace strata
