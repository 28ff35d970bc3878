// The viewer's UI logic under synthetic Dear ImGui input in an offscreen (OSMesa) context: the
// panel's controls reach the render worker, the panel lies beside the image, its file dialog
// opens files, and loads run off the UI thread. ImGui 1.86 predates io.AddKeyEvent, so input
// goes through io.MousePos / io.MouseDown.
#include <doctest/doctest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <thread>
#include <vector>
#include <imgui.h>

#include "io/auto_exposure.h"
#include "io/image_io.h"
#include "test_support.h"
#include "viewer_run.h"

using namespace strata;
using namespace strata::viewer;

namespace {

// The panel and, right of it, an image 480 pixels wide.
constexpr int kWidth = static_cast<int>(kPanelWidth) + 480, kHeight = 720;

struct Harness {
    int width, height;
    std::unique_ptr<OffscreenContext> context = OffscreenContext::create(OffscreenBackend::OsMesa);
    FrameTarget target;
    ImGuiSession imgui;
    Viewer viewer;

    explicit Harness(const ViewerSettings& settings, const std::filesystem::path& scene = test::cornellScene(),
                     int width = kWidth, int height = kHeight)
        : width(width),
          height(height),
          target(FrameTarget::offscreen(width, height)),
          viewer(std::make_shared<LoadedScene>(loadScene(scene)), settings, nullptr) {
        frame();
        frame();  // the panel's layout settles on its second frame
    }
    void frame() {
        beginOffscreenFrame(width, height, 1.0f / 60.0f);
        viewer.frame(target);
    }
    // Frames until no load is in flight, and one more, in which the viewer takes its outcome.
    // Returns the frames drawn while it was; fails after a generous bound (a stuck loader).
    int settle() {
        int frames = 0;
        for (; viewer.loading(); ++frames) {
            REQUIRE_MESSAGE(frames < 6000, "the load never ended");
            frame();
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
        }
        frame();
        return frames;
    }
    void open(const std::filesystem::path& path) {
        viewer.openScene(path);
        settle();
    }
    // Moves to the control's point, presses, releases: one click, as ImGui sees it over 3 frames;
    // then one more frame, so that what the click opened (a combo's popup, placed on its second
    // frame) is where the next click looks for it.
    void click(const std::string& control, float fraction = 0.5f) {
        const auto& controls = viewer.panel().controls();
        REQUIRE_MESSAGE(controls.count(control) == 1, "no control " << control);
        const auto rect = controls.at(control);
        ImGuiIO& io = ImGui::GetIO();
        io.MousePos = ImVec2(rect.min.x + fraction * (rect.max.x - rect.min.x), rect.centre().y);
        frame();
        io.MouseDown[0] = true;
        frame();
        io.MouseDown[0] = false;
        frame();
        frame();
    }
    // Two clicks as fast as the frames go: well within ImGui's double-click time.
    void doubleClick(const std::string& control) {
        click(control);
        click(control);
    }
    // Runs frames until `done` holds for the displayed snapshot; fails after a generous bound
    // (a stuck worker, not a slow one: it is not a timing assertion).
    template <typename Done>
    const WorkerSnapshot& waitFor(Done done) {
        for (int i = 0; i < 1500; ++i) {
            frame();
            const WorkerSnapshot* shown = viewer.shownSnapshot();
            if (shown && done(*shown)) return *shown;
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
        }
        FAIL("the render worker never reached the expected state");
        return *viewer.shownSnapshot();
    }
};

ViewerSettings smallSingleView() {
    ViewerSettings settings;
    settings.split = false;
    settings.single = {SamplerKind::Uniform, 5};
    settings.resolutionScale = 0.125f;  // 60x90 pixels: each step is cheap
    settings.threads = 1;
    return settings;
}

}  // namespace

TEST_CASE("choosing strata24 in the sampler combo changes the sampler and restarts accumulation") {
    Harness h(smallSingleView());
    const uint64_t before = h.waitFor([](const WorkerSnapshot& s) { return s.spp >= 2; }).generation;
    CHECK(h.viewer.workerConfig().sides.at(0).sampler == SamplerKind::Uniform);
    h.click("sampler");  // opens the combo
    h.click("sampler/strata24");
    CHECK(h.viewer.settings().single.sampler == SamplerKind::Strata24);
    CHECK(h.viewer.workerConfig().sides.at(0).sampler == SamplerKind::Strata24);
    const auto& restarted = h.waitFor([&](const WorkerSnapshot& s) { return s.generation > before; });
    CHECK(restarted.spp <= 24);  // accumulation began again
}

TEST_CASE("the light choice combo switches next-event estimation to the light tree and restarts accumulation") {
    Harness h(smallSingleView());
    const uint64_t before = h.waitFor([](const WorkerSnapshot& s) { return s.spp >= 2; }).generation;
    CHECK(h.viewer.workerConfig().lightSampler == LightSamplerKind::Auto);
    h.click("light choice");  // opens the combo
    h.click("light choice/tree");
    CHECK(h.viewer.settings().lightSampler == LightSamplerKind::Tree);
    CHECK(h.viewer.workerConfig().lightSampler == LightSamplerKind::Tree);
    const auto& restarted = h.waitFor([&](const WorkerSnapshot& s) { return s.generation > before; });
    CHECK(restarted.spp <= 24);
}

TEST_CASE("the depth slider sets the recursion depth K") {
    Harness h(smallSingleView());
    h.click("depth K", 0.99f);  // at the slider's right end
    CHECK(h.viewer.settings().single.depth == 64);
    CHECK(h.viewer.workerConfig().sides.at(0).depth == 64);
    h.click("depth K", 0.01f);
    CHECK(h.viewer.workerConfig().sides.at(0).depth == 0);
}

