#include "viewer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <imgui.h>
#include <imgui_impl_opengl3.h>

#include "util/error.h"
#include "io/auto_exposure.h"
#include "io/image_io.h"
#include "scene/scene_format.h"

namespace strata::viewer {
namespace {
// After the last camera motion, keep the cheap preview this long before full passes resume, so
// that a drag with short pauses between mouse events stays fluid.
constexpr auto kSettleTime = std::chrono::milliseconds(150);
constexpr float kDividerGrabPixels = 6.0f;
// Blender's bundled studio-light worlds (CC0), offered in the panel when Blender is installed.
const std::filesystem::path kStudioLights = "/usr/share/blender/datafiles/studiolights/world";

std::vector<std::string> studioLightMaps() {
    std::vector<std::string> maps;
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(kStudioLights, error)) {
        if (entry.path().extension() == ".exr") maps.push_back(entry.path().string());
    }
    std::sort(maps.begin(), maps.end());
    return maps;
}

std::string sideText(const SideConfig& side, const SideSnapshot* snapshot) {
    char text[160];
    const int n = std::snprintf(text, sizeof text, "%s, K=%d", std::string(samplerName(side.sampler)).c_str(),
                                side.depth);
    if (snapshot && !snapshot->history.empty()) {
        std::snprintf(text + n, sizeof text - n, "   error %.3g", snapshot->history.back().error);
    }
    return text;
}
}  // namespace

Viewer::Viewer(std::shared_ptr<LoadedScene> scene, const ViewerSettings& settings,
               std::shared_ptr<const Image> reference)
    : scene_(std::move(scene)),
      reference_(std::move(reference)),
      settings_(settings),
      camera_(scene_->settings.pose, scene_->scene.boundsMin(), scene_->scene.boundsMax()) {
    takeSceneLens();
    panel_.setScenePath(scene_->scenePath().string());
    panel_.setSceneReport(describeScene(*scene_), describeWarnings(*scene_));
    panel_.setEnvironmentMapChoices(studioLightMaps());
    if (settings_.environment.map) panel_.setEnvironmentMapPath(settings_.environment.map->name());
}

void Viewer::openScene(const std::filesystem::path& path) {
    if (lowerCaseExtension(path) == ".exr") {
        openEnvironmentMap(path);
        return;
    }
    sceneLoader_.start({LoadRequest::Kind::Scene, path, settings_.traversal, settings_.budget, settings_.files});
}

void Viewer::openEnvironmentMap(const std::filesystem::path& exrPath) {
    mapLoader_.start(
        {LoadRequest::Kind::EnvironmentMap, exrPath, settings_.traversal, settings_.budget, settings_.files});
}

void Viewer::setWakeCallback(const std::function<void()>& onWake) {
    worker_.setPublishCallback(onWake);
    sceneLoader_.setNotifyCallback(onWake);
    mapLoader_.setNotifyCallback(onWake);
}

std::optional<LoadProgress> Viewer::currentLoad() const {
    if (auto scene = sceneLoader_.progress()) return scene;
    return mapLoader_.progress();
}

void Viewer::finishLoad(LoadOutcome outcome) {
    const bool scene = outcome.request.kind == LoadRequest::Kind::Scene;
    const std::string path = outcome.request.path.string();
    if (outcome.cancelled) {
        panel_.setMessage("cancelled loading " + path +
                          (scene ? "; the open scene stays" : "; the environment stays"));
    } else if (!outcome.error.empty()) {
        panel_.setMessage((scene ? "cannot open scene: " : "cannot use environment map: ") + outcome.error);
    } else if (scene) {
        showScene(std::move(outcome.scene), outcome.seconds);
    } else {
        useEnvironmentMap(*outcome.map, outcome.request.path);
    }
}

