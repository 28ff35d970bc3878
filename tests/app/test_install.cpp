// The installed program: this build put into a fresh prefix by `cmake --install` (and into a .deb
// by cpack), run from a folder with no assets/ above it, so that it can only use what was
// installed. Nothing in the build tree is removed or changed (the install adds its manifest).
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdlib>
#include <set>
#include <sstream>
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
    CHECK(!fs::exists(prefix / "share" / "strata" / "readme"));  // README and docs/ pictures stay out
    // Run among files named like its libraries, which it must not load from there.
    REQUIRE(test::plantLibraryDecoys(strata, work) >= 5);

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

TEST_CASE("install: the .deb holds the program and its scenes and depends on the libraries it links") {
    if (test::kSanitizedBuild) {
        MESSAGE("skipped: a sanitized build's package would depend on the sanitizer runtimes");
        return;
    }
    if (std::system("command -v dpkg-deb >/dev/null 2>&1") != 0) {
        MESSAGE("skipped: no dpkg-deb (not a Debian system)");
        return;
    }
    REQUIRE_MESSAGE(std::system("command -v dpkg-shlibdeps >/dev/null 2>&1") == 0,
                    "dpkg-shlibdeps is missing (scripts/setup.sh installs dpkg-dev)");
    const auto dir = test::scratchDir("deb");
    const auto cpack = test::runCommand("cd " + dir.string() + " && " + STRATA_CPACK + " -G DEB --config " +
                                        STRATA_BUILD_DIR + "/CPackConfig.cmake -B " + dir.string());
    REQUIRE_MESSAGE(cpack.exitCode == 0, cpack.out << cpack.err);
    fs::path deb;
    for (const auto& entry : fs::directory_iterator(dir)) {
        if (entry.path().extension() == ".deb") deb = entry.path();
    }
    REQUIRE_MESSAGE(deb.filename().string().rfind("strata_", 0) == 0, cpack.out);

    const auto contents = test::runCommand("dpkg-deb -c " + deb.string());
    REQUIRE_MESSAGE(contents.exitCode == 0, contents.err);
    for (const char* file : {"./usr/bin/strata", "./usr/share/strata/NOTICE", "./usr/share/strata/cornell/cornell.obj",
                             "./usr/share/strata/cornell/cornell.mtl", "./usr/share/strata/cornell/cornell.json",
                             "./usr/share/strata/furnace/furnace.obj", "./usr/share/strata/glossy/glossy.obj",
                             "./usr/share/doc/strata/copyright", "./usr/share/doc/strata/changelog.gz",
                             "./usr/share/man/man1/strata.1.gz"}) {
        CHECK_MESSAGE(contents.out.find(std::string(" ") + file + "\n") != std::string::npos, std::string(file));
    }
    CHECK(contents.out.find("readme") == std::string::npos);

    const auto field = [&](const std::string& name) {
        const auto value = test::runCommand("dpkg-deb -f " + deb.string() + " " + name);
        REQUIRE_MESSAGE(value.exitCode == 0, value.err);
        return value.out;
    };
    CHECK(field("Package") == "strata\n");
    CHECK(field("Section") == "graphics\n");
    // The project maintains it, and it says what the program reads.
    CHECK(field("Maintainer").rfind("Strata developers <", 0) == 0);
    CHECK(field("Description").find("OBJ and glTF 2.0 scenes") != std::string::npos);
    // Debian's machine-readable copyright format, with Strata's own licence status.
    const auto copyright =
        test::runCommand("dpkg-deb --fsys-tarfile " + deb.string() + " | tar -xO ./usr/share/doc/strata/copyright");
    REQUIRE(copyright.exitCode == 0);
    CHECK(copyright.out.rfind("Format: https://www.debian.org/doc/packaging-manuals/copyright-format/1.0/\n"
                              "Upstream-Name: Strata\n", 0) == 0);
    CHECK(copyright.out.find("\nFiles: *\nCopyright: 2026 Seed bb8e34dd maintainers\nLicense: no-licence-stated\n") !=
          std::string::npos);
    // Lintian finds nothing, down to its pedantic and experimental tags.
    REQUIRE_MESSAGE(std::system("command -v lintian >/dev/null 2>&1") == 0,
                    "lintian is missing (scripts/setup.sh installs it)");
    const auto lintian = test::runCommand("lintian --pedantic --info --display-experimental " + deb.string());
    CHECK_MESSAGE(lintian.exitCode == 0, lintian.out << lintian.err);
    CHECK_MESSAGE(lintian.out.empty(), lintian.out);
    const std::string depends = field("Depends");
    MESSAGE("Depends: " << depends);
    // Each entry is "package" or "package (>= version)"; dpkg-shlibdeps found them from the links,
    // all but libosmesa6, which the program opens at run time (cmake/packaging.cmake names it).
    std::set<std::string> packages;
    std::istringstream entries(depends);
    for (std::string entry; std::getline(entries >> std::ws, entry, ',');) {
        packages.insert(entry.substr(0, entry.find_first_of(" \n")));
    }
    for (const std::string package : {"libembree3-3", "libtbb12", "libglfw3", "libopenexr-3-1-30", "libosmesa6",
                                      "libegl1", "libstdc++6", "libc6"}) {
        CHECK_MESSAGE(packages.count(package) == 1, package);
    }
}
