// The installed program: this build put into a fresh prefix by `cmake --install`, run from a
// folder with no assets/ above it, so that it can only use what was installed. Nothing in the build tree is removed or changed (the install adds its manifest).
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <stb_image.h>

#include "test_support.h"

using namespace strata;

namespace {

namespace fs = std::filesystem;

// Installs this build under `prefix`; returns the installed program.
fs::path installInto(const fs::path& prefix) {
    const auto install = test::runCommand(std::string(STRATA_CMAKE) + " --install " + STRATA_BUILD_DIR +
                                          " --prefix " + prefix.string());
    REQUIRE_MESSAGE(install.exitCode == 0, install.out << install.err);
    return prefix / "bin" / "strata";
}

test::CommandResult runIn(const fs::path& dir, const fs::path& program, const std::string& arguments) {
    return test::runCommand("cd " + dir.string() + " && " + program.string() + " " + arguments);
}

bool assetsAbove(fs::path dir) {
    for (;; dir = dir.parent_path()) {
        if (fs::exists(dir / "assets")) return true;
        if (dir == dir.parent_path()) return false;
    }
}

// The bundled scene `name` as installed with `strata` (the path it reports).
fs::path installedScene(const fs::path& strata, const std::string& name) {
    return fs::canonical(strata).parent_path().parent_path() / "share" / "strata" / name / (name + ".obj");
}

// `strata render` with no scene, in `dir`: the installed Cornell box, a lit 64x64 PNG.
void checkRendersBundledScene(const fs::path& strata, const fs::path& dir) {
    const auto render = runIn(dir, strata, "render --spp 24 --width 64 --height 64 --out x.png --json");
    REQUIRE_MESSAGE(render.exitCode == 0, render.err);
    const auto report = nlohmann::json::parse(render.out);
    CHECK(report["scene"] == installedScene(strata, "cornell").string());
    for (const auto& channel : report["mean_rgb"]) CHECK(channel.get<double>() > 0.0);
    int width = 0, height = 0, channels = 0;
    unsigned char* pixels = stbi_load((dir / "x.png").c_str(), &width, &height, &channels, 3);
    REQUIRE_MESSAGE(pixels != nullptr, "no readable PNG " << (dir / "x.png"));
    CHECK(width == 64);
    CHECK(height == 64);
    CHECK(*std::max_element(pixels, pixels + 3 * width * height) > 0);
    stbi_image_free(pixels);
}

}  // namespace

TEST_CASE("install: the installed strata renders, views and benches its bundled scenes from any folder") {
    const auto prefix = test::scratchDir("install-prefix");
    const auto work = test::scratchDir("install-work");
    REQUIRE_MESSAGE(!assetsAbove(work), work << " has an assets/ folder above it");
    const fs::path strata = installInto(prefix);
    CHECK(fs::is_regular_file(prefix / "share" / "strata" / "NOTICE"));
    CHECK(!fs::exists(prefix / "share" / "strata" / "readme"));  // the README's pictures stay out

    checkRendersBundledScene(strata, work);

    if (test::kSanitizedBuild) {
        MESSAGE("view skipped: a sanitized `strata view` stops on Mesa's leaks");
    } else {
        const auto view = runIn(work, strata, "view --headless --frames 5 --window 96 64 --threads 2 --json");
        REQUIRE_MESSAGE(view.exitCode == 0, view.err);
        const auto report = nlohmann::json::parse(view.out);
        CHECK(report["scene"] == installedScene(strata, "cornell").string());
        CHECK(report["frames"].get<int>() >= 5);
    }

    // The suite of bundled scenes, small; the output goes to ./bench-out by default.
    const auto bench = runIn(work, strata, "bench --quick --skip-throughput --max-spp 48 --width 16");
    REQUIRE_MESSAGE(bench.exitCode == 0, bench.err);
    CHECK(fs::is_regular_file(work / "bench-out" / "summary.md"));
    CHECK(bench.out.find(installedScene(strata, "cornell").string()) != std::string::npos);
    CHECK(bench.out.find(installedScene(strata, "furnace").string()) != std::string::npos);
}

TEST_CASE("install: a moved prefix keeps working, and one without its scenes says which folder is missing") {
    const auto first = test::scratchDir("install-first");
    const auto moved = test::scratchDir("install-moved");
    const auto work = test::scratchDir("install-moved-work");
    installInto(first / "prefix");
    fs::rename(first / "prefix", moved / "prefix");
    const fs::path strata = moved / "prefix" / "bin" / "strata";
    checkRendersBundledScene(strata, work);

    fs::remove_all(moved / "prefix" / "share" / "strata");
    const auto broken = runIn(work, strata, "render --spp 24");
    CHECK(broken.exitCode == 1);
    CHECK(std::count(broken.err.begin(), broken.err.end(), '\n') == 1);
    CHECK(broken.err.find("the bundled scenes are missing: no folder " +
                          (fs::canonical(moved) / "prefix" / "share" / "strata").string()) != std::string::npos);
}
