#include "viewer_run.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>
#include <thread>
#define GLFW_INCLUDE_NONE  // key codes only; OpenGL comes from glad
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_opengl3.h>

#include "util/error.h"
#include "glfw_window.h"

namespace strata::viewer {
namespace {

using Clock = std::chrono::steady_clock;

constexpr auto kIdleAfter = std::chrono::seconds(1);

// Whether this frame had user input (pointer motion, buttons, wheel, keys, typing).
bool hadInput() {
    const ImGuiIO& io = ImGui::GetIO();
    if (io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f || io.MouseWheel != 0.0f || io.WantTextInput) {
        return true;
    }
    for (bool down : io.MouseDown) {
        if (down) return true;
    }
    for (bool down : io.KeysDown) {
        if (down) return true;
    }
    return false;
}

// The worker has stopped at a target (spp, time, noise threshold) or for good (paused, failed).
bool resting(const WorkerSnapshot* shown) {
    return shown && (!shown->error.empty() || (shown->idle && !shown->preview));
}

bool finished(const ViewRunOptions& options, const ViewerSettings& settings, int frame,
              const WorkerSnapshot* shown) {
    if (options.frames <= 0 || frame < options.frames) return false;
    const bool hasTarget = settings.targetSpp > 0 || settings.targetSeconds > 0.0f || settings.noiseThreshold > 0.0f;
    // Wait for the target, unless rendering cannot get there (a failed configuration).
    return !hasTarget || resting(shown);
}

// The frame loop shared by both contexts: `beginFrame` does the platform part, `endFrame` presents,
// `waitForEvent(until)` blocks until there is input (or a new snapshot), or until `until` if given,
// and says whether it could (only a window can).
template <typename BeginFrame, typename EndFrame, typename WaitForEvent>
ViewRunReport loop(Viewer& viewer, const ViewRunOptions& options, FrameTarget& target,
                   BeginFrame beginFrame, EndFrame endFrame, WaitForEvent waitForEvent) {
    ViewRunReport report;
    const auto activeFrame = std::chrono::duration_cast<Clock::duration>(
        std::chrono::duration<double>(1.0 / options.activeFramesPerSecond));
    const auto idleFrame = std::chrono::duration_cast<Clock::duration>(
        std::chrono::duration<double>(1.0 / options.idleFramesPerSecond));
    auto lastInput = Clock::now();
    const auto start = Clock::now();
    auto previous = start;
    for (int frame = 0;; ++frame) {
        const auto frameStart = Clock::now();
        const float delta = std::max(1e-4f, std::chrono::duration<float>(frameStart - previous).count());
        previous = frameStart;
        if (!beginFrame(delta)) break;
        viewer.frame(target);
        const bool last = finished(options, viewer.settings(), frame + 1, viewer.shownSnapshot());
        if (last && options.screenshot) target.writePng(*options.screenshot);
        endFrame();
        report.frameSeconds.push_back(std::chrono::duration<double>(Clock::now() - frameStart).count());
        if (last) break;
        if (hadInput()) lastInput = Clock::now();
        const bool quiet = Clock::now() - lastInput >= kIdleAfter;
        // Rendering done, nothing loading and nobody touching anything: nothing on screen can
        // change until an event comes (input, or a snapshot from the worker), so block on it: no
        // CPU at rest.
        if (quiet && resting(viewer.shownSnapshot()) && !viewer.loading() && waitForEvent(std::nullopt)) continue;
        // While the render goes on, a quiet window draws at the idle rate, and at once when input
        // or a snapshot comes.
        const auto next = frameStart + (quiet ? idleFrame : activeFrame);
        if (!(quiet && waitForEvent(next))) std::this_thread::sleep_until(next);
    }
    report.wallSeconds = std::chrono::duration<double>(Clock::now() - start).count();
    report.last = viewer.shownSnapshot() ? std::make_shared<WorkerSnapshot>(*viewer.shownSnapshot()) : nullptr;
    return report;
}

}  // namespace

ImGuiSession::ImGuiSession() {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;
    ImGui::StyleColorsDark();
    if (!ImGui_ImplOpenGL3_Init("#version 330 core")) {
        ImGui::DestroyContext();
        throw Error("OpenGL: the ImGui OpenGL 3 renderer cannot start");
    }
}

ImGuiSession::~ImGuiSession() {
    ImGui_ImplOpenGL3_Shutdown();
    ImGui::DestroyContext();
}

void beginOffscreenFrame(int width, int height, float deltaSeconds) {
    ImGuiIO& io = ImGui::GetIO();
    if (io.BackendPlatformName == nullptr) {
        io.BackendPlatformName = "strata_offscreen";
        // The key map of the GLFW backend, so that scripted keys mean the same as real ones.
        const std::pair<ImGuiKey_, int> keys[] = {
            {ImGuiKey_Tab, GLFW_KEY_TAB},         {ImGuiKey_LeftArrow, GLFW_KEY_LEFT},
            {ImGuiKey_RightArrow, GLFW_KEY_RIGHT}, {ImGuiKey_UpArrow, GLFW_KEY_UP},
            {ImGuiKey_DownArrow, GLFW_KEY_DOWN},   {ImGuiKey_Home, GLFW_KEY_HOME},
            {ImGuiKey_End, GLFW_KEY_END},         {ImGuiKey_Delete, GLFW_KEY_DELETE},
            {ImGuiKey_Backspace, GLFW_KEY_BACKSPACE}, {ImGuiKey_Enter, GLFW_KEY_ENTER},
            {ImGuiKey_Escape, GLFW_KEY_ESCAPE},   {ImGuiKey_A, GLFW_KEY_A},
            {ImGuiKey_C, GLFW_KEY_C},             {ImGuiKey_V, GLFW_KEY_V},
            {ImGuiKey_X, GLFW_KEY_X},             {ImGuiKey_Y, GLFW_KEY_Y},
            {ImGuiKey_Z, GLFW_KEY_Z}};
        for (const auto& [key, code] : keys) io.KeyMap[key] = code;
    }
    io.DisplaySize = ImVec2(static_cast<float>(width), static_cast<float>(height));
    io.DisplayFramebufferScale = ImVec2(1.0f, 1.0f);
    io.DeltaTime = deltaSeconds;
}

ViewRunReport runViewer(std::shared_ptr<LoadedScene> scene, const ViewerSettings& settings,
                        std::shared_ptr<const Image> reference, const ViewRunOptions& options) {
    if (options.width < 16 || options.height < 16 || options.width > 16384 || options.height > 16384) {
        throw UsageError("--window: size must be in 16..16384");
    }
    if (options.headless) {
        if (options.frames <= 0) throw UsageError("--headless needs --frames N (N > 0)");
        const auto context = OffscreenContext::create(options.backend);
        FrameTarget target = FrameTarget::offscreen(options.width, options.height);
        ImGuiSession imgui;
        Viewer viewer(std::move(scene), settings, std::move(reference));
        ViewRunReport report = loop(
            viewer, options, target,
            [&](float delta) {
                beginOffscreenFrame(options.width, options.height, delta);
                return true;
            },
            // Wait for the GPU (llvmpipe) so that frame times are what a display would show.
            [] { glFinish(); },
            // Offscreen there are no events to wait for: scripted frames go on at the idle rate.
            [](std::optional<Clock::time_point>) { return false; });
        report.context = context->backendName();
        return report;
    }
    GlfwWindow window(options.width, options.height, "Strata");
    ImGuiSession imgui;
    window.initImGui();
    int width = 0, height = 0;
    window.framebufferSize(width, height);
    FrameTarget target = FrameTarget::defaultFramebuffer(width, height);
    ViewRunReport report;
    {
        Viewer viewer(std::move(scene), settings, std::move(reference));
        // A new render snapshot, or a load's progress, ends the wait for events below.
        viewer.setWakeCallback([] { glfwPostEmptyEvent(); });
        report = loop(
            viewer, options, target,
            [&](float) {
                window.beginFrame();
                for (const auto& path : window.takeDroppedPaths()) viewer.openScene(path);
                window.framebufferSize(width, height);
                target.resize(std::max(width, 1), std::max(height, 1));
                return !window.shouldClose();
            },
            [&] { window.swapBuffers(); },
            [&](std::optional<Clock::time_point> until) {
                if (until) {
                    window.waitForEvent(std::chrono::duration<double>(*until - Clock::now()).count());
                } else {
                    window.waitForEvent();
                }
                return true;
            });
    }
    window.shutdownImGui();
    report.context = "glfw";
    return report;
}

double percentile(std::vector<double> values, double p) {
    if (values.empty()) return 0.0;
    std::sort(values.begin(), values.end());
    const auto rank = static_cast<size_t>(std::ceil(p / 100.0 * static_cast<double>(values.size())));
    return values[std::clamp<size_t>(rank, 1, values.size()) - 1];
}

}  // namespace strata::viewer
