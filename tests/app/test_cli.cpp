#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <set>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stb_image.h>

#include "film/backdrop.h"
#include "io/image_io.h"
#include "io/tonemap.h"
#include "test_support.h"

using namespace strata;

namespace {
std::string furnace() { return (test::sourceDir() / "assets/furnace/furnace.obj").string(); }

}  // namespace

TEST_CASE("cli: the furnace at depth 3, 240 spp reports a mean within 1% of 1.875") {
    const auto result = test::runStrata("render " + furnace() + " --depth 3 --spp 240 --json");
    REQUIRE(result.exitCode == 0);
    const auto report = nlohmann::json::parse(result.out);
    for (const char* key : {"seconds", "spp", "paths", "rays", "paths_per_second", "rays_per_second",
                            "mean_rgb", "nonfinite_samples"}) {
        CHECK(report.contains(key));
    }
    CHECK(report["spp"] == 240);
    CHECK(report["nonfinite_samples"] == 0);
    CHECK(report["paths"] == 240 * 64 * 64);
    CHECK(std::abs(report["mean_rgb"][0].get<double>() - 1.875) < 0.01 * 1.875);
}

TEST_CASE("cli: --threads 1 and --threads 2 write bit-identical images") {
    const auto dir = test::scratchDir("cli-threads");
    for (const char* threads : {"1", "2"}) {
        const auto result = test::runStrata("render " + test::cornellScene().string() +
                                            " --width 48 --height 32 --spp 48 --depth 4 --threads " +
                                            threads + " --out " + (dir / (std::string(threads) + ".pfm")).string());
        REQUIRE(result.exitCode == 0);
    }
    CHECK(test::fileBytes(dir / "1.pfm") == test::fileBytes(dir / "2.pfm"));
}

TEST_CASE("cli: --version prints the version, --help one line per command") {
    const auto version = test::runStrata("--version");
    REQUIRE(version.exitCode == 0);
    CHECK(version.out.rfind("strata ", 0) == 0);
    CHECK(test::lineCount(version.out) == 1);
    const auto help = test::runStrata("--help");
    REQUIRE(help.exitCode == 0);
    for (const char* command : {"bench", "render", "samples", "view"}) {
        CHECK_MESSAGE(help.out.find(std::string("\n  ") + command + " ") != std::string::npos, help.out);
    }
}

TEST_CASE("cli: the program loads its libraries from the system, not from the folder it is run in") {
    const auto dir = test::scratchDir("cli-decoys");
    REQUIRE(test::plantLibraryDecoys(STRATA_BINARY, dir) >= 5);
    const auto result = test::runCommand("cd " + dir.string() + " && " + STRATA_BINARY + " render " + furnace() +
                                         " --width 8 --height 8 --spp 24 --depth 1 --json");
    REQUIRE_MESSAGE(result.exitCode == 0, result.err);
    CHECK(nlohmann::json::parse(result.out)["mean_rgb"][0].get<double>() > 0.0);
}

TEST_CASE("cli: render with no scene renders the bundled Cornell box, from the source tree in a build") {
    const auto result = test::runStrata("render --width 8 --height 8 --spp 24 --json");
    REQUIRE_MESSAGE(result.exitCode == 0, result.err);
    CHECK(nlohmann::json::parse(result.out)["scene"] == test::cornellScene().string());
}