TEST_CASE("a target spp set in the panel stops rendering there") {
    Harness h(smallSingleView());
    h.click("Budget");
    // The "+" button right of the field adds one pass (24) per click.
    const auto& controls = h.viewer.panel().controls();
    REQUIRE(controls.count("target spp") == 1);
    const float plusFraction = 1.0f - 0.5f * ImGui::GetFrameHeight() /
                                          (controls.at("target spp").max.x - controls.at("target spp").min.x);
    h.click("target spp", plusFraction);
    h.click("target spp", plusFraction);
    REQUIRE(h.viewer.workerConfig().targetSpp == 48);
    // On a fast run the worker may already rest at 24 spp between the two clicks: wait for the
    // rest that follows the second one. It must stop exactly at the target, not beyond.
    const auto& done = h.waitFor([](const WorkerSnapshot& s) { return s.idle && s.spp >= 48; });
    CHECK(done.spp == 48);
    CHECK(done.passes == 2);
    const uint64_t paths = done.paths;
    // Resting: more frames and time bring no new samples.
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    for (int i = 0; i < 5; ++i) h.frame();
    CHECK(h.viewer.shownSnapshot()->paths == paths);
    CHECK(h.viewer.shownSnapshot()->spp == 48);
}

TEST_CASE("a scene that fails to load leaves the old one rendering") {
    Harness h(smallSingleView());
    const auto before = h.viewer.workerConfig().scene;
    const auto dir = test::scratchDir("viewer-bad-scene");
    const auto bad = dir / "bad.obj";
    std::ofstream(bad) << "v 0 0 0\nf 1 2 3\n";  // indices out of range
    h.open(bad);
    CHECK(h.viewer.workerConfig().scene == before);
    CHECK(h.viewer.panel().message().find("bad.obj") != std::string::npos);
    h.open(dir / "missing.obj");
    CHECK(h.viewer.workerConfig().scene == before);
    CHECK(h.viewer.panel().message().find("missing.obj") != std::string::npos);
    // A file of no registered format (as dropped on the window): the format's one line.
    std::ofstream(dir / "model.fbx") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    h.open(dir / "model.fbx");
    CHECK(h.viewer.workerConfig().scene == before);
    CHECK(h.viewer.panel().message() ==
          "cannot open scene: " + (dir / "model.fbx").string() + ": unknown scene format '.fbx' (known: .obj, .gltf, .glb)");
    h.waitFor([](const WorkerSnapshot& s) { return s.spp >= 1 && s.error.empty(); });
}

TEST_CASE("a scene file of a registered extension, in any case, opens in place of the old one") {
    Harness h(smallSingleView());
    const auto before = h.viewer.workerConfig().scene;
    const auto dir = test::scratchDir("viewer-open-scene");
    std::ofstream(dir / "QUAD.OBJ") << "mtllib quad.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nusemtl lamp\nf 1 2 3 4\n";
    std::ofstream(dir / "quad.mtl") << "newmtl lamp\nKd 0.5 0.5 0.5\nKe 1 1 1\n";
    h.open(dir / "QUAD.OBJ");
    CHECK(h.viewer.workerConfig().scene != before);
    CHECK(h.viewer.workerConfig().scene->scene.summary().triangles == 2);
    CHECK(h.viewer.panel().message().rfind("opened " + (dir / "QUAD.OBJ").string() + " in ", 0) == 0);
    CHECK(h.viewer.panel().scenePath() == (dir / "QUAD.OBJ").string());
    h.waitFor([](const WorkerSnapshot& s) { return s.spp >= 1 && s.error.empty(); });
}

TEST_CASE("a scene opened with a file outside its folder is refused naming the option, and when allowed it says so") {
    const auto dir = test::scratchDir("viewer-outside-files");
    std::filesystem::create_directories(dir / "model");
    std::ofstream(dir / "model" / "s.obj") << "mtllib s.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\n"
                                              "usemtl m\nf 1/1 2/1 3/1 4/1\n";
    std::ofstream(dir / "model" / "s.mtl") << "newmtl m\nKd 1 1 1\nmap_Kd ../grey.tga\n";
    // An 8-bit grey 1x1 TGA.
    std::ofstream(dir / "grey.tga", std::ios::binary) << std::string("\0\0\3\0\0\0\0\0\0\0\0\0\1\0\1\0\x08\0\x80", 19);
    const std::string reference = (dir / "model" / "s.mtl").string() + ":3: map_Kd '../grey.tga'";
    const std::string folder = " the model's folder (" + std::filesystem::canonical(dir / "model").string() + ")";

    {  // one viewer (one ImGui context) at a time
        Harness refusing(smallSingleView());
        const auto before = refusing.viewer.workerConfig().scene;
        refusing.viewer.openScene(dir / "model" / "s.obj");
        refusing.settle();
        CHECK(refusing.viewer.workerConfig().scene == before);
        CHECK(refusing.viewer.panel().message() == "cannot open scene: " + reference + " resolves outside" +
                                                       folder + "; --allow-outside-files reads it");
    }
    ViewerSettings allowing = smallSingleView();
    allowing.files.allowOutsideFiles = true;
    Harness h(allowing);
    h.viewer.openScene(dir / "model" / "s.obj");
    h.settle();
    CHECK(h.viewer.workerConfig().scene->scene.summary().triangles == 2);
    const std::string message = h.viewer.panel().message();
    CHECK(message.rfind("opened " + (dir / "model" / "s.obj").string() + " in ", 0) == 0);
    CHECK(message.find(" (warnings on stderr: 1)") != std::string::npos);
    CHECK(h.viewer.panel().sceneNote() == "read 1 file outside the scene's folder, as --allow-outside-files lets it");
    CHECK(h.viewer.panel().sceneWarnings().find(reference + " is outside" + folder +
                                                 "; read as --allow-outside-files allows") != std::string::npos);
}

