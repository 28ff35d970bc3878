// The first picture of models a user would expect to open, with no option at all: Debian's
// assimp-testmodels (and Embree's Cornell box from embree-tools), rendered small by `strata render`.
// Each must show its model framed (spanning at least 40% of the frame's width and height by the
// EXR's alpha, the share of camera rays that found a surface), lit (not black) and standing out
// from what is around it.
// Skipped, with a message, for the models that are not installed.
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <vector>
#include <stb_image.h>

#include "film/accumulation_buffer.h"
#include "io/image_io.h"
#include "test_support.h"

using namespace strata;
namespace fs = std::filesystem;

namespace {

const fs::path kAssimp = "/usr/share/assimp/models";

struct Model {
    const char* name;
    fs::path path;
    const char* package;
};

const Model kModels[] = {
    {"box", kAssimp / "OBJ/box.obj", "assimp-testmodels"},
    {"concave_polygon", kAssimp / "OBJ/concave_polygon.obj", "assimp-testmodels"},
    {"space_in_material_name", kAssimp / "OBJ/space_in_material_name.obj", "assimp-testmodels"},
    {"WusonOBJ", kAssimp / "OBJ/WusonOBJ.obj", "assimp-testmodels"},
    {"cube_usemtl", kAssimp / "OBJ/cube_usemtl.obj", "assimp-testmodels"},
    {"regr_3429812", kAssimp / "OBJ/regr_3429812.obj", "assimp-testmodels"},
    {"BoxTextured", kAssimp / "glTF2/BoxTextured-glTF/BoxTextured.gltf", "assimp-testmodels"},
    {"2CylinderEngine", kAssimp / "glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb",
     "assimp-testmodels"},
    {"ClearCoatTest", kAssimp / "glTF2/ClearCoat-glTF/ClearCoatTest.gltf", "assimp-testmodels"},
    {"cornell_box", "/usr/share/doc/embree3/models/cornell_box.obj", "embree-tools"},
};
}  // namespace

TEST_CASE("default view: each model a user would open shows up, lit, across at least 40% of the frame") {
    const auto dir = test::scratchDir("default-view");
    int rendered = 0;
    for (const Model& model : kModels) {
        const std::string name = model.name;
        CAPTURE(name);
        if (!fs::is_regular_file(model.path)) {
            MESSAGE("skipped: " << model.path << " is absent (apt-get install " << model.package << ")");
            continue;
        }
        const fs::path exr = dir / (name + ".exr");
        const fs::path png = dir / (name + ".png");
        const auto result = test::runStrata("render " + model.path.string() +
                                            " --width 96 --height 96 --spp 24 --out " + exr.string() +
                                            " --out " + png.string());
        REQUIRE_MESSAGE(result.exitCode == 0, result.err);
        const Image image = readExr(exr);
        REQUIRE(image.alpha.size() == image.pixels.size());
        std::vector<double> onModel;  // the luminance of the pixels that see the model
        int left = image.width, right = -1, top = image.height, bottom = -1;
        for (size_t p = 0; p < image.pixels.size(); ++p) {
            if (!(image.alpha[p] >= 0.5f)) continue;
            onModel.push_back(luminance(glm::dvec3(image.pixels[p])));
            const int x = static_cast<int>(p % static_cast<size_t>(image.width));
            const int y = static_cast<int>(p / static_cast<size_t>(image.width));
            left = std::min(left, x);
            right = std::max(right, x);
            top = std::min(top, y);
            bottom = std::max(bottom, y);
        }
        const double share = static_cast<double>(onModel.size()) / static_cast<double>(image.pixels.size());
        // The model's extent on screen, as a share of the frame's width and height.
        const double across = static_cast<double>(right - left + 1) / image.width;
        const double down = static_cast<double>(bottom - top + 1) / image.height;
        CAPTURE(share);
        CAPTURE(across);
        CAPTURE(down);
        // Not all sky, and framed: the model spans 40% of the frame both ways (a thin ring
        // covers 5% of it and fills the view as a cube does) and covers more than a few pixels.
        CHECK(across >= 0.4);
        CHECK(down >= 0.4);
        CHECK(share >= 0.02);
        if (onModel.empty()) continue;
        // Not black: most of the model is lit (a few glowing labels on black would not do).
        std::nth_element(onModel.begin(), onModel.begin() + onModel.size() / 2, onModel.end());
        const double median = onModel[onModel.size() / 2];
        CAPTURE(median);
        CHECK(median > 0.02);
        // As displayed, the picture has contrast: not one flat colour (sky, black or white).
        int width = 0, height = 0, channels = 0;
        unsigned char* pixels = stbi_load(png.c_str(), &width, &height, &channels, 3);
        REQUIRE(pixels != nullptr);
        const auto [darkest, brightest] = std::minmax_element(pixels, pixels + 3 * width * height);
        CHECK(*brightest - *darkest >= 64);
        stbi_image_free(pixels);
        ++rendered;
    }
    if (rendered == 0) MESSAGE("skipped: none of the models is installed (scripts/setup.sh installs them)");
}
