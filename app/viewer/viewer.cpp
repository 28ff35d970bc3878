#include "viewer.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <imgui.h>
#include <imgui_impl_opengl3.h>

#include "util/error.h"
#include "io/image_io.h"

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
    panel_.setScenePath(scene_->scenePath().string());
    panel_.setSceneReport(describeScene(*scene_), describeWarnings(*scene_));
    panel_.setEnvironmentMapChoices(studioLightMaps());
    if (settings_.environment.map) panel_.setEnvironmentMapPath(settings_.environment.map->name());
}

void Viewer::openScene(const std::filesystem::path& path) {
    if (path.extension() == ".exr") {
        openEnvironmentMap(path);
        return;
    }
    try {
        LoadedScene loaded = parseScene(readSceneBundle(path), settings_.traversal, settings_.budget);
        if (settings_.environment.kind != Environment::Kind::Default) loaded.scene.setEnvironment(settings_.environment);
        scene_ = std::make_shared<LoadedScene>(std::move(loaded));
        camera_ = CameraController(scene_->settings.pose, scene_->scene.boundsMin(), scene_->scene.boundsMax());
        panel_.setScenePath(path.string());
        panel_.setSceneReport(describeScene(*scene_), describeWarnings(*scene_));
        const size_t warnings = scene_->report.warnings.size();
        std::fprintf(stderr, "%s", describeWarnings(*scene_).c_str());
        panel_.setMessage("opened " + path.string() +
                          (warnings ? " (warnings on stderr: " + std::to_string(warnings) + ")" : ""));
    } catch (const std::exception& e) {
        panel_.setMessage(std::string("cannot open scene: ") + e.what());
    }
}

void Viewer::openEnvironmentMap(const std::filesystem::path& exrPath) {
    try {
        const EnvironmentMapFile file = readEnvironmentMap(exrPath, TextureBudget(settings_.budget.textureBytes));
        settings_.environment.kind = Environment::Kind::Map;
        settings_.environment.map = file.map;
        relight();
        panel_.setEnvironmentMapPath(exrPath.string());
        panel_.setMessage("environment " + exrPath.string() +
                          (file.zeroedNegatives ? " (" + std::to_string(file.zeroedNegatives) +
                                                      " slightly negative texel components read as 0)"
                                                : ""));
    } catch (const std::exception& e) {
        panel_.setMessage(std::string("cannot use environment map: ") + e.what());
    }
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

void Viewer::handleDivider(const ImGuiIO& io, const FrameTarget& target) {
    if (!settings_.split) {
        draggingDivider_ = false;
        return;
    }
    const float dividerX = settings_.display.divider * static_cast<float>(target.width());
    if (!io.WantCaptureMouse && ImGui::IsMouseClicked(0) &&
        std::abs(io.MousePos.x - dividerX) <= kDividerGrabPixels) {
        draggingDivider_ = true;
    }
    if (!io.MouseDown[0]) draggingDivider_ = false;
    if (draggingDivider_) {
        settings_.display.divider = std::clamp(io.MousePos.x / static_cast<float>(target.width()), 0.0f, 1.0f);
    }
    if (!io.WantCaptureMouse && std::abs(io.MousePos.x - dividerX) <= kDividerGrabPixels) {
        ImGui::SetMouseCursor(ImGuiMouseCursor_ResizeEW);
    }
}

void Viewer::frame(const FrameTarget& target) {
    ImGui_ImplOpenGL3_NewFrame();
    ImGui::NewFrame();
    const ImGuiIO& io = ImGui::GetIO();

    if (auto latest = worker_.latest(); latest && latest != shown_) shown_ = std::move(latest);

    const PanelActions actions = panel_.draw(settings_, shown_.get(), scene_->scene);
    handleDivider(io, target);
    const auto now = std::chrono::steady_clock::now();
    if (camera_.update(io, !io.WantCaptureMouse && !draggingDivider_, !io.WantCaptureKeyboard)) lastMotion_ = now;
    // A relight previews like a camera motion, so that dragging the rotation or intensity is fluid.
    if (actions.relight) lastMotion_ = now;
    applyActions(actions);

    WorkerConfig config;
    config.scene = scene_;
    config.pose = camera_.pose();
    config.width = std::max(1, static_cast<int>(std::lround(target.width() * settings_.resolutionScale)));
    config.height = std::max(1, static_cast<int>(std::lround(target.height() * settings_.resolutionScale)));
    config.sides = settings_.sides();
    config.nextEventEstimation = settings_.nextEventEstimation;
    config.rouletteDepth = settings_.rouletteDepth;
    config.seed = settings_.seed;
    config.threads = settings_.threads;
    config.preview = now - lastMotion_ < kSettleTime;
    config.reference = reference_;
    config.noiseThreshold = settings_.noiseThreshold;
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
        image_->blitTo(target);  // covers the whole target: no clear needed (a full-screen pass saved)
    } else {
        target.bind();
        glClearColor(0.1f, 0.1f, 0.1f, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
    }
    drawOverlays(target);
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
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

void Viewer::drawOverlays(const FrameTarget& target) {
    if (!settings_.split) return;
    ImDrawList* draw = ImGui::GetBackgroundDrawList();
    const float x = settings_.display.divider * static_cast<float>(target.width());
    const float height = static_cast<float>(target.height());
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
        const DisplayImage& display = shown_->sides[side].image;
        Image image{display.width, display.height, {}};
        image.pixels.resize(static_cast<size_t>(display.width) * display.height);
        for (size_t p = 0; p < image.pixels.size(); ++p) {
            image.pixels[p] = glm::vec3(display.meanAndCount[4 * p], display.meanAndCount[4 * p + 1],
                                        display.meanAndCount[4 * p + 2]);
        }
        const std::string suffix = shown_->sides.size() == 1 ? "" : (side == 0 ? ".left" : ".right");
        const std::filesystem::path path = stem.string() + suffix + ".exr";
        writeImage(path, image);
        written.append(" ").append(path.string());
    }
    panel_.setMessage("wrote" + written);
}

}  // namespace strata::viewer