// A grey quad that emits nothing: lit only by its environment.
std::filesystem::path writeUnlitQuad(const std::filesystem::path& dir) {
    std::ofstream(dir / "grey.obj") << "mtllib grey.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nusemtl grey\nf 1 2 3 4\n";
    std::ofstream(dir / "grey.mtl") << "newmtl grey\nKd 0.5 0.5 0.5\n";
    return dir / "grey.obj";
}

TEST_CASE("an opened .exr becomes the environment map, and a bad one leaves the old one and says why") {
    const auto dir = test::scratchDir("viewer-environment-map");
    Harness h(smallSingleView(), writeUnlitQuad(dir));
    REQUIRE(h.viewer.workerConfig().scene->scene.lights().litByDefault());
    CHECK(describeEnvironment(h.viewer.workerConfig().scene->scene) == "default white sky: the scene has no light");
    writeImage(dir / "sky.exr", Image{4, 2, std::vector<glm::vec3>(8, glm::vec3(0.5f))});
    h.open(dir / "sky.exr");
    const auto relit = h.viewer.workerConfig().scene;
    CHECK(!relit->scene.lights().litByDefault());
    CHECK(relit->scene.lights().maxRadianceAtInfinity() == 0.5f);
    CHECK(relit->scenePath() == dir / "grey.obj");
    CHECK(h.viewer.panel().message() == "environment " + (dir / "sky.exr").string());
    CHECK(h.viewer.settings().environment.kind == Environment::Kind::Map);
    CHECK(describeEnvironment(relit->scene) == "map sky.exr (4x2), turned 0 degrees");

    writeImage(dir / "square.exr", Image{2, 2, std::vector<glm::vec3>(4, glm::vec3(1.0f))});
    h.open(dir / "square.exr");
    CHECK(h.viewer.workerConfig().scene == relit);
    CHECK(h.viewer.panel().message().rfind("cannot use environment map: " + (dir / "square.exr").string() +
                                           ": an environment map must be a latitude-longitude image", 0) == 0);
    CHECK(h.viewer.panel().message().find('\n') == std::string::npos);
    // The chosen environment lights the scenes opened after it.
    h.open(test::cornellScene());
    CHECK(h.viewer.workerConfig().scene->scene.lights().maxRadianceAtInfinity() == 0.5f);
    h.waitFor([](const WorkerSnapshot& s) { return s.spp >= 1 && s.error.empty(); });
}

TEST_CASE("the Light tab relights the open scene in place: same scene and BVH, accumulation restarts") {
    const auto dir = test::scratchDir("viewer-light-tab");
    Harness h(smallSingleView(), writeUnlitQuad(dir));
    const auto scene = h.viewer.workerConfig().scene;
    const RTCScene bvh = scene->scene.embreeScene();
    REQUIRE(scene->scene.lights().litByDefault());
    uint64_t generation = h.waitFor([](const WorkerSnapshot& s) { return s.spp >= 1; }).generation;
    const auto restarted = [&] {
        generation = h.waitFor([&](const WorkerSnapshot& s) { return s.generation > generation && s.spp >= 1; })
                         .generation;
    };
    h.click("Light");
    h.click("environment none");
    CHECK(h.viewer.settings().environment.kind == Environment::Kind::None);
    CHECK(h.viewer.workerConfig().scene == scene);
    CHECK(scene->scene.embreeScene() == bvh);
    CHECK(scene->scene.lights().size() == 0);
    CHECK(describeEnvironment(scene->scene) == "none");
    restarted();

    h.click("environment uniform");
    CHECK(scene->scene.lights().maxRadianceAtInfinity() == 1.0f);
    CHECK_FALSE(scene->scene.lights().litByDefault());
    restarted();
    // The intensity slider's right end: radiance 100 times the colour (white), beyond 1.
    h.click("environment intensity", 0.999f);
    CHECK(h.viewer.settings().environment.radiance == glm::vec3(100.0f));
    CHECK(scene->scene.lights().maxRadianceAtInfinity() == 100.0f);
    CHECK(describeEnvironment(scene->scene) == "uniform (100, 100, 100)");
    restarted();

    h.click("environment scene's");
    CHECK(scene->scene.lights().litByDefault());
    CHECK(describeEnvironment(scene->scene) == "default white sky: the scene has no light");
    CHECK(scene->scene.embreeScene() == bvh);
    CHECK(h.viewer.workerConfig().scene == scene);
    restarted();
}

