#include "viewer_panel.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <utility>

#include "error_plot.h"
#include "io/image_io.h"
#include "integrator/progressive_renderer.h"
#include "scene/scene.h"
#include "scene/scene_format.h"
#include "integrator/truncation.h"

namespace strata::viewer {
namespace {

// Every sampler the renderer knows, from its "a|b|..." list, so new ones appear in the combo.
std::vector<SamplerKind> allSamplers() {
    std::vector<SamplerKind> kinds;
    const std::string names = samplerNames();
    for (size_t begin = 0; begin <= names.size();) {
        const size_t end = std::min(names.find('|', begin), names.size());
        if (const auto kind = parseSamplerKind(names.substr(begin, end - begin))) kinds.push_back(*kind);
        begin = end + 1;
    }
    return kinds;
}
constexpr const char* kViews[] = {"colour", "relative error", "sample count", "adaptive mask"};
constexpr const char* kTonemaps[] = {"clamp", "reinhard", "aces"};
constexpr int kMaxDepth = 64;

std::string sideLabel(const SideConfig& side) {
    return std::string(samplerName(side.sampler)) + ", K=" + std::to_string(side.depth);
}

std::vector<std::string> sceneFileExtensions() {
    std::vector<std::string> extensions;
    for (std::string_view extension : sceneExtensions()) extensions.emplace_back(extension);
    return extensions;
}

}  // namespace

std::vector<SideConfig> ViewerSettings::sides() const {
    if (split) return {halves[0], halves[1]};
    return {single};
}

float ViewerPanel::width(float displayWidth) const {
    if (folded_) return std::min(kFoldedPanelWidth, displayWidth);
    return std::clamp(displayWidth - kMinImageWidth, 0.0f, kPanelWidth);
}

void ViewerPanel::setSceneReport(std::string summary, std::string warnings) {
    sceneSummary_ = std::move(summary);
    sceneWarnings_ = std::move(warnings);
}

std::string describeEnvironment(const Scene& scene) {
    if (scene.lights().litByDefault()) {
        return "default white sky: " + std::string(scene.lights().defaultSkyReason());
    }
    const Environment& environment = scene.lights().environment();
    char text[320];
    switch (environment.kind) {
        case Environment::Kind::Uniform:
            std::snprintf(text, sizeof text, "uniform (%.3g, %.3g, %.3g)", environment.radiance.x,
                          environment.radiance.y, environment.radiance.z);
            return text;
        case Environment::Kind::Map: {
            const Image& image = environment.map->image();
            std::snprintf(text, sizeof text, "map %s (%dx%d), turned %.3g degrees",
                          std::filesystem::path(environment.map->name()).filename().string().c_str(), image.width,
                          image.height, environment.rotationDegrees);
            return text;
        }
        case Environment::Kind::Default:
        case Environment::Kind::None: break;
    }
    return "none";
}

void ViewerPanel::setScenePath(const std::string& path) {
    std::snprintf(scenePath_.data(), scenePath_.size(), "%s", path.c_str());
}

void ViewerPanel::setReferencePath(const std::string& path) {
    std::snprintf(referencePath_.data(), referencePath_.size(), "%s", path.c_str());
}

void ViewerPanel::setEnvironmentMapPath(const std::string& path) {
    std::snprintf(environmentMapPath_.data(), environmentMapPath_.size(), "%s", path.c_str());
}

void ViewerPanel::setOutputStem(const std::string& stem) {
    std::snprintf(outputStem_.data(), outputStem_.size(), "%s", stem.c_str());
}

bool ViewerPanel::sideControls(const char* label, SideConfig& side, bool depthLocked) {
    bool changed = false;
    const std::string samplerLabel = std::string(label) + "sampler";
    const std::string depthLabel = std::string(label) + "depth K";
    const std::string current(samplerName(side.sampler));
    const bool open = ImGui::BeginCombo(samplerLabel.c_str(), current.c_str());
    remember(samplerLabel);
    if (open) {
        for (SamplerKind kind : allSamplers()) {
            const std::string name(samplerName(kind));
            if (ImGui::Selectable(name.c_str(), kind == side.sampler)) {
                changed |= kind != side.sampler;
                side.sampler = kind;
            }
            remember(samplerLabel + "/" + name, false);
        }
        ImGui::EndCombo();
    }
    ImGui::BeginDisabled(depthLocked);
    changed |= ImGui::SliderInt(depthLabel.c_str(), &side.depth, 0, kMaxDepth);
    ImGui::EndDisabled();
    remember(depthLabel);
    return changed;
}

void ViewerPanel::truncationControls(ViewerSettings& settings, const Scene& scene) {
    ImGui::Checkbox("depth from epsilon", &settings.depthFromEpsilon);
    remember("depth from epsilon", false);
    ImGui::SameLine();
    ImGui::SetNextItemWidth(90.0f);
    ImGui::InputFloat("##epsilon", &settings.epsilon, 0.0f, 0.0f, "%.1e");
    remember("epsilon", false);
    settings.epsilon = std::clamp(settings.epsilon, 1e-12f, 1e12f);
    if (!settings.depthFromEpsilon) return;
    try {
        const TruncationChoice choice = chooseSceneTruncationDepth(settings.epsilon, scene);
        const int depth = std::min(choice.depth, kMaxDepth);  // the sliders' range
        for (SideConfig* side : {&settings.single, &settings.halves[0], &settings.halves[1]}) side->depth = depth;
        const SceneSummary& summary = scene.summary();
        if (depth < choice.depth) {
            ImGui::TextWrapped("K_eps = %d is beyond the viewer's %d: rendering at %d, bound %.2e", choice.depth,
                               kMaxDepth, depth, truncationBound(depth, summary.maxAlbedo, maxEmittedRadiance(scene)));
        } else {
            ImGui::TextWrapped("K_eps = %d, bound %.2e (max albedo %.3g, max Le %.3g)", choice.depth, choice.bound,
                               static_cast<double>(summary.maxAlbedo), maxEmittedRadiance(scene));
        }
    } catch (const std::exception& e) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1, 0.7f, 0.2f, 1));
        ImGui::TextWrapped("no K_eps: %s", e.what());
        ImGui::PopStyleColor();
    }
}

