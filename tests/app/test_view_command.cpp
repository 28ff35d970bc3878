// `strata view` end to end: offscreen (--headless=osmesa) with its JSON report, bad options, and
// the real windowed viewer under Xvfb writing a screenshot that shows the panel and, beside it,
// the box.
#include <doctest/doctest.h>

#include <cstdlib>
#include <nlohmann/json.hpp>
#include <stb_image.h>
#include <sys/wait.h>

#include "test_support.h"

using namespace strata;

namespace {

struct Rgb {
    int width = 0, height = 0;
    std::vector<unsigned char> pixels;
    const unsigned char* at(int x, int y) const { return &pixels[3 * (static_cast<size_t>(y) * width + x)]; }
};

Rgb readPng(const std::filesystem::path& path) {
    Rgb image;
    int channels = 0;
    unsigned char* data = stbi_load(path.c_str(), &image.width, &image.height, &channels, 3);
    REQUIRE_MESSAGE(data != nullptr, "cannot read " << path);
    image.pixels.assign(data, data + 3 * static_cast<size_t>(image.width) * image.height);
    stbi_image_free(data);
    return image;
}

}  // namespace

TEST_CASE("view --headless=osmesa renders to the target spp and reports frame times as JSON") {
    const auto dir = test::scratchDir("view-headless");
    const auto shot = dir / "shot.png";
    // --width/--height give the image; the window is the panel wider.
    const auto result = test::runStrata("view --headless=osmesa --frames 3 --width 96 --height 64 --threads 2 "
                                        "--target-spp 48 --json --screenshot " + shot.string());
    REQUIRE_MESSAGE(result.exitCode == 0, result.err);
    const auto report = nlohmann::json::parse(result.out);
    CHECK(report["context"] == "osmesa");
    CHECK(report["image_width"] == 96);
    CHECK(report["image_height"] == 64);
    CHECK(report["width"] == 96 + 380);
    CHECK(report["spp"] == 48);
    CHECK(report["passes"] == 2);
    CHECK(report["frames"].get<int>() >= 3);
    CHECK(report["frame_ms_p95"].get<double>() >= report["frame_ms_p50"].get<double>());
    CHECK(report["paths"].get<uint64_t>() == 2u * 48u * 96u * 64u);  // both sides, 48 spp, every pixel
    REQUIRE(report["sides"].size() == 2);
    CHECK(report["sides"][0]["sampler"] == "uniform");
    CHECK(report["sides"][1]["sampler"] == "strata24");
    CHECK(report["sides"][1]["error"].get<double>() > 0.0);  // measured at the second pass
    const Rgb image = readPng(shot);
    CHECK(image.width == 96 + 380);
    CHECK(image.height == 64);
}

TEST_CASE("view rejects bad options with one line and a non-zero exit") {
    const auto backend = test::runStrata("view --headless=vulkan --frames 1");
    CHECK(backend.exitCode != 0);
    CHECK(backend.err.find("--headless") != std::string::npos);
    const auto frames = test::runStrata("view --headless=osmesa");
    CHECK(frames.exitCode != 0);
    CHECK(frames.err.find("--frames") != std::string::npos);
    const auto scene = test::runStrata("view /nonexistent/scene.obj --headless=osmesa --frames 1");
    CHECK(scene.exitCode != 0);
    CHECK(scene.err.find("/nonexistent/scene.obj") != std::string::npos);
    const auto shot = test::runStrata("view --headless=osmesa --frames 1 --screenshot out.jpg");
    CHECK(shot.exitCode != 0);
    CHECK(shot.err.find("--screenshot") != std::string::npos);
}

TEST_CASE("view --screenshot takes any letter case of .png, and a folder it cannot write fails before the viewer opens") {
    const auto dir = test::scratchDir("view-screenshot");
    const auto shot = dir / "SHOT.PNG";
    const std::string view = "view --headless=osmesa --frames 1 --window 32 32 --threads 1 --screenshot ";
    const auto written = test::runStrata(view + shot.string());
    REQUIRE_MESSAGE(written.exitCode == 0, written.err);
    CHECK(readPng(shot).width == 32);
    const auto missing = test::runStrata(view + (dir / "no" / "shot.png").string());
    CHECK(missing.exitCode == 1);
    // One line: no scene was read (its summary line) and no context opened.
    CHECK(missing.err == "strata: --screenshot: " + (dir / "no" / "shot.png").string() +
                             ": cannot write: no such folder " + (dir / "no").string() + "\n");
}