TEST_CASE("the Light tab opens a listed map once, and turning it or going back to it reads nothing again") {
    const auto dir = test::scratchDir("viewer-light-maps");
    Harness h(smallSingleView(), writeUnlitQuad(dir));
    writeImage(dir / "warm.exr", Image{4, 2, std::vector<glm::vec3>(8, glm::vec3(2.0f, 1.0f, 0.5f))});
    writeImage(dir / "cool.exr", Image{8, 4, std::vector<glm::vec3>(32, glm::vec3(0.25f, 0.5f, 3.0f))});
    h.viewer.panel().setEnvironmentMapChoices({(dir / "warm.exr").string(), (dir / "cool.exr").string()});
    const auto& lights = h.viewer.workerConfig().scene->scene.lights();
    h.click("Light");
    h.click("environment map");  // no map read yet: the first one listed
    h.settle();
    REQUIRE(h.viewer.settings().environment.kind == Environment::Kind::Map);
    const auto map = h.viewer.settings().environment.map;
    CHECK(map->name() == (dir / "warm.exr").string());
    CHECK(lights.maxRadianceAtInfinity() == 2.0f);
    CHECK(h.viewer.panel().message() == "environment " + (dir / "warm.exr").string());

    h.click("environment rotation", 0.75f);  // -180..180 degrees: about 90
    const float degrees = h.viewer.settings().environment.rotationDegrees;
    CHECK(degrees > 45.0f);
    CHECK(degrees < 135.0f);
    CHECK(lights.environment().rotationDegrees == degrees);
    CHECK(lights.environment().map == map);  // the same map and distribution, turned
    CHECK(describeEnvironment(h.viewer.workerConfig().scene->scene).rfind("map warm.exr (4x2), turned ", 0) == 0);

    h.click("environment uniform");
    h.click("environment map");
    CHECK(!h.viewer.loading());  // the map read before: nothing to load
    CHECK(lights.environment().map == map);
    CHECK(lights.environment().rotationDegrees == degrees);

    h.click("studio lights");
    h.click("studio lights/cool.exr");
    h.settle();
    CHECK(lights.environment().map->name() == (dir / "cool.exr").string());
    CHECK(lights.maxRadianceAtInfinity() == 3.0f);
    CHECK(h.viewer.panel().environmentMapPath() == (dir / "cool.exr").string());
    h.waitFor([](const WorkerSnapshot& s) { return s.spp >= 1 && s.error.empty(); });
}

TEST_CASE("at 1280x720 the load summary, its warnings and the environment are in view above the controls") {
    const auto dir = test::scratchDir("viewer-layout");
    std::ofstream(dir / "s.obj") << "v 0 0 0\nv 1 0 0\nv 1 1 0\nusemtl red\nf 1 2 3\n";
    Harness h(smallSingleView(), dir / "s.obj");
    const auto& controls = h.viewer.panel().controls();
    REQUIRE(controls.count("warnings") == 1);
    REQUIRE(controls.count("Sampling") == 1);
    // In view without scrolling: above the bottom of a 720-pixel window, and above the tabs.
    CHECK(controls.at("warnings").max.y < controls.at("Sampling").min.y);
    CHECK(controls.at("Sampling").max.y < 720.0f);
    // Every tab's controls fit too (the harness's window is 720 high).
    h.click("Budget");
    CHECK(controls.at("target seconds").max.y < 720.0f);
}

TEST_CASE("the command line's environment lights every scene the viewer opens") {
    const auto dir = test::scratchDir("viewer-environment-options");
    ViewerSettings settings = smallSingleView();
    settings.environment.kind = Environment::Kind::None;
    Harness h(settings);
    h.open(writeUnlitQuad(dir));
    const auto opened = h.viewer.workerConfig().scene;
    CHECK(opened->scenePath() == dir / "grey.obj");
    CHECK(opened->scene.lights().size() == 0);
    CHECK(!opened->scene.lights().litByDefault());
    CHECK(describeEnvironment(opened->scene) == "none");
}

TEST_CASE("the panel shows the open scene's load summary and its warnings") {
    Harness h(smallSingleView());
    CHECK(h.viewer.panel().sceneSummary() == describeScene(*h.viewer.workerConfig().scene));
    CHECK(h.viewer.panel().sceneWarnings().empty());
    const auto dir = test::scratchDir("viewer-scene-report");
    std::ofstream(dir / "s.obj") << "v 0 0 0\nv 1 0 0\nv 1 1 0\nusemtl red\nf 1 2 3\n";
    h.open(dir / "s.obj");
    CHECK(h.viewer.panel().sceneSummary().find("s.obj: 1 triangles") != std::string::npos);
    CHECK(h.viewer.panel().sceneSummary().find(", 1 warning") != std::string::npos);
    CHECK(h.viewer.panel().sceneWarnings() ==
          "warning: " + (dir / "s.obj").string() + ":4: material 'red' is not defined; using grey Kd 0.8\n");
}

TEST_CASE("depth from epsilon sets every side's depth to K_eps and locks the sliders") {
    // The furnace (albedo 0.5, Le 1): the bound Le a^(K+1) / (1 - a) = 0.5^K is at most 1e-3
    // first at K = 10.
    ViewerSettings settings = smallSingleView();
    settings.epsilon = 1e-3f;
    Harness h(settings, test::sourceDir() / "assets/furnace/furnace.obj");
    h.click("depth from epsilon");
    REQUIRE(h.viewer.settings().depthFromEpsilon);
    CHECK(h.viewer.workerConfig().sides.at(0).depth == 10);
    CHECK(h.viewer.settings().halves[0].depth == 10);
    CHECK(h.viewer.settings().halves[1].depth == 10);
    h.click("depth K", 0.01f);  // disabled: the click changes nothing
    CHECK(h.viewer.workerConfig().sides.at(0).depth == 10);
    h.click("depth from epsilon");
    h.click("depth K", 0.01f);
    CHECK(h.viewer.workerConfig().sides.at(0).depth == 0);
}

TEST_CASE("depth from epsilon leaves the depth alone where no finite depth bounds the error") {
    ViewerSettings settings = smallSingleView();
    settings.single.depth = 3;
    Harness h(settings, test::testScene("cornell_point"));
    h.click("depth from epsilon");
    CHECK(h.viewer.workerConfig().sides.at(0).depth == 3);  // point lights: no radiance bound
}