void ViewerPanel::environmentControls(Environment& environment, PanelActions& actions) {
    // A radiance set elsewhere (--env-color) taken apart: the intensity its largest component.
    if (colour_ * intensity_ != environment.radiance) {
        intensity_ = std::max({environment.radiance.x, environment.radiance.y, environment.radiance.z});
        if (intensity_ > 0.0f) colour_ = environment.radiance / intensity_;
    }
    using Kind = Environment::Kind;
    constexpr std::pair<const char*, Kind> kKinds[] = {
        {"scene's", Kind::Default}, {"none", Kind::None}, {"uniform", Kind::Uniform}, {"map", Kind::Map}};
    int kind = static_cast<int>(environment.kind);
    for (const auto& [label, value] : kKinds) {
        if (value != Kind::Default) ImGui::SameLine();
        ImGui::RadioButton(label, &kind, static_cast<int>(value));
        remember(std::string("environment ") + label, false);
    }
    if (kind != static_cast<int>(environment.kind)) {
        const auto chosen = static_cast<Kind>(kind);
        choosingMap_ = chosen == Kind::Map && !environment.map;
        if (choosingMap_) {
            // No map read yet: the one named below, else the first one offered.
            if (environmentMapPath_[0] == '\0' && !mapChoices_.empty()) setEnvironmentMapPath(mapChoices_.front());
            if (environmentMapPath_[0] != '\0') actions.openEnvironmentMap = true;
        } else {
            environment.kind = chosen;
            actions.relight = true;
        }
    }
    if (environment.kind == Kind::Uniform) {
        bool changed = ImGui::ColorEdit3("colour", &colour_.x, ImGuiColorEditFlags_Float);
        remember("environment colour");
        changed |= ImGui::SliderFloat("intensity", &intensity_, 0.0f, 100.0f, "%.3g", ImGuiSliderFlags_Logarithmic);
        remember("environment intensity");
        intensity_ = std::max(intensity_, 0.0f);
        if (changed) {
            environment.radiance = colour_ * intensity_;
            actions.relight = true;
        }
    }
    if (environment.kind != Kind::Map && !choosingMap_) return;
    if (environment.kind == Kind::Map) choosingMap_ = false;
    ImGui::InputText("map file", environmentMapPath_.data(), environmentMapPath_.size());
    actions.openEnvironmentMap |= ImGui::Button("open map");
    remember("open map", false);
    ImGui::SameLine();
    browseButton("browse...", "browse maps", Browsing::EnvironmentMap);
    if (!mapChoices_.empty()) {
        const std::string current = std::filesystem::path(environmentMapPath()).filename().string();
        const bool open = ImGui::BeginCombo("studio lights", current.empty() ? "choose" : current.c_str());
        remember("studio lights", false);
        if (open) {
            for (const std::string& path : mapChoices_) {
                const std::string name = std::filesystem::path(path).filename().string();
                if (ImGui::Selectable(name.c_str(), path == environmentMapPath())) {
                    setEnvironmentMapPath(path);
                    actions.openEnvironmentMap = true;
                }
                remember("studio lights/" + name, false);
            }
            ImGui::EndCombo();
        }
    }
    if (environment.kind != Kind::Map) return;
    actions.relight |= ImGui::SliderFloat("rotation", &environment.rotationDegrees, -180.0f, 180.0f, "%.0f degrees");
    remember("environment rotation");
}

