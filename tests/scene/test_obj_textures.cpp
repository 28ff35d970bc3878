// OBJ/MTL textures end to end (scene/obj_loader.h): files written by the test, read into a
// bundle as `strata render` reads them, parsed and traced.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>
#include <vector>
#include <stb_image_write.h>

#include "io/image_io.h"
#include "io/texture_image.h"
#include "materials/material_table.h"
#include "scene/scene_loader.h"
#include "util/error.h"
#include "test_support.h"

using namespace strata;

namespace {

void writePng(const std::filesystem::path& path, int width, int height, int channels,
              const std::vector<unsigned char>& pixels) {
    std::filesystem::create_directories(path.parent_path());
    REQUIRE(stbi_write_png(path.string().c_str(), width, height, channels, pixels.data(), width * channels));
}

// The unit quad z = 0 facing +z, UVs = (x, y), with material `material` of mtl/quad.mtl.
const char* const kQuadObj =
    "mtllib mtl/quad.mtl\n"
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
    "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
    "usemtl quad\nf 1/1 2/2 3/3 4/4\n";

// 2 x 2 RGB, top row red, green; bottom row blue, white (top row = v near 1).
const std::vector<unsigned char> kQuadrants{255, 0, 0, 0, 255, 0, 0, 0, 255, 255, 255, 255};

// Whether radiance read at a texel's centre is `texel`'s: the bilinear filter reads that texel
// alone, up to the rounding of the hit's barycentrics, which differs between Embree's code paths
// and builds (7e-7 of a neighbour seen on one host).
bool readsTexel(const glm::vec3& radiance, const glm::vec3& texel) {
    return glm::all(glm::lessThanEqual(glm::abs(radiance - texel), glm::vec3(1e-5f)));
}

bool hasWarning(const LoadedScene& scene, const std::string& part) {
    return std::any_of(scene.report.warnings.begin(), scene.report.warnings.end(),
                       [&](const std::string& w) { return w.find(part) != std::string::npos; });
}

}  // namespace

TEST_CASE("an OBJ's map_Ke and map_Kd texture each quadrant of a quad, and paths resolve from the MTL's folder") {
    const test::ScratchDir dir = test::scratchDir("obj_textures");
    test::writeFile(dir / "quad.obj", kQuadObj);
    // Windows separators and spaces, relative to the MTL's folder.
    test::writeFile(dir / "mtl" / "quad.mtl",
                    "newmtl quad\nKd 0.5 0.5 0.5\nKe 2 2 2\nmap_Kd -bm 1 -blendu on tex dir\\quad tex.png\n"
                    "map_Ke .\\tex dir\\quad tex.png\n");
    writePng(dir / "mtl" / "tex dir" / "quad tex.png", 2, 2, 3, kQuadrants);
    const LoadedScene loaded = loadScene(dir / "quad.obj");
    CHECK(loaded.report.warnings.empty());
    REQUIRE(loaded.bundle.find("mtl/tex dir/quad tex.png"));
    const Scene& scene = loaded.scene;

    // Depth 0: a camera ray reads Ke times the texel at each quadrant's centre.
    PathIntegratorSettings settings;
    settings.depth = 0;
    const PathIntegrator integrator(scene, settings);
    const auto seen = [&](float x, float y) {
        uint64_t rays = 0;
        return integrator.radiance(Ray{{x, y, 1.0f}, {0.0f, 0.0f, -1.0f}}, PathSamples(1, 0, 0, 0), rays);
    };
    CHECK(readsTexel(seen(0.25f, 0.75f), glm::vec3(2.0f, 0.0f, 0.0f)));  // top left: red
    CHECK(readsTexel(seen(0.75f, 0.75f), glm::vec3(0.0f, 2.0f, 0.0f)));
    CHECK(readsTexel(seen(0.25f, 0.25f), glm::vec3(0.0f, 0.0f, 2.0f)));
    CHECK(readsTexel(seen(0.75f, 0.25f), glm::vec3(2.0f)));
    // The BSDF at each: Kd times the texel.
    const auto diffuseAt = [&](glm::vec2 uv) {
        return scene.materials().bsdf(0, uv).as<LayeredBsdf>()->albedo({0.0f, 0.0f, 1.0f});
    };
    CHECK(diffuseAt({0.25f, 0.75f}) == glm::vec3(0.5f, 0.0f, 0.0f));
    CHECK(diffuseAt({0.75f, 0.25f}) == glm::vec3(0.5f));
}

