// The Blender side of `strata bench --vs-cycles` without Blender: the parameters the script reads,
// the settings that make Cycles render what Strata renders, and the render time it prints.
#include <doctest/doctest.h>

#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>

#include "bench/bench_process.h"
#include "bench/cycles_script.h"
#include "test_support.h"
#include "util/error.h"

using namespace strata;

namespace {
CyclesJob cornellJob() {
    CyclesJob job;
    job.model = "scene.obj";
    job.scale = 1.0 / 559.2;
    job.materials = {{"white", {0.725f, 0.71f, 0.68f}, {0.0f, 0.0f, 0.0f}, {}, 1.0f},
                     {"light", {0.0f, 0.0f, 0.0f}, {17.0f, 12.0f, 4.0f}, {}, 1.0f}};
    job.pose = {{278.0f, 273.0f, -800.0f}, {278.0f, 273.0f, 0.0f}, {0.0f, 1.0f, 0.0f}, 39.3076f};
    job.spp = 72;
    job.maxBounces = cyclesMaxBounces(9);
    job.threads = 2;
    job.seed = 7;
    job.out = "out.exr";
    return job;
}
}  // namespace

TEST_CASE("cycles script: the parameters hold the job, by the names the script reads") {
    const auto parameters = nlohmann::json::parse(cyclesParameters(cornellJob()));
    CHECK(parameters["model"] == std::filesystem::absolute("scene.obj").string());
    CHECK(parameters["out"] == std::filesystem::absolute("out.exr").string());
    CHECK(parameters["scale"].get<double>() == doctest::Approx(1.0 / 559.2));
    CHECK(parameters["materials"]["light"]["ke"][0].get<double>() == doctest::Approx(17.0));
    CHECK(parameters["materials"]["white"]["kd"][2].get<double>() == doctest::Approx(0.68));
    CHECK(parameters["position"][2].get<double>() == doctest::Approx(-800.0));
    CHECK(parameters["look_at"][0].get<double>() == doctest::Approx(278.0));
    CHECK(parameters["up"][1].get<double>() == doctest::Approx(1.0));
    CHECK(parameters["fov_y"].get<double>() == doctest::Approx(39.3076));
    CHECK(parameters["max_bounces"] == 8);
    CHECK(parameters["spp"] == 72);
    CHECK(parameters["threads"] == 2);
    CHECK(parameters["seed"] == 7);
    CHECK(parameters["sky"] == nlohmann::json::array({0.0, 0.0, 0.0}));  // the box: a black world
    CyclesJob underSky = cornellJob();
    underSky.sky = {0.5f, 1.0f, 2.0f};
    CHECK(nlohmann::json::parse(cyclesParameters(underSky))["sky"] == nlohmann::json::array({0.5, 1.0, 2.0}));
    CHECK(parameters["environment"].is_null());
    CHECK(parameters["materials"]["white"]["texture"] == "");
    CHECK(parameters["materials"]["white"]["ks"] == nlohmann::json::array({0.0, 0.0, 0.0}));

    // A textured material names its linear EXR; a glossy one its Ks and roughness; a map its file
    // and the frame's rows (the frame applied to a direction is row . direction).
    CyclesJob real = cornellJob();
    real.colourTextures["white"] = "colour-0.exr";
    real.materials[0].specular = glm::vec3(1.0f);
    real.materials[0].roughness = 0.3f;
    real.environmentMap = "sky.exr";
    real.environmentFrame = glm::mat3(glm::vec3(0.0f, -1.0f, 0.0f), glm::vec3(0.0f, 0.0f, 1.0f),
                                      glm::vec3(-1.0f, 0.0f, 0.0f));  // columns
    const auto realParameters = nlohmann::json::parse(cyclesParameters(real));
    CHECK(realParameters["materials"]["white"]["texture"] == std::filesystem::absolute("colour-0.exr").string());
    CHECK(realParameters["materials"]["light"]["texture"] == "");
    CHECK(realParameters["materials"]["white"]["ks"] == nlohmann::json::array({1.0, 1.0, 1.0}));
    CHECK(realParameters["materials"]["white"]["roughness"].get<double>() == doctest::Approx(0.3));
    CHECK(realParameters["environment"]["file"] == std::filesystem::absolute("sky.exr").string());
    CHECK(realParameters["environment"]["frame"][0] == nlohmann::json::array({0.0, 0.0, -1.0}));
    CHECK(realParameters["environment"]["frame"][1] == nlohmann::json::array({-1.0, 0.0, 0.0}));
    CHECK(realParameters["environment"]["frame"][2] == nlohmann::json::array({0.0, 1.0, 0.0}));

    // Every parameter is read by the script, and the script reads no other.
    const std::string script(cyclesScript());
    for (const auto& [key, value] : parameters.items()) {
        CHECK_MESSAGE(script.find("params[\"" + key + "\"]") != std::string::npos, key);
    }
    for (size_t at = script.find("params[\""); at != std::string::npos; at = script.find("params[\"", at + 1)) {
        const size_t start = at + 8;
        const std::string key = script.substr(start, script.find('"', start) - start);
        CHECK_MESSAGE(parameters.contains(key), key);
    }
}