void ViewerPanel::loadLine(const std::optional<LoadProgress>& loading, PanelActions& actions) {
    if (!loading) {
        browseButton("open scene...", "open scene...", Browsing::Scene);
        ImGui::SameLine();
        ImGui::TextDisabled("or drop a file on the window");
        return;
    }
    actions.cancelLoad = ImGui::SmallButton("cancel");
    remember("cancel load", false);
    ImGui::SameLine();
    const std::string name = loading->request.path.filename().string();
    ImGui::TextColored(ImVec4(0.6f, 0.85f, 1, 1), "%s %s: %s %.1f s", loading->cancelling ? "cancelling" : "loading",
                       name.c_str(), loading->stage, loading->seconds);
}

void ViewerPanel::statusLines(const WorkerSnapshot* snapshot, const Scene& scene,
                              const std::optional<LoadProgress>& loading, PanelActions& actions) {
    readouts(snapshot);
    loadLine(loading, actions);
    ImGui::TextWrapped("%s", sceneSummary_.c_str());
    if (!sceneNote_.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(0.6f, 0.85f, 1, 1));
        ImGui::TextWrapped("%s", sceneNote_.c_str());
        ImGui::PopStyleColor();
        remember("scene note", false);
    }
    if (!sceneWarnings_.empty()) {
        const auto count = std::count(sceneWarnings_.begin(), sceneWarnings_.end(), '\n');
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1, 0.7f, 0.2f, 1));
        const bool open = ImGui::TreeNode("warnings", "%td loading warning%s", count, count == 1 ? "" : "s");
        remember("warnings", false);
        if (open) {
            ImGui::TextWrapped("%s", sceneWarnings_.c_str());
            ImGui::TreePop();
        }
        ImGui::PopStyleColor();
    }
    // Two lines kept for it, so that a relight (dragging the rotation) moves no control below.
    const float top = ImGui::GetCursorPosY();
    showLightTab_ |= ImGui::SmallButton("change");
    remember("change environment", false);
    ImGui::SameLine();
    ImGui::TextWrapped("environment: %s", describeEnvironment(scene).c_str());
    const float reserved = 2.0f * ImGui::GetTextLineHeightWithSpacing();
    if (ImGui::GetCursorPosY() < top + reserved) ImGui::SetCursorPosY(top + reserved);
    ImGui::Separator();
}