TEST_CASE("cli: bad options and bad files give one line naming them and a non-zero exit") {
    const auto dir = test::scratchDir("cli-bad");
    std::ofstream(dir / "bad.obj") << "v 0 0 0\nv 1 0 zero\n";
    std::ofstream(dir / "good.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    std::ofstream(dir / "bad-camera.json") << "{\"position\": [0,0,0],\n \"look_at\": }";
    struct Case {
        std::string arguments;
        std::string mentions;
    };
    const std::vector<Case> cases = {
        {"render " + furnace() + " --spp 25", "--spp"},
        {"render " + furnace() + " --spp 0", "--spp"},
        {"render " + furnace() + " --spp lots", "--spp"},
        {"render " + furnace() + " --sampler best", "--sampler"},
        {"render " + furnace() + " --depth -1", "--depth"},
        {"render " + furnace() + " --threads 100000", "--threads"},
        {"render " + furnace() + " --width 0", "--width"},
        {"render " + furnace() + " --out image.bmp", "image.bmp"},
        {"render " + furnace() + " --tonemap filmic", "--tonemap"},
        {"render " + furnace() + " --bogus", "--bogus"},
        {"render " + (dir / "absent.obj").string(), "absent.obj"},
        {"render " + (dir / "bad.obj").string(), "bad.obj:2"},
        {"render " + (dir / "good.obj").string() + " --camera " + (dir / "bad-camera.json").string(), "bad-camera.json"},
        {"render " + (dir / "good.obj").string() + " --camera " + (dir / "nope.json").string(), "nope.json"},
        {"samples --passes 0", "--passes"},
        {"samples --sampler nope", "--sampler"},
        {"frobnicate", "frobnicate"},
    };
    for (const auto& c : cases) {
        const auto result = test::runStrata(c.arguments);
        INFO("strata " << c.arguments << "\n-> exit " << result.exitCode << ", stderr: " << result.err);
        CHECK(result.exitCode != 0);
        CHECK(result.exitCode < 128);  // an exit, not a crash
        CHECK(test::lineCount(result.err) == 1);
        CHECK(result.err.find(c.mentions) != std::string::npos);
    }
}

TEST_CASE("cli: a failed render leaves an existing output file untouched") {
    const auto dir = test::scratchDir("cli-clobber");
    const auto out = dir / "keep.png";
    std::ofstream(out) << "precious";
    const auto result = test::runStrata("render " + (dir / "absent.obj").string() + " --out " + out.string());
    CHECK(result.exitCode != 0);
    CHECK(test::fileBytes(out) == "precious");
}

TEST_CASE("cli: samples prints one CSV line per sample, every stratum once per pass and bounce") {
    const auto result = test::runStrata("samples --sampler strata24 --passes 3 --depth 2 --seed 5");
    REQUIRE(result.exitCode == 0);
    std::istringstream in(result.out);
    std::string line;
    std::getline(in, line);
    CHECK(line == "pass,path,bounce,stratum,x,y,z");
    std::map<std::pair<int, int>, std::set<int>> strataByPassAndBounce;
    int rows = 0;
    while (std::getline(in, line)) {
        int pass, path, bounce, stratum;
        double x, y, z;
        REQUIRE(std::sscanf(line.c_str(), "%d,%d,%d,%d,%lf,%lf,%lf", &pass, &path, &bounce, &stratum,
                            &x, &y, &z) == 7);
        CHECK(std::abs(x * x + y * y + z * z - 1.0) < 1e-6);
        CHECK(z >= 0.0);
        strataByPassAndBounce[{pass, bounce}].insert(stratum);
        ++rows;
    }
    CHECK(rows == 3 * 24 * 2);
    for (const auto& [key, strata] : strataByPassAndBounce) CHECK(strata.size() == 24);

    const auto uniform = test::runStrata("samples --sampler uniform --passes 1");
    REQUIRE(uniform.exitCode == 0);
    CHECK(uniform.out.find(",-1,") != std::string::npos);
}

TEST_CASE("cli: a scene that cannot be lit renders black at once and says why") {
    const auto dir = test::scratchDir("cli-dark");
    std::ofstream(dir / "dark.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    const auto result = test::runStrata("render " + (dir / "dark.obj").string() + " --env none --spp 48 --json");
    REQUIRE(result.exitCode == 0);
    const auto report = nlohmann::json::parse(result.out);
    CHECK(report["black_early_out"] == true);
    CHECK(report["paths"] == 0);
    CHECK(result.err.find("no emitter") != std::string::npos);
    const auto forced = test::runStrata("render " + (dir / "dark.obj").string() +
                                        " --env none --spp 24 --no-early-out --width 8 --height 8 --json");
    REQUIRE(forced.exitCode == 0);
    CHECK(nlohmann::json::parse(forced.out)["paths"] == 24 * 64);
}

TEST_CASE("cli: a scene with no light is lit by a white sky, and says so, and --env-color sets its radiance") {
    const auto dir = test::scratchDir("cli-default-sky");
    // A square of albedo 0.5 filling the view: under a sky of 1 every pixel reads 0.5.
    std::ofstream(dir / "grey.obj") << "mtllib grey.mtl\nusemtl grey\nv -9 -9 0\nv 9 -9 0\nv 9 9 0\nv -9 9 0\nf 1 2 3 4\n";
    std::ofstream(dir / "grey.mtl") << "newmtl grey\nKd 0.5 0.5 0.5\n";
    std::ofstream(dir / "grey.json") << R"({"position":[0,0,5],"look_at":[0,0,0],"up":[0,1,0],"fov_y":20})";
    // Cosine sampling alone is exact here; next-event estimation's MIS would add noise.
    const std::string render = "render " + (dir / "grey.obj").string() +
                               " --sampler cosine --no-nee --depth 2 --spp 24 --width 4 --height 4 --json";
    const auto lit = test::runStrata(render);
    REQUIRE(lit.exitCode == 0);
    CHECK(lit.err.find("note: the scene has no light; lighting it with a uniform white environment "
                       "(--env none for black)") != std::string::npos);
    const auto mean = nlohmann::json::parse(lit.out)["mean_rgb"];
    CHECK(mean[1].get<double>() == doctest::Approx(0.5).epsilon(1e-6));
    const auto coloured = test::runStrata(render + " --env-color 2 4 0");
    REQUIRE(coloured.exitCode == 0);
    CHECK(coloured.err.find("note: the scene has no light") == std::string::npos);
    CHECK(nlohmann::json::parse(coloured.out)["mean_rgb"][1].get<double>() == doctest::Approx(2.0).epsilon(1e-6));
}

TEST_CASE("cli: the PNG is filmic at the first pass's exposure by default, --tonemap clamp and --exposure fix it") {
    const auto dir = test::scratchDir("cli-display");
    // The grey square of albedo 0.5 filling the view under the default sky: every pixel reads 0.5.
    std::ofstream(dir / "grey.obj") << "mtllib grey.mtl\nusemtl grey\nv -9 -9 0\nv 9 -9 0\nv 9 9 0\nv -9 9 0\nf 1 2 3 4\n";
    std::ofstream(dir / "grey.mtl") << "newmtl grey\nKd 0.5 0.5 0.5\n";
    std::ofstream(dir / "grey.json") << R"({"position":[0,0,5],"look_at":[0,0,0],"up":[0,1,0],"fov_y":20})";
    const std::string render = "render " + (dir / "grey.obj").string() + " --sampler cosine --no-nee --depth 2 "
                               "--spp 24 --width 4 --height 4 --json --out " + (dir / "out.png").string();
    const auto pngByte = [&](const std::string& options) {
        const auto result = test::runStrata(render + options);
        REQUIRE_MESSAGE(result.exitCode == 0, result.err);
        int width = 0, height = 0, channels = 0;
        unsigned char* pixels = stbi_load((dir / "out.png").c_str(), &width, &height, &channels, 3);
        REQUIRE(pixels != nullptr);
        const int byte = pixels[0];
        for (int i = 0; i < 3 * width * height; ++i) CHECK(pixels[i] == byte);
        stbi_image_free(pixels);
        return std::pair{byte, nlohmann::json::parse(result.out)};
    };
    // The key 0.18 for a luminance of 0.5, through ACES (Narkowicz's fit).
    const float stops = std::log2(0.18f / 0.5f);
    const auto [filmic, report] = pngByte("");
    CHECK(report["tonemap"] == "aces");
    CHECK(report["exposure"].get<double>() == doctest::Approx(stops).epsilon(1e-4));
    CHECK(filmic == toByte(encodeSrgb(applyTonemap(glm::vec3(0.5f), stops, Tonemap::Aces).x)));
    // Today's display: the linear radiance clamped, exposure 0.
    const auto [clamped, clampReport] = pngByte(" --tonemap clamp");
    CHECK(clamped == toByte(encodeSrgb(0.5f)));
    CHECK(clampReport["exposure"] == 0.0);
    CHECK(pngByte(" --exposure 1").first == toByte(encodeSrgb(applyTonemap(glm::vec3(0.5f), 1.0f, Tonemap::Aces).x)));
    CHECK(pngByte(" --tonemap clamp --exposure 0.5").first == toByte(encodeSrgb(std::min(1.0f, 0.5f * std::sqrt(2.0f)))));
    CHECK(test::runStrata(render).err.find("note: PNG exposure -1.47 stops, from the first pass") != std::string::npos);
    // Without a PNG there is no exposure to meter or report.
    std::string exrOnly = render;
    exrOnly.replace(exrOnly.rfind("out.png"), 7, "out.exr");
    const auto linear = test::runStrata(exrOnly);
    REQUIRE_MESSAGE(linear.exitCode == 0, linear.err);
    CHECK(nlohmann::json::parse(linear.out)["exposure"].is_null());
    CHECK(linear.err.find("PNG exposure") == std::string::npos);
}

TEST_CASE("cli: under the default sky camera rays that miss show the backdrop, and the EXR's alpha says where") {
    const auto dir = test::scratchDir("cli-backdrop");
    // A small grey square in the middle of the view, the rest sky.
    std::ofstream(dir / "grey.obj") << "mtllib grey.mtl\nusemtl grey\nv -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3 4\n";
    std::ofstream(dir / "grey.mtl") << "newmtl grey\nKd 0.5 0.5 0.5\n";
    std::ofstream(dir / "grey.json") << R"({"position":[0,0,5],"look_at":[0,0,0],"up":[0,1,0],"fov_y":60})";
    const std::string exr = (dir / "out.exr").string();
    const std::string render = "render " + (dir / "grey.obj").string() +
                               " --sampler cosine --no-nee --depth 2 --spp 24 --width 16 --height 16 --out " + exr;
    const auto corner = [&](const std::string& options) {
        const auto result = test::runStrata(render + options);
        REQUIRE_MESSAGE(result.exitCode == 0, result.err);
        const Image image = readExr(exr);
        REQUIRE(image.alpha.size() == 256);
        CHECK(image.alpha[0] == 0.0f);             // the corner sees sky
        CHECK(image.alpha[8 * 16 + 8] == 1.0f);    // the centre the square
        CHECK(image.pixels[8 * 16 + 8].y == doctest::Approx(0.5f).epsilon(1e-6));
        return image.pixels[0];
    };
    // The top-left pixel of the grey gradient, between its top and the next row's.
    const float top = corner("").y;
    CHECK(top < Backdrop::kGradientTop);
    CHECK(top > Backdrop::kGradientTop + (Backdrop::kGradientBottom - Backdrop::kGradientTop) / 16.0f);
    CHECK(corner(" --background env") == glm::vec3(1.0f));
    CHECK(corner(" --background 0.25,0,1") == glm::vec3(0.25f, 0.0f, 1.0f));
    // A sky the user gives is seen as it is, unless --background says otherwise.
    CHECK(corner(" --env-color 1 1 1") == glm::vec3(1.0f));
    CHECK(corner(" --env-color 1 1 1 --background gradient").y == top);
}

TEST_CASE("cli: --epsilon picks the depth from the truncation bound") {
    const auto result = test::runStrata("render " + furnace() + " --epsilon 1e-3 --spp 24 --json");
    REQUIRE(result.exitCode == 0);
    CHECK(nlohmann::json::parse(result.out)["depth"] == 10);
    CHECK(result.err.find("depth K = 10") != std::string::npos);
}

TEST_CASE("cli: --env overrides the scene description's environment, which stands without it") {
    const auto dir = test::scratchDir("cli-described-sky");
    // The grey square of albedo 0.5 filling the view, under the description's sky of 2.
    std::ofstream(dir / "grey.obj") << "mtllib grey.mtl\nusemtl grey\nv -9 -9 0\nv 9 -9 0\nv 9 9 0\nv -9 9 0\nf 1 2 3 4\n";
    std::ofstream(dir / "grey.mtl") << "newmtl grey\nKd 0.5 0.5 0.5\n";
    std::ofstream(dir / "grey.json") << R"({"position":[0,0,5],"look_at":[0,0,0],"up":[0,1,0],"fov_y":20,)"
                                        R"("environment":{"color":[2,2,2]}})";
    // Cosine sampling alone is exact here; next-event estimation's MIS would add noise.
    const std::string render = "render " + (dir / "grey.obj").string() +
                               " --sampler cosine --no-nee --depth 2 --spp 24 --width 4 --height 4 --json";
    const auto described = test::runStrata(render);
    REQUIRE(described.exitCode == 0);
    CHECK(described.err.find("note: the scene has no light") == std::string::npos);
    CHECK(nlohmann::json::parse(described.out)["mean_rgb"][1].get<double>() == doctest::Approx(1.0).epsilon(1e-6));
    const auto coloured = test::runStrata(render + " --env-color 4 4 4");
    REQUIRE(coloured.exitCode == 0);
    CHECK(nlohmann::json::parse(coloured.out)["mean_rgb"][1].get<double>() == doctest::Approx(2.0).epsilon(1e-6));
    const auto dark = test::runStrata(render + " --env none --no-early-out");
    REQUIRE(dark.exitCode == 0);
    CHECK(nlohmann::json::parse(dark.out)["mean_rgb"][1].get<double>() == 0.0);
}

TEST_CASE("cli: next-event estimation and Russian roulette are on by default, each with its switch, the terminator offset off") {
    const std::string render = "render " + furnace() + " --width 8 --height 8 --spp 24 --json";
    const auto settingsOf = [&](const std::string& options) {
        const auto result = test::runStrata(render + options);
        REQUIRE_MESSAGE(result.exitCode == 0, result.err);
        const auto report = nlohmann::json::parse(result.out);
        return std::pair{report["nee"].get<bool>(), report["roulette_depth"].get<int>()};
    };
    CHECK(settingsOf("") == std::pair{true, kRouletteDepthDefault});
    CHECK(settingsOf(" --nee") == std::pair{true, kRouletteDepthDefault});
    CHECK(settingsOf(" --no-nee") == std::pair{false, kRouletteDepthDefault});
    CHECK(settingsOf(" --roulette-depth -1") == std::pair{true, -1});
    // The terminator offset is off unless asked for.
    const auto offsetOf = [&](const std::string& options) {
        const auto result = test::runStrata(render + options);
        REQUIRE_MESSAGE(result.exitCode == 0, result.err);
        return nlohmann::json::parse(result.out)["terminator_offset"].get<double>();
    };
    CHECK(offsetOf("") == 0.0);
    CHECK(offsetOf(" --terminator-offset 0.25") == 0.25);
    const auto help = test::runStrata("render --help");
    REQUIRE(help.exitCode == 0);
    CHECK(help.out.find("--no-nee") != std::string::npos);
}

TEST_CASE("cli: the load summary names the triangle test, and --watertight forces the watertight one") {
    // The furnace near the origin (rounding gap share 3e-6) takes the fast test by default; forced
    // to the watertight one it renders the same furnace value.
    const auto automatic = test::runStrata("render " + furnace() + " --depth 3 --spp 24 --width 16 --height 16 --json");
    REQUIRE(automatic.exitCode == 0);
    CHECK(automatic.err.find("fast triangle test") != std::string::npos);
    const auto forced =
        test::runStrata("render " + furnace() + " --depth 3 --spp 24 --width 16 --height 16 --watertight --json");
    REQUIRE(forced.exitCode == 0);
    CHECK(forced.err.find("watertight triangle test") != std::string::npos);
    CHECK(std::abs(nlohmann::json::parse(forced.out)["mean_rgb"][0].get<double>() - 1.875) < 0.01 * 1.875);
}

TEST_CASE("cli: a texture outside the scene's folder is refused, and --allow-outside-files reads it in render and view") {
    const test::ScratchDir dir = test::scratchDir("cli-outside");
    std::filesystem::create_directories(dir / "model");
    std::ofstream(dir / "model" / "s.obj") << "mtllib s.mtl\nv 0 0 0\nv 1 0 0\nv 1 0 1\nv 0 0 1\nvt 0 0\nvt 1 0\n"
                                              "vt 1 1\nvt 0 1\nusemtl lamp\nf 1/1 3/3 2/2\nf 1/1 4/4 3/3\n";
    std::ofstream(dir / "model" / "s.mtl") << "newmtl lamp\nKd 0.5 0.5 0.5\nKe 1 1 1\nmap_Ke ../glow.tga\n";
    // An 8-bit grey 1x1 TGA: the texture that must not be read without the option.
    std::ofstream(dir / "glow.tga", std::ios::binary) << std::string("\0\0\3\0\0\0\0\0\0\0\0\0\1\0\1\0\x08\0\x80", 19);
    const std::string scene = (dir / "model" / "s.obj").string();
    const auto refused = test::runStrata("render " + scene + " --spp 24 --width 4 --height 4 --out " +
                                         (dir / "o.exr").string());
    CHECK(refused.exitCode == 1);
    CHECK(refused.err.find("s.mtl:4: map_Ke '../glow.tga' resolves outside the model's folder (") != std::string::npos);
    CHECK(refused.err.find("); --allow-outside-files reads it") != std::string::npos);
    const std::string note = "s.mtl:4: map_Ke '../glow.tga' is outside the model's folder";
    const auto rendered = test::runStrata("render " + scene + " --allow-outside-files --spp 24 --width 4 --height 4 --out " +
                                          (dir / "o.exr").string());
    CHECK(rendered.exitCode == 0);
    CHECK(rendered.err.find(note) != std::string::npos);
    if (test::kSanitizedBuild) return;  // the viewer's Mesa leaks stop a sanitized child
    const auto viewed = test::runStrata("view " + scene + " --headless=osmesa --frames 1 --window 32 32 --allow-outside-files");
    CHECK(viewed.exitCode == 0);
    CHECK(viewed.err.find(note) != std::string::npos);
}

TEST_CASE("cli: usage errors exit 2, input errors 1, and a mistyped option is named with the one meant") {
    const auto dir = test::scratchDir("cli-exit");
    std::ofstream(dir / "bad.obj") << "v 0 0 0\nv 1 0 zero\n";
    struct Case {
        std::string arguments;
        int exitCode;
        std::string says;
    };
    const std::vector<Case> cases = {
        {"render " + furnace() + " --sp 24", 2, "strata: unknown option '--sp'; did you mean '--spp'? (see strata render --help)"},
        {"render " + furnace() + " --env-colour 1 1 1", 2, "unknown option '--env-colour'; did you mean '--env-color'?"},
        {"render " + furnace() + " --nonsense-option", 2, "unknown option '--nonsense-option' (see strata render --help)"},
        {"render " + furnace() + " --spp -5", 2, "--spp: must be a positive multiple of 24"},
        {"render " + furnace() + " --width 0", 2, "--width: must be in 1..65536"},
        {"render " + furnace() + " --spp many", 2, "--spp"},
        {"samples --passes 0", 2, "--passes"},
        {"frobnicate", 2, "unknown command 'frobnicate'"},
        {"render " + (dir / "absent.obj").string(), 1, "absent.obj: no such scene file"},
        {"render " + dir.string(), 1, "is a folder, not a scene file"},
        {"render " + (dir / "bad.obj").string(), 1, "bad.obj:2"},
    };
    for (const auto& c : cases) {
        const auto result = test::runStrata(c.arguments);
        INFO("strata " << c.arguments << "\n-> exit " << result.exitCode << ", stderr: " << result.err);
        CHECK(result.exitCode == c.exitCode);
        CHECK(test::lineCount(result.err) == 1);
        CHECK(result.err.find(c.says) != std::string::npos);
    }
    // --help says so.
    CHECK(test::runStrata("--help").out.find("2 bad usage") != std::string::npos);
}