TEST_CASE("a noise threshold stops every pixel, then rendering, and the mask view shows them done") {
    ViewerSettings settings = smallSingleView();
    settings.single = {SamplerKind::Strata24, 2};
    settings.noiseThreshold = 0.05f;
    settings.display.tonemap = Tonemap::Clamp;
    Harness h(settings, test::sourceDir() / "assets/furnace/furnace.obj");
    const auto& done = h.waitFor([](const WorkerSnapshot& s) { return s.idle && !s.preview; });
    REQUIRE(done.sides.size() == 1);
    CHECK(done.sides[0].activePixels == 0);
    CHECK(done.passes >= 4);  // AdaptiveSettings::minPasses
    const auto& flags = done.sides[0].image.errorAndDone;
    for (size_t p = 1; p < flags.size(); p += 2) REQUIRE(flags[p] == 1.0f);
    // Every pixel's relative error is under the threshold, and the mean is the exact furnace
    // value at depth 2, Le (1 + a + a^2) = 1.75, within the threshold's statistical slack.
    const auto& pixels = done.sides[0].image.meanAndCount;
    double sum = 0.0;
    for (size_t p = 0; p < flags.size() / 2; ++p) {
        CHECK(flags[2 * p] <= 0.05f);
        sum += pixels[4 * p];
    }
    CHECK(sum / static_cast<double>(flags.size() / 2) == doctest::Approx(1.75).epsilon(0.01));
    const uint64_t paths = done.paths;
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    for (int i = 0; i < 5; ++i) h.frame();
    CHECK(h.viewer.shownSnapshot()->paths == paths);  // resting

    // The furnace is white under the clamp tonemap; the mask view washes done pixels green.
    const auto colour = h.target.readRgb();
    h.viewer.settings().display.view = DisplayView::AdaptiveMask;
    h.frame();
    const auto mask = h.target.readRgb();
    const size_t at = 3 * (static_cast<size_t>(kHeight / 2) * kWidth + kWidth - 10);  // right of the panel
    CHECK(int(colour[at + 0]) == 255);
    CHECK(int(colour[at + 1]) == 255);
    CHECK(int(mask[at + 1]) > int(mask[at + 0]) + 60);
    CHECK(int(mask[at + 1]) > int(mask[at + 2]) + 60);
}

TEST_CASE("a target render time stops rendering once that much time is spent") {
    ViewerSettings settings = smallSingleView();
    settings.targetSeconds = 0.3f;
    Harness h(settings);
    const auto& done = h.waitFor([](const WorkerSnapshot& s) { return s.idle && !s.preview; });
    CHECK(done.renderSeconds >= 0.3);
    const uint64_t paths = done.paths;
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    for (int i = 0; i < 5; ++i) h.frame();
    CHECK(h.viewer.shownSnapshot()->paths == paths);
}

TEST_CASE("a slow step reaches the display band by band, before the step is complete") {
    // The furnace at depth 16 and full panel resolution on one thread: the first step (one path
    // for each of 480x720 pixels, 17 rays each) is rendered in bands, each shown when done.
    ViewerSettings settings = smallSingleView();
    settings.single.depth = 16;
    settings.resolutionScale = 1.0f;
    Harness h(settings, test::sourceDir() / "assets/furnace/furnace.obj");
    const auto& partial = h.waitFor([](const WorkerSnapshot& s) {
        if (s.spp != 0 || s.sides.empty()) return false;
        const auto& counts = s.sides[0].image.meanAndCount;
        return counts[3] == 1.0f && counts[counts.size() - 1] == 0.0f;  // top row done, bottom not
    });
    const DisplayImage& image = partial.sides[0].image;
    // Whole rows are done, from the top: every pixel has 0 or 1 samples, done ones above the rest.
    int lastDoneRow = -1, firstOpenRow = image.height;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const float count = image.meanAndCount[4 * (static_cast<size_t>(y) * image.width + x) + 3];
            REQUIRE((count == 0.0f || count == 1.0f));
            if (count == 1.0f) lastDoneRow = std::max(lastDoneRow, y);
            if (count == 0.0f) firstOpenRow = std::min(firstOpenRow, y);
        }
    }
    CHECK(lastDoneRow < firstOpenRow);
    CHECK(lastDoneRow >= 0);
}

TEST_CASE("the save buttons write the image as displayed (PNG) and its linear radiance (EXR)") {
    ViewerSettings settings = smallSingleView();
    settings.targetSpp = 24;
    Harness h(settings);
    const auto& done = h.waitFor([](const WorkerSnapshot& s) { return s.idle && s.spp == 24; });
    const DisplayImage& shown = done.sides.at(0).image;
    const auto dir = test::scratchDir("viewer-save");
    h.viewer.panel().setOutputStem((dir / "shot").string());
    h.click("Files");  // the tab starts hidden
    h.click("save PNG");
    h.click("save EXR");
    CHECK(h.viewer.panel().message().find("shot.exr") != std::string::npos);
    // The EXR holds the snapshot's means exactly (32-bit float channels).
    const Image exr = readExr(dir / "shot.exr");
    REQUIRE(exr.width == shown.width);
    REQUIRE(exr.height == shown.height);
    size_t differing = 0;
    for (size_t p = 0; p < exr.pixels.size(); ++p) {
        for (int c = 0; c < 3; ++c) differing += exr.pixels[p][c] != shown.meanAndCount[4 * p + static_cast<size_t>(c)];
    }
    CHECK(differing == 0);
    // The PNG is the render-size image, its size in the IHDR chunk (big-endian, bytes 16..23).
    std::ifstream png(dir / "shot.png", std::ios::binary);
    std::vector<unsigned char> header(24);
    png.read(reinterpret_cast<char*>(header.data()), 24);
    REQUIRE(png.gcount() == 24);
    const auto bigEndian = [&](size_t at) {
        return (header[at] << 24) | (header[at + 1] << 16) | (header[at + 2] << 8) | header[at + 3];
    };
    CHECK(header[1] == 'P');
    CHECK(bigEndian(16) == shown.width);
    CHECK(bigEndian(20) == shown.height);
}