void ViewerPanel::samplingControls(ViewerSettings& settings, const Scene& scene) {
    ImGui::Checkbox("split view", &settings.split);
    remember("split view", false);
    // Locked while epsilon chooses the depth; truncationControls sets it below.
    const bool depthLocked = settings.depthFromEpsilon;
    if (settings.split) {
        sideControls("left ", settings.halves[0], depthLocked);
        sideControls("right ", settings.halves[1], depthLocked);
    } else {
        sideControls("", settings.single, depthLocked);
    }
    truncationControls(settings, scene);
    ImGui::Checkbox("next-event estimation", &settings.nextEventEstimation);
    ImGui::BeginDisabled(!settings.nextEventEstimation);
    const std::string currentLight(lightSamplerName(settings.lightSampler));
    const bool open = ImGui::BeginCombo("light choice", currentLight.c_str());
    remember("light choice");
    if (ImGui::IsItemHovered()) {
        ImGui::SetTooltip("power: by emitted power\ntree: by what each light can send to the point\n"
                          "auto: the tree where a scene has many emitters");
    }
    if (open) {
        for (LightSamplerKind kind : kLightSamplerKinds) {
            const std::string name(lightSamplerName(kind));
            if (ImGui::Selectable(name.c_str(), kind == settings.lightSampler)) settings.lightSampler = kind;
            remember("light choice/" + name, false);
        }
        ImGui::EndCombo();
    }
    ImGui::SliderFloat("terminator offset", &settings.terminatorOffset, 0.0f, 1.0f,
                       settings.terminatorOffset > 0.0f ? "%.2f" : "off");
    remember("terminator offset");
    if (ImGui::IsItemHovered()) {
        ImGui::SetTooltip("Coarse meshes with vertex normals: shadow rays toward a light within this\n"
                          "cosine of a facet's plane leave from the curved surface the normals\n"
                          "describe, not the facet (0: off; Cycles' geometry offset is 0.1)");
    }
    ImGui::EndDisabled();
    ImGui::SliderInt("roulette from bounce", &settings.rouletteDepth, -1, kMaxDepth,
                     settings.rouletteDepth < 0 ? "off" : "%d");
    int seed = static_cast<int>(settings.seed);
    if (ImGui::InputInt("seed", &seed)) settings.seed = static_cast<uint64_t>(std::max(seed, 0));
}

void ViewerPanel::budgetControls(ViewerSettings& settings, PanelActions& actions) {
    ImGui::SliderInt("threads (0: all)", &settings.threads, 0, 64);
    ImGui::SliderFloat("resolution", &settings.resolutionScale, 0.05f, 1.0f, "%.3f");
    ImGui::InputFloat("noise threshold", &settings.noiseThreshold, 0.01f, 0.05f, "%.3f");
    remember("noise threshold");
    settings.noiseThreshold = std::clamp(settings.noiseThreshold, 0.0f, 10.0f);
    ImGui::InputInt("target spp", &settings.targetSpp, kPathsPerPass, 10 * kPathsPerPass);
    remember("target spp");
    settings.targetSpp = std::max(settings.targetSpp, 0);
    ImGui::InputFloat("target seconds", &settings.targetSeconds, 1.0f, 10.0f, "%.1f");
    remember("target seconds");
    settings.targetSeconds = std::max(settings.targetSeconds, 0.0f);
    ImGui::Checkbox("paused", &settings.paused);
    ImGui::SameLine();
    actions.reset = ImGui::Button("reset");
}

void ViewerPanel::displayControls(DisplaySettings& display) {
    int view = static_cast<int>(display.view);
    ImGui::Combo("view", &view, kViews, IM_ARRAYSIZE(kViews));
    display.view = static_cast<DisplayView>(view);
    int tonemap = static_cast<int>(display.tonemap);
    ImGui::Combo("tonemap", &tonemap, kTonemaps, IM_ARRAYSIZE(kTonemaps));
    display.tonemap = static_cast<Tonemap>(tonemap);
    ImGui::SliderFloat("exposure", &display.exposure, -8.0f, 8.0f, "%.1f stops");
    if (display.view == DisplayView::RelativeError) {
        ImGui::SliderFloat("error scale", &display.errorScale, 0.001f, 1.0f, "%.3f", ImGuiSliderFlags_Logarithmic);
    }
}

void ViewerPanel::lensControls(ViewerSettings& settings, const Scene& scene) {
    // Up to a tenth of the scene's diagonal: wider blurs everything but the focal plane away.
    const float largest = 0.1f * glm::length(scene.boundsMax() - scene.boundsMin());
    ImGui::SliderFloat("aperture radius", &settings.apertureRadius, 0.0f, std::max(largest, settings.apertureRadius),
                       "%.3g", ImGuiSliderFlags_Logarithmic);
    remember("aperture radius");
    settings.apertureRadius = std::max(settings.apertureRadius, 0.0f);
    ImGui::InputFloat("focus distance", &settings.focusDistance, 0.0f, 0.0f, settings.focusDistance > 0.0f ? "%.4g" : "target");
    remember("focus distance");
    settings.focusDistance = std::max(settings.focusDistance, 0.0f);
    ImGui::TextDisabled("ctrl + click the image: focus there");
}