TEST_CASE("MTL textures that cannot be used are warnings, and the material keeps its constants") {
    const test::ScratchDir dir = test::scratchDir("obj_bad_textures");
    test::writeFile(dir / "quad.obj", kQuadObj);
    test::writeFile(dir / "mtl" / "quad.mtl",
                    "newmtl quad\nKd 0.5 0.5 0.5\nmap_Kd missing.png\nmap_Ke broken.png\nbump height.png\n"
                    "map_d -o 0.5 0.5 1 -zz 1 alpha.png\nnorm\nnorm -s 2 2 flat.png\n");
    test::writeFile(dir / "mtl" / "broken.png", "\x89PNG\r\n\x1a\nthis is not a PNG");
    writePng(dir / "mtl" / "height.png", 1, 1, 3, {128, 128, 128});
    writePng(dir / "mtl" / "alpha.png", 1, 1, 1, {255});
    writePng(dir / "mtl" / "flat.png", 1, 1, 3, {128, 128, 255});
    const LoadedScene loaded = loadScene(dir / "quad.obj");
    CHECK(hasWarning(loaded, "quad.mtl:3: map_Kd: texture file 'mtl/missing.png' is missing; using the factor alone"));
    CHECK(hasWarning(loaded, "quad.mtl:4: map_Ke: "));
    CHECK(hasWarning(loaded, "broken.png: cannot decode the texture"));
    CHECK(hasWarning(loaded, "quad.mtl:5: bump: 'height.png' holds heights, not normals"));
    CHECK(hasWarning(loaded, "quad.mtl:8: norm: its -o and -s differ from map_d's, whose placement the material's textures share"));
    CHECK(hasWarning(loaded, "quad.mtl:6: map_d: unknown option '-zz' skipped"));
    CHECK(hasWarning(loaded, "quad.mtl:7: norm names no file; ignored"));
    const Material& m = loaded.scene.mesh().materials[0];
    CHECK(!m.textures.colour);
    CHECK(!m.textures.emission);
    CHECK(m.textures.normal);
    CHECK(m.textures.coverage);
    CHECK(m.emission == glm::vec3(0.0f));
}

TEST_CASE("an MTL's map_d is an opacity times d, an emitter's too") {
    const test::ScratchDir dir = test::scratchDir("obj_map_d");
    std::string obj = "mtllib mtl/quad.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nvt 0 0\nvt 1 0\nvt 1 1\n";
    for (const char* name : {"leaf", "veil", "glass", "lamp"}) {
        obj += std::string("usemtl ") + name + "\nf 1/1 2/2 3/3\n";
    }
    test::writeFile(dir / "quad.obj", obj);
    test::writeFile(dir / "mtl" / "quad.mtl",
                    "newmtl leaf\nKd 0.5 0.5 0.5\nmap_d leaf.png\n"
                    "newmtl veil\nKd 0.5 0.5 0.5\nd 0.5\nmap_d grey.png\n"
                    "newmtl glass\nillum 7\nNi 1.5\nd 0.3\nmap_d grey.png\n"
                    "newmtl lamp\nKe 1 1 1\nd 0.5\nmap_d -imfchan r leaf.png\n");
    // The leaf's alpha is 102 (0.4): its opacity is the image's alpha, not its grey.
    writePng(dir / "mtl" / "leaf.png", 1, 1, 4, {255, 255, 255, 102});
    writePng(dir / "mtl" / "grey.png", 1, 1, 1, {153});
    const LoadedScene loaded = loadScene(dir / "quad.obj");
    const auto& materials = loaded.scene.mesh().materials;
    REQUIRE(materials.size() >= 4);
    // A ray goes on through with probability 1 - opacity: for the passing numbers u >= opacity.
    const auto opacity = [&](size_t m) {
        const Material& material = materials[m];
        CHECK(material.textures.blended);
        CHECK_FALSE(material.cutOut({0.5f, 0.5f}, 0.0f));
        return material.textures.coverage->lookup({0.5f, 0.5f})[material.textures.coverageChannel] *
               material.textures.opacity;
    };
    CHECK(opacity(0) == doctest::Approx(0.4));
    CHECK(materials[0].cutOut({0.5f, 0.5f}, 0.41f));
    CHECK_FALSE(materials[0].cutOut({0.5f, 0.5f}, 0.39f));
    CHECK(opacity(1) == doctest::Approx(0.3));  // d 0.5 times the grey 0.6
    CHECK(opacity(2) == doctest::Approx(0.6));  // a dielectric's d is its illum's, not applied
    // The lamp's -imfchan r: the red channel, 1, times d 0.5.
    CHECK(opacity(3) == doctest::Approx(0.5));
    CHECK(loaded.report.warnings.empty());
}