TEST_CASE("at 1280x720 the panel lies beside the image: no panel pixel covers the Cornell box") {
    // One image (no divider or side labels drawn over it), a quarter of the image area's size.
    ViewerSettings settings;
    settings.split = false;
    settings.resolutionScale = 0.25f;
    settings.targetSpp = 24;
    Harness h(settings, test::cornellScene(), 1280, 720);
    h.waitFor([](const WorkerSnapshot& s) { return s.idle && s.spp == 24; });
    h.frame();
    const Viewport area = h.viewer.imageArea();
    CHECK(area.x == static_cast<int>(kPanelWidth));
    CHECK(area.width == 1280 - area.x);
    CHECK(area.height == 720);
    // The render has the image area's size (times the scale): nothing of it is cut off.
    const DisplayImage& image = h.viewer.shownSnapshot()->sides.at(0).image;
    REQUIRE(image.width == area.width / 4);
    REQUIRE(image.height == area.height / 4);

    // The box, from the render alone: the bounding rectangle of its lit pixels (outside the box
    // the camera sees nothing: no environment). All of it is in the image.
    int x0 = image.width, x1 = -1, y0 = image.height, y1 = -1;
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const float* p = &image.meanAndCount[4 * (static_cast<size_t>(y) * image.width + x)];
            if (p[0] + p[1] + p[2] <= 0.0f) continue;
            x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
        }
    }
    REQUIRE(x1 > x0);
    CHECK(x0 > 0);
    CHECK(x1 < image.width - 1);
    CHECK(y0 >= 0);
    CHECK(y1 <= image.height - 1);
    CHECK(x1 - x0 > image.width / 2);  // the box, not a speck

    // On screen, every pixel of the box's rectangle is the displayed image's pixel under it:
    // nothing of the panel is drawn over it.
    const std::vector<uint8_t> screen = h.target.readRgb();
    REQUIRE(h.viewer.displayedImage() != nullptr);
    const std::vector<uint8_t> shown = h.viewer.displayedImage()->readRgb();
    const int left = area.x + x0 * 4, right = area.x + (x1 + 1) * 4;
    size_t covered = 0, compared = 0;
    for (int sy = y0 * 4; sy < (y1 + 1) * 4; ++sy) {
        for (int sx = left; sx < right; ++sx) {
            const size_t s = 3 * (static_cast<size_t>(sy) * 1280 + sx);
            const size_t i = 3 * (static_cast<size_t>(sy / 4) * image.width + (sx - area.x) / 4);
            covered += screen[s] != shown[i] || screen[s + 1] != shown[i + 1] || screen[s + 2] != shown[i + 2];
            ++compared;
        }
    }
    CHECK(compared > 200000);
    CHECK(covered == 0);
    // And every control the panel drew is left of the box.
    for (const auto& [name, rect] : h.viewer.panel().controls()) {
        CAPTURE(name);
        CHECK(rect.max.x <= static_cast<float>(left));
    }
}

TEST_CASE("the panel folds to a strip and the image takes the window's width, and unfolded, it is back") {
    Harness h(smallSingleView());
    CHECK(h.viewer.imageArea().x == static_cast<int>(kPanelWidth));
    const int narrow = h.viewer.workerConfig().width;
    h.click("fold panel");
    CHECK(h.viewer.panel().folded());
    CHECK(h.viewer.imageArea().x == static_cast<int>(kFoldedPanelWidth));
    CHECK(h.viewer.imageArea().width == kWidth - static_cast<int>(kFoldedPanelWidth));
    CHECK(h.viewer.workerConfig().width > narrow);
    h.click("unfold panel");
    CHECK(!h.viewer.panel().folded());
    CHECK(h.viewer.imageArea().x == static_cast<int>(kPanelWidth));
    CHECK(h.viewer.workerConfig().width == narrow);
}

TEST_CASE("at 1280x720 the split view's plots and the load line fit in the window, the plots' labels inside them") {
    ViewerSettings settings;
    settings.resolutionScale = 0.125f;
    settings.threads = 1;
    settings.targetSpp = 72;  // three passes: two points a curve
    Harness h(settings, test::cornellScene(), 1280, 720);
    h.waitFor([](const WorkerSnapshot& s) { return s.idle && s.spp == 72; });
    h.frame();
    const auto& controls = h.viewer.panel().controls();
    REQUIRE(controls.count("error vs seconds") == 1);
    CHECK(controls.at("open scene...").max.y < controls.at("Sampling").min.y);
    CHECK(controls.at("change environment").max.y < controls.at("Sampling").min.y);
    CHECK(controls.at("error vs spp").min.y > controls.at("Sampling").max.y);
    CHECK(controls.at("error vs seconds").max.y <= 720.0f);
    CHECK(controls.at("error vs seconds").max.x <= kPanelWidth);
}