void Viewer::showScene(std::shared_ptr<LoadedScene> scene, double seconds) {
    // Here, before the render worker sees the scene: whatever the environment is now, also when
    // it changed while the scene loaded.
    if (settings_.environment.kind != Environment::Kind::Default) {
        scene->scene.setEnvironment(settings_.environment);
    }
    scene_ = std::move(scene);
    camera_ = CameraController(scene_->settings.pose, scene_->scene.boundsMin(), scene_->scene.boundsMax());
    takeSceneLens();
    const std::string path = scene_->scenePath().string();
    panel_.setScenePath(path);
    panel_.setSceneReport(describeScene(*scene_), describeWarnings(*scene_));
    // Said apart from the warnings, since it is why the scene opened at all: without
    // --allow-outside-files these files would have been refused.
    const size_t outside = scene_->bundle.outsideNotes.size();
    panel_.setSceneNote(outside == 0 ? std::string()
                                     : "read " + std::to_string(outside) + (outside == 1 ? " file" : " files") +
                                           " outside the scene's folder, as --allow-outside-files lets it");
    const size_t warnings = scene_->report.warnings.size();
    std::fprintf(stderr, "%s", describeWarnings(*scene_).c_str());
    char time[32];
    std::snprintf(time, sizeof time, " in %.2f s", seconds);
    panel_.setMessage("opened " + path + time +
                      (warnings ? " (warnings on stderr: " + std::to_string(warnings) + ")" : ""));
}

void Viewer::useEnvironmentMap(const EnvironmentMapFile& file, const std::filesystem::path& exrPath) {
    settings_.environment.kind = Environment::Kind::Map;
    settings_.environment.map = file.map;
    relight();
    panel_.setEnvironmentMapPath(exrPath.string());
    panel_.setMessage("environment " + exrPath.string() +
                      (file.zeroedNegatives ? " (" + std::to_string(file.zeroedNegatives) +
                                                  " slightly negative texel components read as 0)"
                                            : ""));
}

void Viewer::relight() {
    worker_.release();
    scene_->scene.setEnvironment(settings_.environment);
    relit_ = true;
}

void Viewer::loadReference(const std::filesystem::path& exrPath) {
    try {
        reference_ = std::make_shared<const Image>(readExr(exrPath));
        panel_.setReferencePath(exrPath.string());
        panel_.setMessage("reference " + exrPath.string() + " (" + std::to_string(reference_->width) + "x" +
                          std::to_string(reference_->height) + "; RMSE needs the same render size)");
    } catch (const std::exception& e) {
        panel_.setMessage(std::string("cannot load reference: ") + e.what());
    }
}

void Viewer::handleDivider(const ImGuiIO& io) {
    if (!settings_.split) {
        draggingDivider_ = false;
        return;
    }
    const float left = static_cast<float>(imageArea_.x), width = static_cast<float>(imageArea_.width);
    const float dividerX = left + settings_.display.divider * width;
    if (!io.WantCaptureMouse && ImGui::IsMouseClicked(0) &&
        std::abs(io.MousePos.x - dividerX) <= kDividerGrabPixels) {
        draggingDivider_ = true;
    }
    if (!io.MouseDown[0]) draggingDivider_ = false;
    if (draggingDivider_) {
        settings_.display.divider = std::clamp((io.MousePos.x - left) / std::max(width, 1.0f), 0.0f, 1.0f);
    }
    if (!io.WantCaptureMouse && std::abs(io.MousePos.x - dividerX) <= kDividerGrabPixels) {
        ImGui::SetMouseCursor(ImGuiMouseCursor_ResizeEW);
    }
}

void Viewer::takeSceneLens() {
    settings_.apertureRadius = scene_->settings.pose.apertureRadius;
    settings_.focusDistance = scene_->settings.pose.focusDistance;
}

void Viewer::focusOnClick(const ImGuiIO& io, const CameraPose& pose, int width, int height) {
    if (io.WantCaptureMouse || !io.KeyCtrl || !ImGui::IsMouseClicked(0)) return;
    const float u = (io.MousePos.x - static_cast<float>(imageArea_.x)) / static_cast<float>(imageArea_.width);
    const float v = io.MousePos.y / static_cast<float>(imageArea_.height);
    if (!(u >= 0.0f && u < 1.0f && v >= 0.0f && v < 1.0f)) return;
    // The pinhole ray through the pixel's centre, to the first surface: its depth along the view.
    CameraPose pinhole = pose;
    pinhole.apertureRadius = 0.0f;
    const Ray ray = Camera(pinhole, width, height)
                        .generateRay(static_cast<int>(u * static_cast<float>(width)),
                                     static_cast<int>(v * static_cast<float>(height)), glm::vec2(0.5f));
    if (const auto hit = scene_->scene.intersect(ray)) {
        settings_.focusDistance = hit->t * glm::dot(ray.direction, glm::normalize(pose.lookAt - pose.position));
        char message[64];
        std::snprintf(message, sizeof message, "focused at %.4g", settings_.focusDistance);
        panel_.setMessage(message);
    }
}