TEST_CASE("an MTL's map_Pm and map_Pr vary metallic and roughness, each from the channel -imfchan names") {
    const test::ScratchDir dir = test::scratchDir("obj_metallic_roughness");
    test::writeFile(dir / "quad.obj", kQuadObj);
    // Without Pm and Pr lines the textures give them whole: metallic is the green of the
    // quadrants, roughness their red (the first channel).
    test::writeFile(dir / "mtl" / "quad.mtl", "newmtl quad\nKd 0.5 0.5 0.5\nmap_Pm -imfchan g -clamp on pbr.png\nmap_Pr pbr.png\n");
    writePng(dir / "mtl" / "pbr.png", 2, 2, 3, kQuadrants);
    const LoadedScene loaded = loadScene(dir / "quad.obj");
    CHECK(loaded.report.warnings.empty());
    const Material& m = loaded.scene.mesh().materials[0];
    REQUIRE(m.metallicRoughness);
    // -clamp on clamps the one texture it is given on, not the other reference to the file.
    REQUIRE(m.textures.metallic);
    CHECK(m.textures.metallic->sampling().u == TextureWrap::ClampToEdge);
    CHECK(m.textures.roughness->sampling().u == TextureWrap::Repeat);
    CHECK(m.textures.metallicChannel == 1);
    CHECK(m.textures.roughnessChannel == 0);
    const MaterialTable table(loaded.scene.mesh().materials);
    // The red quadrant: metallic 0, roughness 1: Kd 0.5 under a GGX layer of alpha 1.
    const Bsdf red = table.bsdf(0, {0.25f, 0.75f});
    REQUIRE(red.as<LayeredBsdf>());
    CHECK(red.as<LayeredBsdf>()->lobe()->distribution.alpha() == doctest::Approx(1.0));
    CHECK(red.readsDiffuseNumbers());
    // The green one: metallic 1, roughness 0: a mirror of F0 = Kd.
    CHECK(table.bsdf(0, {0.75f, 0.75f}).as<SmoothConductor>());
    // The white one: metallic 1, roughness 1: a rough conductor, no diffuse base.
    const Bsdf white = table.bsdf(0, {0.75f, 0.25f});
    REQUIRE(white.as<LayeredBsdf>());
    CHECK_FALSE(white.readsDiffuseNumbers());
}

TEST_CASE("an MTL's -s and -o place its textures: uv * scale + offset, a shared vt copied per placement") {
    const test::ScratchDir dir = test::scratchDir("obj_uv_placement");
    // The quad's left triangle in a placed material, its right one in an unplaced one: the two
    // share the vt of corners 1 and 3.
    test::writeFile(dir / "quad.obj",
                    "mtllib quad.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
                    "usemtl tiled\nf 1/1 3/3 4/4\nusemtl plain\nf 1/1 2/2 3/3\n");
    test::writeFile(dir / "quad.mtl", "newmtl tiled\nKd 1 1 1\nmap_Kd -s 4 2 1 -o 0.25 0.5 tex.png\n"
                                      "newmtl plain\nKd 1 1 1\nmap_Kd tex.png\n");
    writePng(dir / "tex.png", 2, 2, 3, kQuadrants);
    const LoadedScene loaded = loadScene(dir / "quad.obj");
    CHECK(loaded.report.warnings.empty());
    const MeshData& mesh = loaded.scene.mesh();
    REQUIRE(mesh.triangles.size() == 2);
    const auto tiled = cornerUvs(mesh, 0);
    CHECK(tiled[0] == glm::vec2(0.25f, 0.5f));
    CHECK(tiled[1] == glm::vec2(4.25f, 2.5f));
    CHECK(tiled[2] == glm::vec2(0.25f, 2.5f));
    const auto plain = cornerUvs(mesh, 1);
    CHECK(plain[0] == glm::vec2(0.0f, 0.0f));
    CHECK(plain[2] == glm::vec2(1.0f, 1.0f));
    // The four vt and the tiled material's three copies.
    CHECK(mesh.uvs.size() == 7);
}