TEST_CASE("cycles script: it sets what makes Cycles' image Strata's") {
    const std::string script(cyclesScript());
    for (const char* setting : {
             "read_factory_settings(use_empty=True)",         // no cube, lamp or grey world
             "forward_axis='Y', up_axis='Z'",                 // OBJ axes as they are
             "root.matrix_world = frame @ root.matrix_world", // the scene turned into the map's frame
             "colorspace_settings.name = 'Linear'",           // the EXRs hold linear values
             "interpolation = 'Linear'", "extension = 'REPEAT'",  // Strata's texture lookup
             "interpolation = 'Closest'",                      // Strata's map: constant texels
             "distribution = 'GGX'",
             "global_scale=scale",                            // unit size for the light sampler
             "geometry.outputs[\"Backfacing\"]",              // one-sided emission
             "scene.world = world",                           // black, or the job's sky
             "sensor_fit = 'VERTICAL'",                       // fov_y is the vertical angle
             "use_adaptive_sampling = False", "use_denoising = False",
             "sample_clamp_indirect = 0.0", "blur_glossy = 0.0", "light_sampling_threshold = 0.0",
             "\"diffuse_bounces\", \"glossy_bounces\"",        // no per-kind caps below max_bounces
             "pixel_filter_type = 'BOX'", "filter_width = 1.0",
             "view_transform = 'Standard'", "dither_intensity = 0.0", "color_depth = '32'",
             "threads_mode = 'FIXED'"}) {
        CHECK_MESSAGE(script.find(setting) != std::string::npos, setting);
    }
    // The time printed is render() alone: taken just around it.
    const size_t render = script.find("bpy.ops.render.render()");
    REQUIRE(render != std::string::npos);
    CHECK(script.rfind("start = time.perf_counter()", render) != std::string::npos);
    CHECK(script.find("seconds = time.perf_counter() - start", render) != std::string::npos);
}

TEST_CASE("cycles script: it is valid Python") {
    const auto dir = test::scratchDir("cycles-script");
    {
        std::ofstream(dir / "cycles_render.py") << cyclesScript();
    }
    const auto result = test::runCommand("python3 -c 'import ast, sys; ast.parse(open(sys.argv[1]).read())' " +
                                         (dir / "cycles_render.py").string());
    CHECK_MESSAGE(result.exitCode == 0, result.err);
}

TEST_CASE("cycles script: the command line runs it in an empty Blender, failing on a Python error") {
    const auto argv = cyclesCommandLine("dir/cycles_render.py", "dir/p.json");
    const std::vector<std::string> expected = {"blender", "-b", "--factory-startup", "--python-exit-code", "1",
                                               "--python", "dir/cycles_render.py", "--", "dir/p.json"};
    CHECK(argv == expected);
}

TEST_CASE("cycles script: depth K is max_bounces K - 1, and depth 0 is refused") {
    CHECK(cyclesMaxBounces(9) == 8);
    CHECK(cyclesMaxBounces(1) == 0);
    CHECK_THROWS_AS(cyclesMaxBounces(0), Error);
}

TEST_CASE("cycles script: the unit scale is one over the bounding box's largest side") {
    MeshData mesh;
    CHECK(cyclesUnitScale(mesh) == 1.0);
    mesh.positions = {{0.0f, 0.0f, 0.0f}, {556.0f, 548.8f, 0.0f}, {-3.2f, 10.0f, 559.2f}};
    CHECK(cyclesUnitScale(mesh) == doctest::Approx(1.0 / 559.2));
    mesh.positions = {{1.0f, 2.0f, 3.0f}};
    CHECK(cyclesUnitScale(mesh) == 1.0);
}

TEST_CASE("cycles script: the render time is read from Blender's output") {
    const std::string log =
        "Blender 3.4.1\nFra:1 Mem:12.02M | Time:00:08.44 | Sample 16/16\n"
        "cycles render seconds: 8.458229\n\nBlender quit\n";
    CHECK(*parseCyclesSeconds(log) == doctest::Approx(8.458229));
    CHECK(*parseCyclesSeconds("cycles render seconds: 2.5\r\n") == doctest::Approx(2.5));
    CHECK_FALSE(parseCyclesSeconds("Blender 3.4.1\nBlender quit\n"));
    CHECK_FALSE(parseCyclesSeconds("cycles render seconds: \n"));
    CHECK_FALSE(parseCyclesSeconds("cycles render seconds: 3.5s\n"));
    CHECK_FALSE(parseCyclesSeconds("cycles render seconds: -1\n"));
    CHECK_FALSE(parseCyclesSeconds("cycles render seconds: nan\n"));
    CHECK_FALSE(parseCyclesSeconds("  cycles render seconds: 1.0\n"));
}

TEST_CASE("cycles script: a program is found on PATH only when it is there") {
    const char* saved = std::getenv("PATH");
    const std::string path = saved ? saved : "";
    const auto dir = test::scratchDir("on-path");
    {
        std::ofstream(dir / "tool") << "#!/bin/sh\n";
        std::ofstream(dir / "plain") << "not executable\n";
    }
    std::filesystem::permissions(dir / "tool", std::filesystem::perms::owner_all);
    setenv("PATH", ("/nonexistent:" + dir.string()).c_str(), 1);
    CHECK(onPath("tool"));
    CHECK_FALSE(onPath("plain"));
    CHECK_FALSE(onPath("no-such-program"));
    setenv("PATH", "/nonexistent", 1);
    CHECK_FALSE(onPath("tool"));
    setenv("PATH", path.c_str(), 1);
}