void Viewer::frame(const FrameTarget& target) {
    ImGui_ImplOpenGL3_NewFrame();
    ImGui::NewFrame();
    const ImGuiIO& io = ImGui::GetIO();

    if (auto latest = worker_.latest(); latest && latest != shown_) shown_ = std::move(latest);
    for (LoadWorker* loader : {&sceneLoader_, &mapLoader_}) {
        if (auto outcome = loader->take()) finishLoad(std::move(*outcome));
    }
    meterExposure();

    const PanelActions actions = panel_.draw(settings_, shown_.get(), scene_->scene, currentLoad());
    // The image has the window right of the panel, and the render its size: nothing of it is
    // hidden under a control.
    const int panelWidth = static_cast<int>(std::ceil(panel_.width(static_cast<float>(target.width()))));
    imageArea_ = Viewport{panelWidth, 0, std::max(1, target.width() - panelWidth), target.height()};
    handleDivider(io);
    const auto now = std::chrono::steady_clock::now();
    if (camera_.update(io, !io.WantCaptureMouse && !draggingDivider_, !io.WantCaptureKeyboard)) lastMotion_ = now;
    // A relight previews like a camera motion, so that dragging the rotation or intensity is fluid.
    if (actions.relight) lastMotion_ = now;
    applyActions(actions);

    WorkerConfig config;
    config.scene = scene_;
    config.pose = camera_.pose();
    config.width = std::max(1, static_cast<int>(std::lround(imageArea_.width * settings_.resolutionScale)));
    config.height = std::max(1, static_cast<int>(std::lround(imageArea_.height * settings_.resolutionScale)));
    focusOnClick(io, config.pose, config.width, config.height);
    config.pose.apertureRadius = settings_.apertureRadius;
    config.pose.focusDistance = settings_.focusDistance;
    config.sides = settings_.sides();
    config.nextEventEstimation = settings_.nextEventEstimation;
    config.rouletteDepth = settings_.rouletteDepth;
    config.lightSampler = settings_.lightSampler;
    config.terminatorOffset = settings_.terminatorOffset;
    config.seed = settings_.seed;
    config.threads = settings_.threads;
    config.preview = now - lastMotion_ < kSettleTime;
    config.reference = reference_;
    config.noiseThreshold = settings_.noiseThreshold;
    config.backdrop = settings_.backdrop;
    config.targetSpp = static_cast<uint32_t>(settings_.targetSpp);
    config.targetSeconds = settings_.targetSeconds;
    config.paused = settings_.paused;
    if (!everConfigured_ || actions.reset || relit_ || needsRestart(configured_, config) ||
        configured_.targetSpp != config.targetSpp || configured_.targetSeconds != config.targetSeconds ||
        configured_.paused != config.paused) {
        worker_.configure(config, actions.reset || relit_);
        configured_ = config;
        everConfigured_ = true;
        relit_ = false;
    }

    DisplaySettings display = settings_.display;
    display.split = settings_.split && shown_ && shown_->sides.size() == 2;
    display.sampleScale = std::max(1.0f, shown_ ? static_cast<float>(shown_->spp) : 1.0f);
    updateImage(display);
    if (image_) {
        // Covers the image area, and the panel's opaque window the rest: no clear needed (a
        // full-window pass saved).
        image_->blitTo(target, imageArea_);
    } else {
        target.bind();
        glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
    }
    drawOverlays();
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

void Viewer::meterExposure() {
    if (!settings_.autoExposure || metered_ || !shown_ || shown_->preview || shown_->sides.empty()) return;
    const DisplayImage& image = shown_->sides[0].image;
    // Whole: every pixel has its first path (a snapshot between bands has rows without).
    for (size_t p = 3; p < image.meanAndCount.size(); p += 4) {
        if (image.meanAndCount[p] == 0.0f) return;
    }
    settings_.display.exposure = autoExposure(image.radiance());
    metered_ = true;
}

void Viewer::updateImage(const DisplaySettings& display) {
    if (!shown_ || shown_->sides.empty()) return;
    const DisplayImage& image = shown_->sides[0].image;
    if (image.width < 1 || image.height < 1) return;
    const bool resized = !image_ || image_->width() != image.width || image_->height() != image.height;
    if (!resized && imageSnapshot_ == shown_ && imageSettings_ == display) return;
    // A new snapshot, or a view that reads the error textures this snapshot's upload skipped.
    if (imageSnapshot_ != shown_ ||
        (DisplayPipeline::readsError(display.view) && !DisplayPipeline::readsError(imageSettings_.view))) {
        for (size_t side = 0; side < shown_->sides.size(); ++side) {
            pipeline_.upload(static_cast<int>(side), shown_->sides[side].image, display.view);
        }
    }
    if (resized) image_.emplace(FrameTarget::offscreen(image.width, image.height));
    image_->bind();
    pipeline_.draw(display, Viewport{0, 0, image.width, image.height});
    imageSnapshot_ = shown_;
    imageSettings_ = display;
}

void Viewer::drawOverlays() {
    if (!settings_.split) return;
    ImDrawList* draw = ImGui::GetBackgroundDrawList();
    const float x =
        static_cast<float>(imageArea_.x) + settings_.display.divider * static_cast<float>(imageArea_.width);
    const float height = static_cast<float>(imageArea_.height);
    draw->AddLine(ImVec2(x, 0), ImVec2(x, height), IM_COL32(255, 255, 255, 220), 2.0f);
    for (int side = 0; side < 2; ++side) {
        const SideSnapshot* snapshot =
            shown_ && shown_->sides.size() == 2 ? &shown_->sides[side] : nullptr;
        const std::string text = sideText(settings_.halves[side], snapshot);
        const ImVec2 size = ImGui::CalcTextSize(text.c_str());
        const ImVec2 at(side == 0 ? x - size.x - 12.0f : x + 12.0f, height - size.y - 12.0f);
        draw->AddRectFilled(ImVec2(at.x - 4, at.y - 3), ImVec2(at.x + size.x + 4, at.y + size.y + 3),
                            IM_COL32(0, 0, 0, 170), 3.0f);
        draw->AddText(at, kSideColours[side], text.c_str());
    }
}

void Viewer::applyActions(const PanelActions& actions) {
    if (actions.cancelLoad) (sceneLoader_.progress() ? sceneLoader_ : mapLoader_).cancel();
    if (actions.openScene) openScene(panel_.scenePath());
    if (actions.openEnvironmentMap) openEnvironmentMap(panel_.environmentMapPath());
    if (actions.relight) relight();
    if (actions.loadReference) loadReference(panel_.referencePath());
    try {
        if (actions.savePng) savePng(panel_.outputStem() + ".png");
        if (actions.saveExr) saveExr(panel_.outputStem());
    } catch (const std::exception& e) {
        panel_.setMessage(e.what());
    }
}

void Viewer::savePng(const std::filesystem::path& path) {
    // As displayed, without the panel, at the render size.
    if (!image_) throw Error("nothing rendered yet");
    image_->writePng(path);
    panel_.setMessage("wrote " + path.string());
}

void Viewer::saveExr(const std::filesystem::path& stem) {
    if (!shown_ || shown_->sides.empty()) throw Error("nothing rendered yet");
    std::string written;
    for (size_t side = 0; side < shown_->sides.size(); ++side) {
        const Image image = shown_->sides[side].image.radiance();
        const std::string suffix = shown_->sides.size() == 1 ? "" : (side == 0 ? ".left" : ".right");
        const std::filesystem::path path = stem.string() + suffix + ".exr";
        writeImage(path, image);
        written.append(" ").append(path.string());
    }
    panel_.setMessage("wrote" + written);
}

}  // namespace strata::viewer
