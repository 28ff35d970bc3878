#pragma once
// `strata bench`, the viewer: its throughput with the panel open against `strata render` on the
// same scene and settings (the viewer must keep at least 90%), and its UI frame times at 1280x720
// in the split view while it renders (p95 under 33 ms). Both run `strata view` offscreen (EGL or
// OSMesa, the same display code as the window) as separate processes, timed from start to exit.
#include <filesystem>
#include <string>

namespace strata {

struct ViewerBenchSettings {
    std::filesystem::path scene;
    int depth = 5;
    // The throughput race: one configuration (strata24), both programs to the same spp.
    int width = 640;
    int height = 360;
    int spp = 240;
    // The frame-time runs: the default split view at this window size.
    int uiWidth = 1280;
    int uiHeight = 720;
    int uiFrames = 300;
    int repeats = 3;
    int threads = 0;  // 0: all cores
    std::filesystem::path outDir;
};

// The markdown section for the summary, or a note why it could not run (no offscreen context).
std::string runViewerComparison(const ViewerBenchSettings& settings);

}  // namespace strata