TEST_CASE("the windowed viewer under Xvfb shows the panel and, beside it, the Cornell box") {
    REQUIRE_MESSAGE(std::system("command -v xvfb-run >/dev/null 2>&1") == 0,
                    "xvfb-run is missing (scripts/setup.sh installs xvfb)");
    const auto dir = test::scratchDir("view-xvfb");
    const auto shot = dir / "window.png";
    constexpr int kWidth = 1280, kHeight = 720, kPanel = 380;
    // --no-split: one image, so the box's walls are where the camera puts them.
    const std::string command = "xvfb-run -a -s '-screen 0 1600x900x24' " + std::string(STRATA_BINARY) +
                                " view --no-split --window " + std::to_string(kWidth) + " " +
                                std::to_string(kHeight) + " --frames 4 --scale 0.25 --target-spp 48 --threads 2 " +
                                "--exposure 1 --screenshot " + shot.string() + " >" + (dir / "log").string() +
                                " 2>&1";
    const int status = std::system(command.c_str());
    REQUIRE_MESSAGE((WIFEXITED(status) && WEXITSTATUS(status) == 0), "xvfb-run strata view failed, see "
                                                                       << (dir / "log"));
    const Rgb image = readPng(shot);
    REQUIRE(image.width == kWidth);
    REQUIRE(image.height == kHeight);
    // The panel, at the left: ImGui's dark style, blue buttons and tabs (blue well above red).
    int bluish = 0;
    for (int y = 0; y < 240; ++y) {
        for (int x = 0; x < kPanel; ++x) bluish += image.at(x, y)[2] > image.at(x, y)[0] + 40;
    }
    CHECK(bluish > kPanel * 240 / 20);
    // The image has the rest of the window, and the camera frames the box in the middle square
    // of it: its right wall is green. In the right wall's band green dominates red; the box is
    // lit; between the panel and the box the image is the black of the render, not the panel.
    long green = 0, red = 0, lit = 0, dark = 0;
    const int boxLeft = kPanel + (kWidth - kPanel - kHeight) / 2;
    for (int y = kHeight / 4; y < 3 * kHeight / 4; ++y) {
        for (int x = boxLeft + kHeight * 85 / 100; x < boxLeft + kHeight * 95 / 100; ++x) {
            green += image.at(x, y)[1];
            red += image.at(x, y)[0];
        }
        for (int x = boxLeft; x < boxLeft + kHeight; ++x) lit += image.at(x, y)[0] + image.at(x, y)[1] > 40;
        for (int x = kPanel + 4; x < boxLeft - 4; ++x) dark += image.at(x, y)[0] + image.at(x, y)[1] + image.at(x, y)[2] == 0;
    }
    CHECK(green > red * 6 / 5);  // the wall is still speckled: a margin, not a factor
    CHECK(lit > kHeight * kHeight / 2 / 4);
    CHECK(dark == static_cast<long>(kHeight / 2) * (boxLeft - kPanel - 8));
}

TEST_CASE("view --reference measures RMSE: zero for the side that repeats the reference's render") {
    // The batch renderer's image at the same camera, sampler, depth, seed and spp is the viewer's
    // strata24 side sample for sample (a pixel's samples depend only on seed, pixel, pass, step),
    // so that side's RMSE is 0 up to the EXR's float32 rounding, and the uniform side's is noise.
    // Without next-event estimation: the viewer's camera comes back from its orbit controller
    // rounded in the last bits, which moves every hit point by a rounding error; light samples'
    // distances and cosines follow it, while hemisphere samples' weights depend only on normals.
    const auto dir = test::scratchDir("view-reference");
    const auto reference = dir / "reference.exr";
    const auto render = test::runStrata("render " + test::cornellScene().string() +
                                        " --width 48 --height 32 --spp 48 --sampler strata24 --no-nee --out " +
                                        reference.string());
    REQUIRE_MESSAGE(render.exitCode == 0, render.err);
    const auto view = test::runStrata("view --headless=osmesa --frames 1 --width 48 --height 32 --target-spp 48 --no-nee --json "
                                      "--reference " + reference.string());
    REQUIRE_MESSAGE(view.exitCode == 0, view.err);
    const auto report = nlohmann::json::parse(view.out);
    CHECK(report["error_against_reference"] == true);
    CHECK(report["sides"][0]["sampler"] == "uniform");
    CHECK(report["sides"][0]["error"].get<double>() > 1e-3);
    CHECK(report["sides"][1]["error"].get<double>() < 1e-6);
}