namespace {

// An N x N grid of quads: 2 N^2 triangles, a few MB of OBJ that take a while to parse and build.
std::filesystem::path writeGrid(const std::filesystem::path& dir, int n) {
    const auto path = dir / "grid.obj";
    std::ofstream obj(path);
    for (int j = 0; j <= n; ++j) {
        for (int i = 0; i <= n; ++i) obj << "v " << i << ' ' << j << " 0\n";
    }
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            const int a = j * (n + 1) + i + 1;
            obj << "f " << a << ' ' << a + 1 << ' ' << a + n + 2 << ' ' << a + n + 1 << '\n';
        }
    }
    return path;
}

}  // namespace

TEST_CASE("viewer threads: a large scene loads off the UI thread while frames go on and the old scene renders") {
    const auto dir = test::scratchDir("viewer-async-load");
    const auto grid = writeGrid(dir, 400);
    Harness h(smallSingleView());
    const auto before = h.viewer.workerConfig().scene;
    const uint64_t generation = h.waitFor([](const WorkerSnapshot& s) { return s.spp >= 1; }).generation;
    h.viewer.openScene(grid);
    CHECK(h.viewer.loading());  // returned before the load ended
    int frames = 0;
    bool progressShown = false, oldSceneKept = true;
    while (h.viewer.loading()) {
        REQUIRE_MESSAGE(frames < 60000, "the load never ended");
        h.frame();
        ++frames;
        progressShown |= h.viewer.panel().controls().count("cancel load") == 1;
        if (!h.viewer.loading()) break;  // this frame may have shown the new scene
        // The old scene is configured, and rendering it goes on without a restart.
        oldSceneKept &= h.viewer.workerConfig().scene == before && h.viewer.shownSnapshot()->generation == generation;
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    }
    h.frame();
    INFO(frames << " UI frames during the load");
    CHECK(frames >= 3);
    CHECK(progressShown);
    CHECK(oldSceneKept);
    CHECK(h.viewer.workerConfig().scene->scene.summary().triangles == 2 * 400 * 400);
    CHECK(h.viewer.panel().message().rfind("opened " + grid.string() + " in ", 0) == 0);
    h.waitFor([](const WorkerSnapshot& s) { return s.spp >= 1 && s.error.empty(); });
}

TEST_CASE("viewer threads: the load line's cancel button stops a load and keeps the open scene") {
    const auto dir = test::scratchDir("viewer-cancel-load");
    const auto grid = writeGrid(dir, 400);
    Harness h(smallSingleView());
    const auto before = h.viewer.workerConfig().scene;
    const std::string summary = h.viewer.panel().sceneSummary();
    h.viewer.openScene(grid);
    h.frame();  // draws the load line with its button
    h.click("cancel load");
    h.settle();
    CHECK(h.viewer.workerConfig().scene == before);
    CHECK(h.viewer.panel().sceneSummary() == summary);
    CHECK(h.viewer.panel().message() == "cancelled loading " + grid.string() + "; the open scene stays");
    h.waitFor([](const WorkerSnapshot& s) { return s.spp >= 1 && s.error.empty(); });
}

TEST_CASE("the file dialog lists scene files and folders, goes up and into them, and opens the scene chosen") {
    const auto dir = test::scratchDir("viewer-file-dialog");
    std::filesystem::create_directory(dir / "sub");
    std::ofstream(dir / "sub/QUAD.OBJ") << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n";
    std::ofstream(dir / "sub/notes.txt") << "not a scene\n";
    Harness h(smallSingleView());
    h.viewer.panel().setScenePath((dir / "sub/gone.obj").string());  // the nearest folder: sub
    h.click("open scene...");
    const FileDialog& dialog = h.viewer.panel().fileDialog();
    REQUIRE(dialog.isOpen());
    CHECK(dialog.folder() == dir / "sub");
    const auto& controls = h.viewer.panel().controls();
    CHECK(controls.count("dialog/QUAD.OBJ") == 1);
    CHECK(controls.count("dialog/notes.txt") == 0);
    h.doubleClick("dialog/..");
    CHECK(dialog.folder() == dir);
    h.click("dialog/sub");  // selected: its name in the path field
    CHECK(dialog.folder() == dir);
    h.click("dialog open");
    CHECK(dialog.folder() == dir / "sub");
    h.click("dialog/QUAD.OBJ");
    CHECK(dialog.isOpen());
    h.click("dialog open");
    CHECK(!dialog.isOpen());
    h.settle();
    CHECK(h.viewer.workerConfig().scene->scenePath() == dir / "sub/QUAD.OBJ");
    CHECK(h.viewer.workerConfig().scene->scene.summary().triangles == 2);
    CHECK(h.viewer.panel().scenePath() == (dir / "sub/QUAD.OBJ").string());

    // It opens again at that scene; a double click on a file opens it, Cancel opens nothing.
    h.click("open scene...");
    REQUIRE(dialog.isOpen());
    CHECK(dialog.folder() == dir / "sub");
    const auto opened = h.viewer.workerConfig().scene;
    h.doubleClick("dialog/QUAD.OBJ");
    CHECK(!dialog.isOpen());
    h.settle();
    CHECK(h.viewer.workerConfig().scene != opened);
    CHECK(h.viewer.workerConfig().scene->scenePath() == dir / "sub/QUAD.OBJ");
    h.click("open scene...");
    REQUIRE(dialog.isOpen());
    h.click("dialog cancel");
    CHECK(!dialog.isOpen());
    CHECK(!h.viewer.loading());
}