TEST_CASE("a bump map whose values are normals is read as a normal map") {
    const test::ScratchDir dir = test::scratchDir("obj_bump_normals");
    test::writeFile(dir / "quad.obj", kQuadObj);
    test::writeFile(dir / "mtl" / "quad.mtl", "newmtl quad\nKd 0.5 0.5 0.5\nmap_Bump -bm 0.5 n.png\n");
    writePng(dir / "mtl" / "n.png", 1, 1, 3, {128, 128, 255});
    const LoadedScene loaded = loadScene(dir / "quad.obj");
    CHECK(loaded.report.warnings.empty());
    const Material& m = loaded.scene.mesh().materials[0];
    REQUIRE(m.textures.normal);
    CHECK(m.textures.normalScale == 0.5f);
}

TEST_CASE("an EXR map_Ke's NaN, infinite and negative texels are a warning, and the quad emits finite radiance >= 0") {
    const test::ScratchDir dir = test::scratchDir("obj_exr_emission");
    test::writeFile(dir / "quad.obj", kQuadObj);
    test::writeFile(dir / "mtl" / "quad.mtl", "newmtl quad\nKd 0.5 0.5 0.5\nKe 2 2 2\nmap_Ke glow.exr\n");
    // Top row (1, 0.5, 0.25), (NaN, 1, 1); bottom row (inf, -inf, 0), (-5, 2, 3).
    writeImage(dir / "mtl" / "glow.exr", Image{2, 2, {{1.0f, 0.5f, 0.25f}, {std::nanf(""), 1.0f, 1.0f},
                                                      {INFINITY, -INFINITY, 0.0f}, {-5.0f, 2.0f, 3.0f}}});
    const LoadedScene loaded = loadScene(dir / "quad.obj");
    CHECK(loaded.report.warnings == std::vector<std::string>{
                                        (dir / "mtl" / "quad.mtl").string() +
                                        ":4: map_Ke: 'mtl/glow.exr': 4 of 12 texel values are NaN, infinite or negative; "
                                        "read as 0, or as the texture's largest finite value for +inf"});
    PathIntegratorSettings settings;
    settings.depth = 0;
    const PathIntegrator integrator(loaded.scene, settings);
    const auto seen = [&](float x, float y) {
        uint64_t rays = 0;
        return integrator.radiance(Ray{{x, y, 1.0f}, {0.0f, 0.0f, -1.0f}}, PathSamples(1, 0, 0, 0), rays);
    };
    // Ke 2 times each texel as read: NaN and negatives as 0, +inf as the largest finite value 3.
    CHECK(readsTexel(seen(0.25f, 0.75f), glm::vec3(2.0f, 1.0f, 0.5f)));
    CHECK(readsTexel(seen(0.75f, 0.75f), glm::vec3(0.0f, 2.0f, 2.0f)));
    CHECK(readsTexel(seen(0.25f, 0.25f), glm::vec3(6.0f, 0.0f, 0.0f)));
    CHECK(readsTexel(seen(0.75f, 0.25f), glm::vec3(0.0f, 4.0f, 6.0f)));
}

TEST_CASE("MTL names and words in messages have their control characters escaped") {
    const test::ScratchDir dir = test::scratchDir("obj_escaped_names");
    test::writeFile(dir / "quad.obj", "mtllib mtl/quad.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nusemtl \x1b]0;owned\x07\nf 1 2 3\n");
    test::writeFile(dir / "mtl" / "quad.mtl", "newmtl quad\nKd 0.5 0.5 0.5\n");
    const LoadedScene loaded = loadScene(dir / "quad.obj");
    CHECK(loaded.report.warnings ==
          std::vector<std::string>{(dir / "quad.obj").string() +
                                   ":5: material '\\x1b]0;owned\\x07' is not defined; using grey Kd 0.8"});
    test::writeFile(dir / "mtl" / "quad.mtl", "newmtl quad\nKd 0.5 \x1b[2J 0.5\n");
    CHECK_THROWS_WITH_AS(loadScene(dir / "quad.obj"),
                         ((dir / "mtl" / "quad.mtl").string() + ":2: '\\x1b[2J' is not a number").c_str(), Error);
}
