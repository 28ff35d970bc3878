#include "viewer_panel.h"

#include <algorithm>
#include <cstdio>

#include "error_plot.h"
#include "io/image_io.h"
#include "integrator/progressive_renderer.h"
#include "scene/scene.h"
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

}  // namespace

std::vector<SideConfig> ViewerSettings::sides() const {
    if (split) return {halves[0], halves[1]};
    return {single};
}

void ViewerPanel::remember(const std::string& name, bool labelled) {
    Rect rect{ImGui::GetItemRectMin(), ImGui::GetItemRectMax()};
    if (labelled) rect.max.x = rect.min.x + ImGui::CalcItemWidth();
    controls_[name] = rect;
}

void ViewerPanel::setSceneReport(std::string summary, std::string warnings) {
    sceneSummary_ = std::move(summary);
    sceneWarnings_ = std::move(warnings);
}

std::string describeEnvironment(const Scene& scene) {
    if (scene.lights().litByDefault()) return "default white sky: the scene has no light";
    const Environment& environment = scene.mesh().environment;
    char text[128];
    switch (environment.kind) {
        case Environment::Kind::Uniform:
            std::snprintf(text, sizeof text, "uniform (%.3g, %.3g, %.3g)", environment.radiance.x,
                          environment.radiance.y, environment.radiance.z);
            return text;
        case Environment::Kind::Map:
            std::snprintf(text, sizeof text, "map %dx%d turned %.3g degrees", environment.map->width,
                          environment.map->height, environment.rotationDegrees);
            return text;
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

PanelActions ViewerPanel::draw(ViewerSettings& settings, const WorkerSnapshot* snapshot, const Scene& scene) {
    PanelActions actions;
    ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(380, ImGui::GetIO().DisplaySize.y - 16), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowBgAlpha(0.85f);
    ImGui::Begin("Strata");
    ImGui::PushItemWidth(190.0f);
    readouts(snapshot);

    if (ImGui::CollapsingHeader("Rendering", ImGuiTreeNodeFlags_DefaultOpen)) {
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
        ImGui::SliderInt("roulette from bounce", &settings.rouletteDepth, -1, kMaxDepth,
                         settings.rouletteDepth < 0 ? "off" : "%d");
        int seed = static_cast<int>(settings.seed);
        if (ImGui::InputInt("seed", &seed)) settings.seed = static_cast<uint64_t>(std::max(seed, 0));
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
    if (snapshot && settings.split && ImGui::CollapsingHeader("Noise", ImGuiTreeNodeFlags_DefaultOpen)) {
        errorPlots(*snapshot, settings);
    }
    if (ImGui::CollapsingHeader("Display", ImGuiTreeNodeFlags_DefaultOpen)) {
        int view = static_cast<int>(settings.display.view);
        ImGui::Combo("view", &view, kViews, IM_ARRAYSIZE(kViews));
        settings.display.view = static_cast<DisplayView>(view);
        int tonemap = static_cast<int>(settings.display.tonemap);
        ImGui::Combo("tonemap", &tonemap, kTonemaps, IM_ARRAYSIZE(kTonemaps));
        settings.display.tonemap = static_cast<Tonemap>(tonemap);
        ImGui::SliderFloat("exposure", &settings.display.exposure, -8.0f, 8.0f, "%.1f stops");
        if (settings.display.view == DisplayView::RelativeError) {
            ImGui::SliderFloat("error scale", &settings.display.errorScale, 0.001f, 1.0f, "%.3f",
                               ImGuiSliderFlags_Logarithmic);
        }
    }
    const bool filesOpen = ImGui::CollapsingHeader("Files");
    remember("Files", false);
    if (filesOpen) {
        ImGui::InputText("scene file", scenePath_.data(), scenePath_.size());
        actions.openScene = ImGui::Button("open scene");
        ImGui::InputText("reference .exr", referencePath_.data(), referencePath_.size());
        actions.loadReference = ImGui::Button("load reference");
        ImGui::InputText("save as", outputStem_.data(), outputStem_.size());
        actions.savePng = ImGui::Button("save PNG");
        remember("save PNG", false);
        ImGui::SameLine();
        actions.saveExr = ImGui::Button("save EXR");
        remember("save EXR", false);
    }
    ImGui::TextWrapped("%s", sceneSummary_.c_str());
    if (!sceneWarnings_.empty()) ImGui::TextColored(ImVec4(1, 0.7f, 0.2f, 1), "%s", sceneWarnings_.c_str());
    ImGui::TextWrapped("environment: %s", describeEnvironment(scene).c_str());
    if (!message_.empty()) ImGui::TextWrapped("%s", message_.c_str());
    ImGui::PopItemWidth();
    ImGui::End();
    return actions;
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
    drawErrorPlot("##error_vs_spp", ErrorAxis::Spp, series, 100.0f);
    drawErrorPlot("##error_vs_seconds", ErrorAxis::Seconds, series, 100.0f);
}

}  // namespace strata::viewer