TEST_CASE("the environment line opens the Light tab, whose map comes from the file dialog and turns live") {
    const auto dir = test::scratchDir("viewer-light-dialog");
    Harness h(smallSingleView(), writeUnlitQuad(dir));
    writeImage(dir / "warm.exr", Image{4, 2, std::vector<glm::vec3>(8, glm::vec3(2.0f, 1.0f, 0.5f))});
    h.viewer.panel().setEnvironmentMapChoices({});  // only the dialog offers maps
    const auto& scene = h.viewer.workerConfig().scene->scene;
    CHECK(h.viewer.panel().controls().count("environment none") == 0);  // the Sampling tab shows
    h.click("change environment");
    h.click("environment none");
    CHECK(h.viewer.settings().environment.kind == Environment::Kind::None);
    CHECK(describeEnvironment(scene) == "none");

    h.click("environment map");  // no map yet: the file controls show
    CHECK(!h.viewer.loading());
    h.viewer.panel().setEnvironmentMapPath((dir / "warm.exr").string());
    h.click("browse maps");
    const FileDialog& dialog = h.viewer.panel().fileDialog();
    REQUIRE(dialog.isOpen());
    CHECK(dialog.folder() == dir);
    CHECK(dialog.entries() == std::vector<FolderEntry>{{"warm.exr", false}});
    h.click("dialog open");  // the field holds warm.exr
    h.settle();
    CHECK(h.viewer.settings().environment.kind == Environment::Kind::Map);
    CHECK(scene.lights().environment().map->name() == (dir / "warm.exr").string());
    CHECK(scene.lights().maxRadianceAtInfinity() == 2.0f);
    h.click("environment rotation", 0.25f);  // -180..180 degrees: about -90
    CHECK(scene.lights().environment().rotationDegrees < -45.0f);
    CHECK(describeEnvironment(scene).rfind("map warm.exr (4x2), turned -", 0) == 0);
}

TEST_CASE("the loader's note has its line in the load summary, above the controls") {
    Harness h(smallSingleView());
    h.viewer.panel().setSceneNote("read 1 file outside the scene's folder, as --allow-outside-files lets it");
    h.frame();
    const auto& controls = h.viewer.panel().controls();
    REQUIRE(controls.count("scene note") == 1);
    CHECK(controls.at("scene note").min.y > controls.at("open scene...").max.y);
    CHECK(controls.at("scene note").max.y < controls.at("change environment").min.y);
}

TEST_CASE("the display's exposure comes from the first whole image and then stays, and the backdrop reaches the worker") {
    ViewerSettings settings = smallSingleView();
    settings.autoExposure = true;
    settings.backdrop = {BackdropSetting::Kind::Colour, glm::vec3(0.5f)};
    settings.targetSpp = 48;
    {
        Harness h(settings);
        CHECK(h.viewer.workerConfig().backdrop == settings.backdrop);
        const uint64_t generation =
            h.waitFor([](const WorkerSnapshot& s) { return !s.preview && s.spp >= 1; }).generation;
        const float metered = h.viewer.settings().display.exposure;
        CHECK(metered != 0.0f);
        // Taken from a one-path image, within a quarter stop of the exposure of the finished one.
        const auto& done = h.waitFor([](const WorkerSnapshot& s) { return s.idle && s.spp == 48; });
        CHECK(done.generation == generation);
        CHECK(std::abs(metered - autoExposure(done.sides.at(0).image.radiance())) < 0.25f);
        CHECK(h.viewer.settings().display.exposure == metered);
    }
    // Given (not automatic), the exposure is left alone.
    settings.autoExposure = false;
    settings.display.exposure = 1.5f;
    Harness fixed(settings);
    fixed.waitFor([](const WorkerSnapshot& s) { return !s.preview && s.spp >= 1; });
    CHECK(fixed.viewer.settings().display.exposure == 1.5f);
}

TEST_CASE("ctrl + click on the image focuses the lens on the surface there, and the lens reaches the worker") {
    Harness h(smallSingleView());
    ViewerSettings& settings = h.viewer.settings();
    CHECK(settings.apertureRadius == 0.0f);  // the Cornell box's camera is a pinhole
    settings.apertureRadius = 5.0f;
    h.frame();
    CHECK(h.viewer.workerConfig().pose.apertureRadius == 5.0f);
    // A click a fifth of the way down the image's middle column: the pinhole ray through that
    // pixel's centre finds the box's far side there, at its depth along the view.
    const Viewport& area = h.viewer.imageArea();
    const WorkerConfig& config = h.viewer.workerConfig();
    CameraPose pinhole = config.pose;
    pinhole.apertureRadius = 0.0f;
    const Ray ray = Camera(pinhole, config.width, config.height)
                        .generateRay(config.width / 2, config.height / 5, glm::vec2(0.5f));
    const auto hit = config.scene->scene.intersect(ray);
    REQUIRE(hit);
    const float depth = hit->t * glm::dot(ray.direction, glm::normalize(pinhole.lookAt - pinhole.position));
    ImGuiIO& io = ImGui::GetIO();
    io.MousePos = ImVec2(static_cast<float>(area.x) + 0.5f * static_cast<float>(area.width) + 1.0f,
                         (static_cast<float>(config.height / 5) + 0.5f) / static_cast<float>(config.height) *
                             static_cast<float>(area.height));
    io.KeyCtrl = true;
    h.frame();
    io.MouseDown[0] = true;
    h.frame();
    io.MouseDown[0] = false;
    io.KeyCtrl = false;
    h.frame();
    CHECK(settings.focusDistance == doctest::Approx(depth).epsilon(1e-4));
    CHECK(h.viewer.workerConfig().pose.focusDistance == settings.focusDistance);
    // Without ctrl a click focuses nothing.
    settings.focusDistance = 0.0f;
    io.MouseDown[0] = true;
    h.frame();
    io.MouseDown[0] = false;
    h.frame();
    CHECK(settings.focusDistance == 0.0f);
}
