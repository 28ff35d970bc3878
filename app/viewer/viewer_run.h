#pragma once
// Running the viewer: the ImGui context and its OpenGL 3 renderer for the current context, the
// offscreen stand-in for a platform backend, and the frame loop of `strata view` (windowed through
// GLFW, or offscreen with --headless) with its frame-time statistics.
#include <filesystem>
#include <memory>
#include <optional>
#include <vector>

#include "offscreen_context.h"
#include "viewer.h"

namespace strata::viewer {

// ImGui context + OpenGL 3 backend for the current OpenGL context; no .ini file is written.
class ImGuiSession {
public:
    ImGuiSession();
    ~ImGuiSession();
    ImGuiSession(const ImGuiSession&) = delete;
    ImGuiSession& operator=(const ImGuiSession&) = delete;
};

// Offscreen platform frame: display size and time step, and (once) the key map, with GLFW key
// codes as the windowed backend uses. Input is whatever the caller put in io (the tests' clicks).
void beginOffscreenFrame(int width, int height, float deltaSeconds);

struct ViewRunOptions {
    bool headless = false;
    OffscreenBackend backend = OffscreenBackend::Auto;
    int width = 1280;
    int height = 720;
    int frames = 0;  // 0: until the window closes (windowed only)
    std::optional<std::filesystem::path> screenshot;
    // Frame rate cap while the user interacts, and after a second without input: the UI thread's
    // drawing (llvmpipe on a small machine) takes CPU from rendering, which needs it more while
    // nobody touches anything.
    double activeFramesPerSecond = 60.0;
    double idleFramesPerSecond = 20.0;
};

struct ViewRunReport {
    std::vector<double> frameSeconds;  // UI frame times (work, excluding the frame-rate cap's sleep)
    std::shared_ptr<const WorkerSnapshot> last;
    std::string context;  // "glfw", "egl" or "osmesa"
    double wallSeconds = 0.0;
};

// Runs frames until the window closes or, with `frames`, at least that many and, when the settings
// set a target spp, until the render worker has reached it. Writes the screenshot of the last frame.
ViewRunReport runViewer(std::shared_ptr<LoadedScene> scene, const ViewerSettings& settings,
                        std::shared_ptr<const Image> reference, const ViewRunOptions& options);

// The p-th percentile (0..100) of `values`, nearest rank.
double percentile(std::vector<double> values, double p);

}  // namespace strata::viewer
