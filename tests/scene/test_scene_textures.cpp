// A scene's textures (scene/scene_textures.h): decoded once per file and encoding, each counted
// against the scene's texture budget before its texels are allocated; a file no decoder reads is
// a warning and the factor alone, one that would go over the budget an error, and a damaged file
// that decodes a warning, once per file.
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "image_support.h"
#include "scene/scene_textures.h"
#include "util/error.h"

using namespace strata;

namespace {
// 8 x 8 RGB: 192 bytes of texels.
std::string smallPng() { return test::pngFile(8, 8, 8, 2, std::string(8 * (1 + 8 * 3), '\0')); }
}  // namespace

TEST_CASE("scene textures: each file and encoding counts once, and the texture past the budget is refused, named") {
    const SceneBundle bundle{"s.obj", {{"s.obj", ""}, {"t.png", smallPng()}, {"u.png", smallPng()}}, {}, {}};
    std::vector<std::string> warnings;
    // One texture's worth.
    SceneTextures textures(bundle, warnings, TextureBudget(214));
    const auto colour = textures.file("t.png", TextureEncoding::Colour, "s.mtl:3: map_Kd");
    REQUIRE(colour);
    CHECK(textures.file("t.png", TextureEncoding::Colour, "s.mtl:9: map_Kd") == colour);
    CHECK(textures.budget().used() == 192);
    CHECK_THROWS_WITH_AS(textures.file("u.png", TextureEncoding::Colour, "s.mtl:4: map_Ke"),
                         "s.mtl:4: map_Ke: texture 'u.png' is 8 x 8, 3 channels of 8 bits (192 bytes); with it the "
                         "scene's textures would take 384 bytes, over the --texture-budget of 214 bytes",
                         Error);
    // The same file as data is another texture.
    CHECK_THROWS_AS(textures.file("t.png", TextureEncoding::Data, "s.mtl:5: map_d"), Error);
    CHECK(warnings.empty());
}

TEST_CASE("scene textures: a header its file cannot hold is a warning and takes nothing of the budget") {
    const SceneBundle bundle{"s.obj", {{"s.obj", ""}, {"big.gif", test::forgedGif(16384, 16384, 40000)}}, {}, {}};
    std::vector<std::string> warnings;
    SceneTextures textures(bundle, warnings, TextureBudget());
    CHECK_FALSE(textures.file("big.gif", TextureEncoding::Colour, "s.mtl:3: map_Kd"));
    CHECK(warnings == std::vector<std::string>{"s.mtl:3: map_Kd: big.gif: a 16384 x 16384 image cannot be stored in "
                                               "40000 bytes (truncated or corrupt); using the factor alone"});
    CHECK(textures.budget().used() == 0);
}

TEST_CASE("scene textures: a truncated JPEG decodes with one warning naming it, however often it is used") {
    const SceneBundle bundle{"s.obj", {{"s.obj", ""}, {"cut.jpg", test::truncatedJpeg()}}, {}, {}};
    std::vector<std::string> warnings;
    SceneTextures textures(bundle, warnings, TextureBudget());
    CHECK(textures.file("cut.jpg", TextureEncoding::Colour, "s.mtl:3: map_Kd"));
    CHECK(textures.file("cut.jpg", TextureEncoding::Data, "s.mtl:4: map_d"));
    REQUIRE(warnings.size() == 1);
    CHECK(warnings[0].rfind("s.mtl:3: map_Kd: cut.jpg: damaged or truncated JPEG (libjpeg: ", 0) == 0);
    CHECK(textures.budget().used() == 2 * 32 * 32 * 3);
}