void ViewerPanel::browseButton(const char* label, const char* name, Browsing purpose) {
    if (ImGui::Button((std::string(label) + "##" + name).c_str())) {
        browsing_ = purpose;
        switch (purpose) {
            case Browsing::Scene: dialog_.open("Open a scene", scenePath(), sceneFileExtensions()); break;
            case Browsing::EnvironmentMap:
                dialog_.open("Open an environment map", environmentMapPath(), {".exr"});
                break;
            case Browsing::Reference: dialog_.open("Load a reference image", referencePath(), {".exr"}); break;
        }
    }
    remember(name, false);
}

void ViewerPanel::chosen(const std::string& path, PanelActions& actions) {
    switch (browsing_) {
        case Browsing::Scene:
            setScenePath(path);
            actions.openScene = true;
            break;
        case Browsing::EnvironmentMap:
            setEnvironmentMapPath(path);
            actions.openEnvironmentMap = true;
            break;
        case Browsing::Reference:
            setReferencePath(path);
            actions.loadReference = true;
            break;
    }
}

void ViewerPanel::fileControls(PanelActions& actions) {
    ImGui::InputText("scene file", scenePath_.data(), scenePath_.size());
    actions.openScene = ImGui::Button("open scene");
    ImGui::SameLine();
    browseButton("browse...", "browse scenes", Browsing::Scene);
    ImGui::InputText("reference .exr", referencePath_.data(), referencePath_.size());
    actions.loadReference = ImGui::Button("load reference");
    ImGui::SameLine();
    browseButton("browse...", "browse references", Browsing::Reference);
    ImGui::InputText("save as", outputStem_.data(), outputStem_.size());
    actions.savePng = ImGui::Button("save PNG");
    remember("save PNG", false);
    ImGui::SameLine();
    actions.saveExr = ImGui::Button("save EXR");
    remember("save EXR", false);
}

PanelActions ViewerPanel::draw(ViewerSettings& settings, const WorkerSnapshot* snapshot, const Scene& scene,
                               const std::optional<LoadProgress>& loading) {
    PanelActions actions;
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowPos(ImVec2(0, 0), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(width(display.x), display.y), ImGuiCond_Always);
    ImGui::SetNextWindowBgAlpha(1.0f);  // beside the image, not over it: nothing to show through
    constexpr ImGuiWindowFlags kSidePanel = ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoResize |
                                            ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoCollapse |
                                            ImGuiWindowFlags_NoSavedSettings |
                                            ImGuiWindowFlags_NoBringToFrontOnFocus;
    if (folded_) {
        // Only the strip's button: the window's padding would leave it no room.
        ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(2, 8));
        ImGui::Begin("Strata", nullptr, kSidePanel | ImGuiWindowFlags_NoScrollbar);
        ImGui::PopStyleVar();
        if (ImGui::ArrowButton("unfold", ImGuiDir_Right)) folded_ = false;
        remember("unfold panel", false);
    } else {
        ImGui::Begin("Strata", nullptr, kSidePanel);
        if (ImGui::ArrowButton("fold", ImGuiDir_Left)) folded_ = true;
        remember("fold panel", false);
        ImGui::SameLine();
        contents(settings, snapshot, scene, loading, actions);
    }
    ImGui::End();
    if (const auto path = dialog_.draw(controls_)) chosen(path->string(), actions);
    return actions;
}

