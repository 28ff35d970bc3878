#pragma once
// The viewer's Dear ImGui panel: every setting the user can change, the live readouts, the error
// plots of the split view and the file actions. It edits ViewerSettings and reports the buttons
// pressed; the Viewer applies them.
//
// A side panel: it fills the window's height at its left edge and the image takes the rest of
// the window (ViewerPanel::width), so no control ever covers the render; a button folds it to a
// strip. Laid out for a 1280x720 window without scrolling: at the top, always in view, the
// readouts, the load in flight (or the button that opens a scene), the open scene's load summary,
// the loader's note, its warnings (folded, with their count) and its environment; then the
// controls in tabs (sampling, budget, light, display, files); then the split view's noise plots
// and the last message. Its file dialog (file_dialog.h) picks scenes, maps and references.
#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>
#include <imgui.h>
#include <glm/vec3.hpp>

#include "control_rects.h"
#include "display_pipeline.h"
#include "file_dialog.h"
#include "lights/environment.h"
#include "load_worker.h"
#include "scene/scene_folder.h"
#include "scene/scene_format.h"
#include "scene/traversal_precision.h"
#include "render_worker.h"

namespace strata::viewer {

struct ViewerSettings {
    bool split = true;
    SideConfig single{SamplerKind::Strata24Bsdf, 5};                  // the one-image view
    std::array<SideConfig, 2> halves{SideConfig{SamplerKind::Uniform, 5},
                                     SideConfig{SamplerKind::Strata24, 5}};  // split: left, right
    // Every side's depth K_eps from the truncation error `epsilon` (renderer/integrator/truncation.h) instead
    // of the depth sliders, when the scene allows it.
    bool depthFromEpsilon = false;
    float epsilon = 1e-3f;
    bool nextEventEstimation = true;
    int rouletteDepth = kRouletteDepthDefault;  // Russian roulette from this bounce on; -1: off
    LightSamplerKind lightSampler = LightSamplerKind::Auto;  // next-event estimation's light choice
    float terminatorOffset = 0.0f;  // smooth facets' shadow rays near the terminator; 0: off
    uint64_t seed = 0;
    int threads = 0;
    float resolutionScale = 1.0f;
    float noiseThreshold = 0.0f;  // adaptive sampling's relative standard error; 0: off
    int targetSpp = 0;            // 0: no limit
    float targetSeconds = 0.0f;   // render time; 0: no limit
    // The camera's thin lens (camera.h): aperture radius (0: a pinhole) and focus distance (0:
    // the orbit's target), each scene's own when it opens.
    float apertureRadius = 0.0f;
    float focusDistance = 0.0f;
    bool paused = false;
    DisplaySettings display;
    // Take display.exposure from the first whole image shown (io/auto_exposure.h).
    bool autoExposure = false;
    // What camera rays that miss show (film/backdrop.h).
    BackdropSetting backdrop;
    // The environment given on the command line (--env options), chosen in the panel or by an
    // .exr opened since: every scene opened takes it in place of its own; Default: each scene
    // keeps its own. The map stays here while another kind is chosen, so going back to it
    // reads nothing.
    Environment environment;
    // The triangle test of every scene opened (--watertight: always the watertight one).
    Traversal traversal = Traversal::Automatic;
    // What every scene opened may read (--allow-outside-files).
    SceneReadOptions files;
    // What every scene and environment map opened may take (--max-triangles, --texture-budget).
    SceneBudget budget;

    // The sides the worker renders in the current mode.
    std::vector<SideConfig> sides() const;
};

struct PanelActions {
    bool reset = false;
    bool savePng = false;
    bool saveExr = false;
    bool openScene = false;
    bool loadReference = false;
    // settings.environment changed: light the open scene with it.
    bool relight = false;
    // Open environmentMapPath() as the environment map.
    bool openEnvironmentMap = false;
    bool cancelLoad = false;
};

// The panel's width at the default font, and the strip it folds to.
inline constexpr float kPanelWidth = 380.0f;
inline constexpr float kFoldedPanelWidth = 24.0f;
// What the panel leaves the image in a window too narrow for both.
inline constexpr float kMinImageWidth = 16.0f;

class ViewerPanel {
public:
    // Draws the panel for this frame; `snapshot` may be null before the first render. `scene` is
    // the one being rendered (its summary bounds the truncation error), `loading` the load in
    // flight, if any.
    PanelActions draw(ViewerSettings& settings, const WorkerSnapshot* snapshot, const Scene& scene,
                      const std::optional<LoadProgress>& loading);

    // The width the panel takes at the left of a window `displayWidth` pixels wide: kPanelWidth
    // (less in a window too narrow for it), or the folded strip. The image has the rest.
    float width(float displayWidth) const;
    bool folded() const { return folded_; }
    void setFolded(bool folded) { folded_ = folded; }

