#pragma once
// The viewer's UI thread: one call of frame() takes the latest render snapshot and whatever a
// load has finished, draws the panel, applies input (camera, divider, settings) by reconfiguring
// the render worker, and draws the display beside the panel into a frame target. Scenes and
// environment maps load on threads of their own (load_worker.h): the UI goes on drawing and the
// open scene goes on rendering until the new one is ready. The same code runs windowed and
// offscreen.
#include <chrono>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>

#include "camera_controller.h"
#include "display_pipeline.h"
#include "frame_target.h"
#include "load_worker.h"
#include "render_worker.h"
#include "viewer_panel.h"

namespace strata::viewer {

class Viewer {
public:
    // Needs a current OpenGL context with the ImGui context and its OpenGL 3 backend initialised.
    // `scene` is lit as settings.environment says already; the viewer relights it in place.
    Viewer(std::shared_ptr<LoadedScene> scene, const ViewerSettings& settings,
           std::shared_ptr<const Image> reference);

    // One UI frame. The caller has started the ImGui platform frame (io.DisplaySize, input).
    void frame(const FrameTarget& target);

    // Starts loading a scene file of any registered format, which a later frame shows, under
    // settings().environment when that is given; an .exr is instead opened as the environment
    // map (openEnvironmentMap). Returns at once; a scene load in flight is cancelled. On failure
    // (an unknown extension too) or cancel the old scene and environment stay and the panel
    // shows why.
    void openScene(const std::filesystem::path& path);
    // Starts reading the map, which then lights the open scene and the scenes opened after it,
    // at the rotation chosen; on failure the old environment stays and the panel shows why.
    void openEnvironmentMap(const std::filesystem::path& exrPath);
    void loadReference(const std::filesystem::path& exrPath);
    // A scene or map load is in flight: its outcome comes with a later frame.
    bool loading() const { return currentLoad().has_value(); }

    // Called from the viewer's other threads on each new render snapshot and at each step of a
    // load (RenderWorker::setPublishCallback, LoadWorker::setNotifyCallback).
    void setWakeCallback(const std::function<void()>& onWake);

    ViewerSettings& settings() { return settings_; }
    ViewerPanel& panel() { return panel_; }
    const WorkerConfig& workerConfig() const { return configured_; }
    // Where the last frame drew the image: the target less the panel at its left.
    const Viewport& imageArea() const { return imageArea_; }
    // The snapshot the last frame displayed (null before the first).
    const WorkerSnapshot* shownSnapshot() const { return shown_.get(); }
    // That snapshot's image as displayed, at its render size (what "save PNG" writes); null
    // before the first.
    const FrameTarget* displayedImage() const { return image_ ? &*image_ : nullptr; }

private:
    // The open scene lit by settings().environment, in place: its BVH and triangle lights stay
    // (Scene::setEnvironment); the worker lets go of the scene meanwhile and then restarts.
    void relight();
    // The load the panel shows: the scene's, else the map's.
    std::optional<LoadProgress> currentLoad() const;
    // What a finished load brings: the scene shown or the map lighting it, or the message why not.
    void finishLoad(LoadOutcome outcome);
    void showScene(std::shared_ptr<LoadedScene> scene, double seconds);
    void useEnvironmentMap(const EnvironmentMapFile& file, const std::filesystem::path& exrPath);
    void handleDivider(const ImGuiIO& io);
    // The open scene's camera lens, into the settings the panel edits.
    void takeSceneLens();
    // Ctrl + left click on the image: the lens focuses on the surface under the cursor.
    void focusOnClick(const ImGuiIO& io, const CameraPose& pose, int width, int height);
    void drawOverlays();
    void applyActions(const PanelActions& actions);
    // The displayed image at its render size, uploaded and redrawn only when the snapshot or the
    // display settings change: the display shader runs over the image's pixels, not the window's,
    // and not every frame (llvmpipe's cost per frame is what keeps the UI responsive).
    void updateImage(const DisplaySettings& display);
    // With settings().autoExposure, the display's exposure from the first whole image shown.
    void meterExposure();
    void savePng(const std::filesystem::path& path);
    void saveExr(const std::filesystem::path& stem);

    std::shared_ptr<LoadedScene> scene_;
    std::shared_ptr<const Image> reference_;
    ViewerSettings settings_;
    ViewerPanel panel_;
    CameraController camera_;
    DisplayPipeline pipeline_;
    std::shared_ptr<const WorkerSnapshot> shown_;
    std::optional<FrameTarget> image_;
    // Held, not just pointed to: a freed snapshot's address may come back as the next one's.
    std::shared_ptr<const WorkerSnapshot> imageSnapshot_;
    DisplaySettings imageSettings_;
    WorkerConfig configured_;
    bool everConfigured_ = false;
    bool relit_ = false;  // since the worker was last configured: restart it
    bool metered_ = false;  // the exposure has been taken from an image
    bool draggingDivider_ = false;
    Viewport imageArea_;
    std::chrono::steady_clock::time_point lastMotion_{};
    // Two loaders, so that choosing a map while a scene loads does not cancel the scene.
    LoadWorker sceneLoader_;
    LoadWorker mapLoader_;
    RenderWorker worker_;  // last: its thread stops before the rest goes
};

}  // namespace strata::viewer