void ViewerPanel::contents(ViewerSettings& settings, const WorkerSnapshot* snapshot, const Scene& scene,
                           const std::optional<LoadProgress>& loading, PanelActions& actions) {
    ImGui::PushItemWidth(190.0f);
    statusLines(snapshot, scene, loading, actions);

    // The controls in tabs, each short enough that the status above and the noise plots below
    // stay in view at 720 pixels of height; `remember` names each tab, for the tests' clicks.
    if (ImGui::BeginTabBar("sections")) {
        const auto tab = [&](const char* name, ImGuiTabItemFlags flags = 0) {
            const bool open = ImGui::BeginTabItem(name, nullptr, flags);
            remember(name, false);
            return open;
        };
        if (tab("Sampling")) {
            samplingControls(settings, scene);
            ImGui::EndTabItem();
        }
        if (tab("Budget")) {
            budgetControls(settings, actions);
            ImGui::EndTabItem();
        }
        if (tab("Light", std::exchange(showLightTab_, false) ? ImGuiTabItemFlags_SetSelected : 0)) {
            environmentControls(settings.environment, actions);
            ImGui::EndTabItem();
        }
        if (tab("Display")) {
            displayControls(settings.display);
            lensControls(settings, scene);
            ImGui::EndTabItem();
        }
        if (tab("Files")) {
            fileControls(actions);
            ImGui::EndTabItem();
        }
        ImGui::EndTabBar();
    }
    if (snapshot && settings.split) {
        ImGui::Separator();
        errorPlots(*snapshot, settings);
    }
    // Last, so that a message coming or going moves no control.
    if (!message_.empty()) {
        ImGui::Separator();
        ImGui::TextWrapped("%s", message_.c_str());
    }
    ImGui::PopItemWidth();
}

void ViewerPanel::readouts(const WorkerSnapshot* snapshot) {
    // Always three lines, so that the controls below never move under the pointer.
    if (!snapshot || !snapshot->error.empty()) {
        if (snapshot) {
            ImGui::TextColored(ImVec4(1, 0.4f, 0.3f, 1), "%s", snapshot->error.c_str());
        } else {
            ImGui::TextUnformatted("starting");
        }
        ImGui::NewLine();
        ImGui::NewLine();
        return;
    }
    const double seconds = std::max(snapshot->elapsedSeconds, 1e-9);
    ImGui::Text("%s  spp %u  passes %u  %.1f s",
                snapshot->preview ? "preview" : (snapshot->idle ? "done" : "rendering"), snapshot->spp,
                snapshot->passes, snapshot->elapsedSeconds);
    ImGui::Text("%.2f Msamples/s  %.2f Mrays/s", snapshot->paths / seconds * 1e-6,
                snapshot->rays / seconds * 1e-6);
    size_t active = 0, pixels = 0;
    for (const SideSnapshot& side : snapshot->sides) {
        active += side.activePixels;
        pixels += static_cast<size_t>(side.image.width) * side.image.height;
    }
    ImGui::TextColored(snapshot->droppedSamples > 0 ? ImVec4(1, 0.7f, 0.2f, 1) : ImVec4(0.7f, 0.7f, 0.7f, 1),
                       "non-finite dropped: %llu   pixels sampled: %.1f%%",
                       static_cast<unsigned long long>(snapshot->droppedSamples),
                       pixels > 0 ? 100.0 * static_cast<double>(active) / static_cast<double>(pixels) : 0.0);
}

void ViewerPanel::errorPlots(const WorkerSnapshot& snapshot, const ViewerSettings& settings) {
    if (snapshot.sides.size() != 2) return;
    // Against a reference the curves are film/image_metrics.h's RMSE, the bench's number for the
    // same image; without one, an estimate from the samples themselves, of another quantity.
    ImGui::Text("%s", snapshot.againstReference ? "RMSE vs the reference (RGB; as strata bench)"
                                               : "estimated std. error of mean luminance (RMS)");
    std::vector<ErrorSeries> series;
    for (int side = 0; side < 2; ++side) {
        series.push_back({sideLabel(settings.halves[side]), kSideColours[side], &snapshot.sides[side].history});
    }
    const auto& left = snapshot.sides[0].history;
    const auto& right = snapshot.sides[1].history;
    if (!left.empty() && !right.empty() && right.back().error > 0.0) {
        const double ratio = left.back().error / right.back().error;
        ImGui::Text("error left / right = %.3f  (variance ratio %.2f)", ratio, ratio * ratio);
    }
    // Two plots of 100 px where the panel has room, shorter (down to 60 px) where the window
    // would cut them off.
    const float room = ImGui::GetContentRegionAvail().y - ImGui::GetStyle().ItemSpacing.y;
    const float height = std::clamp(room / 2.0f, 60.0f, 100.0f);
    drawErrorPlot("##error_vs_spp", ErrorAxis::Spp, series, height);
    remember("error vs spp", false);
    drawErrorPlot("##error_vs_seconds", ErrorAxis::Seconds, series, height);
    remember("error vs seconds", false);
}

}  // namespace strata::viewer