    // The open scene's load summary line and warnings (describeScene, describeWarnings), shown
    // under its path.
    void setSceneReport(std::string summary, std::string warnings);
    const std::string& sceneSummary() const { return sceneSummary_; }
    const std::string& sceneWarnings() const { return sceneWarnings_; }
    // A line from the loader about how the scene was read (what it allowed, or refused and
    // worked around), shown highlighted between the summary and the warnings; empty: none.
    void setSceneNote(std::string note) { sceneNote_ = std::move(note); }
    const std::string& sceneNote() const { return sceneNote_; }

    void setMessage(std::string message) { message_ = std::move(message); }
    const std::string& message() const { return message_; }
    std::string scenePath() const { return scenePath_.data(); }
    std::string referencePath() const { return referencePath_.data(); }
    std::string outputStem() const { return outputStem_.data(); }
    std::string environmentMapPath() const { return environmentMapPath_.data(); }
    void setScenePath(const std::string& path);
    void setReferencePath(const std::string& path);
    void setEnvironmentMapPath(const std::string& path);
    // Maps offered in a list beside the map file field (Blender's studio lights, when installed).
    void setEnvironmentMapChoices(std::vector<std::string> paths) { mapChoices_ = std::move(paths); }
    // The path (without extension) that the save buttons write to.
    void setOutputStem(const std::string& stem);
    const FileDialog& fileDialog() const { return dialog_; }

    // Screen rectangle of each named control as last drawn, without its label (combo items as
    // "combo label/item", the file dialog's as file_dialog.h names them), so that scripted input
    // (the tests) can click it.
    using Rect = ControlRect;
    const std::map<std::string, Rect>& controls() const { return controls_.all(); }

private:
    // What the file dialog was opened for.
    enum class Browsing { Scene, EnvironmentMap, Reference };

    void remember(const std::string& name, bool labelled = true) { controls_.remember(name, labelled); }
    // The unfolded panel's contents, top to bottom.
    void contents(ViewerSettings& settings, const WorkerSnapshot* snapshot, const Scene& scene,
                  const std::optional<LoadProgress>& loading, PanelActions& actions);
    bool sideControls(const char* label, SideConfig& side, bool depthLocked);
    // The epsilon control: sets every side's depth to K_eps and says what it chose, or why not.
    void truncationControls(ViewerSettings& settings, const Scene& scene);
    // The tabs' contents.
    void samplingControls(ViewerSettings& settings, const Scene& scene);
    void budgetControls(ViewerSettings& settings, PanelActions& actions);
    void displayControls(DisplaySettings& display);
    void lensControls(ViewerSettings& settings, const Scene& scene);
    void fileControls(PanelActions& actions);
    // What the panel always shows at its top, above the tabs: the render's readouts, the load
    // line, the scene's load summary, note and warnings, and its environment.
    void statusLines(const WorkerSnapshot* snapshot, const Scene& scene, const std::optional<LoadProgress>& loading,
                     PanelActions& actions);
    // One line: the load in flight with its stage and a Cancel button, else "open scene...".
    void loadLine(const std::optional<LoadProgress>& loading, PanelActions& actions);
    // The environment's kind, colour and intensity, map and rotation; sets `actions` for a change.
    void environmentControls(Environment& environment, PanelActions& actions);
    void readouts(const WorkerSnapshot* snapshot);
    void errorPlots(const WorkerSnapshot& snapshot, const ViewerSettings& settings);
    // A button (`label`, remembered as `name`) that opens the file dialog for `purpose` at the
    // path its field holds.
    void browseButton(const char* label, const char* name, Browsing purpose);
    // The file the dialog returned, into its field, and the action that uses it.
    void chosen(const std::string& path, PanelActions& actions);

    std::string message_;
    std::string sceneSummary_;
    std::string sceneNote_;
    std::string sceneWarnings_;
    std::array<char, 1024> scenePath_{};
    std::array<char, 1024> referencePath_{};
    std::array<char, 1024> outputStem_{'s', 't', 'r', 'a', 't', 'a'};
    std::array<char, 1024> environmentMapPath_{};
    std::vector<std::string> mapChoices_;
    // The uniform environment's radiance as the colour editor and the intensity slider show it,
    // radiance = colour * intensity; taken apart again when the radiance changes elsewhere.
    glm::vec3 colour_{1.0f};
    float intensity_ = 1.0f;
    // "map" was picked before any map was read: its file controls show until one is.
    bool choosingMap_ = false;
    bool folded_ = false;
    // The environment line's button asked for the Light tab: selected on the next draw.
    bool showLightTab_ = false;
    FileDialog dialog_;
    Browsing browsing_ = Browsing::Scene;
    ControlRects controls_;
};

// What rays that leave `scene` see, for the panel: "none", "uniform (r, g, b)", "map NAME (WxH),
// turned D degrees", or "default white sky: the scene has no light".
std::string describeEnvironment(const Scene& scene);

// Colours of the split view's two sides, shared by the labels and the plots.
inline constexpr ImU32 kSideColours[2] = {IM_COL32(255, 140, 60, 255), IM_COL32(90, 200, 255, 255)};

}  // namespace strata::viewer
