// What `strata bench --vs-cycles` writes for Blender, checked without Blender: the textures hold
// the texels Strata reads, the environment rotation makes Cycles' equirectangular lookup read
// Strata's texel, and the white-metal glTF is the material Cycles' Glossy BSDF computes.
#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <random>

#include "bench/cycles_inputs.h"
#include "io/image_io.h"
#include "lights/environment_map.h"
#include "lights/environment_map_light.h"
#include "scene/scene_loader.h"
#include "test_support.h"
#include "util/constants.h"
#include "util/error.h"

using namespace strata;
using namespace strata::test;

namespace {

// Cycles 3.4's direction_to_equirectangular (kernel/geom/geom.h's range (-2 pi, pi, ...)): u
// from +x toward -y, v up from the bottom row, the direction Z up.
glm::vec2 cyclesEquirectangular(const glm::vec3& d) {
    const double u = -std::atan2(double(d.y), double(d.x)) / (2.0 * kPi) + 0.5;
    const double v = std::atan2(double(d.z), std::hypot(double(d.x), double(d.y))) / kPi + 0.5;
    return {float(u), float(v)};
}

uint32_t u32(const std::string& bytes, size_t at) {
    uint32_t value = 0;
    std::memcpy(&value, bytes.data() + at, 4);
    return value;
}

std::string u32Bytes(uint32_t value) {
    std::string bytes(4, '\0');
    std::memcpy(bytes.data(), &value, 4);
    return bytes;
}

// One triangle in a binary glTF with two materials, one of them a red plastic, the other unused.
std::string triangleGlb() {
    const float positions[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
    const std::string bin(reinterpret_cast<const char*>(positions), sizeof(positions));
    const nlohmann::json gltf = {
        {"asset", {{"version", "2.0"}}},
        {"scene", 0},
        {"scenes", {{{"nodes", {0}}}}},
        {"nodes", {{{"mesh", 0}}}},
        {"meshes", {{{"primitives", {{{"attributes", {{"POSITION", 0}}}, {"material", 1}}}}}}},
        {"materials",
         {{{"name", "unused"}},
          {{"name", "red plastic"},
           {"pbrMetallicRoughness", {{"baseColorFactor", {0.8, 0.1, 0.1, 1.0}}, {"metallicFactor", 0.0}}}}}},
        {"buffers", {{{"byteLength", bin.size()}}}},
        {"bufferViews", {{{"buffer", 0}, {"byteLength", bin.size()}}}},
        {"accessors",
         {{{"bufferView", 0}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"},
           {"min", {0.0, 0.0, 0.0}}, {"max", {1.0, 1.0, 0.0}}}}}};
    std::string json = gltf.dump();
    json.append((4 - json.size() % 4) % 4, ' ');
    const std::string chunks = u32Bytes(uint32_t(json.size())) + "JSON" + json + u32Bytes(uint32_t(bin.size())) +
                               std::string("BIN\0", 4) + bin;
    return "glTF" + u32Bytes(2) + u32Bytes(uint32_t(12 + chunks.size())) + chunks;
}

}  // namespace

TEST_CASE("cycles inputs: a texture's EXR holds the linear texels Strata's lookups blend") {
    const auto dir = scratchDir("cycles-texture");
    // 3 x 2 sRGB-coded RGB texels, every code different, so a flipped or shifted row shows.
    std::vector<uint8_t> codes;
    for (int i = 0; i < 3 * 2 * 3; ++i) codes.push_back(static_cast<uint8_t>(10 + 13 * i));
    const Texture texture(3, 2, 3, codes, TextureEncoding::Colour);
    writeLinearTexture(texture, dir / "colour.exr");
    const Image image = readExr(dir / "colour.exr");
    REQUIRE(image.width == 3);
    REQUIRE(image.height == 2);
    const auto& srgb = srgbDecodingTable();
    for (int y = 0; y < 2; ++y) {
        for (int x = 0; x < 3; ++x) {
            const glm::vec3& written = image.pixels[size_t(y) * 3 + x];
            for (int c = 0; c < 3; ++c) {
                // Row 0 of the file is the texture's top row (v = 1), as Blender's loader expects.
                CHECK(written[c] == srgb[codes[(size_t(y) * 3 + x) * 3 + c]]);
                CHECK(written[c] == texture.texel(x, y)[c]);
            }
        }
    }
    // A grey (one-channel) texture is written as three equal channels, as a lookup widens it.
    const Texture grey(1, 1, 1, std::vector<uint8_t>{200}, TextureEncoding::Colour);
    writeLinearTexture(grey, dir / "grey.exr");
    CHECK(readExr(dir / "grey.exr").pixels[0] == glm::vec3(srgb[200]));
}

TEST_CASE("cycles inputs: through the frame, Cycles' equirectangular lookup reads Strata's texel") {
    // A 64 x 32 map whose texels are their own index: the texel read names the cell.
    constexpr int kWidth = 64, kHeight = 32;
    Image image;
    image.width = kWidth;
    image.height = kHeight;
    for (int i = 0; i < kWidth * kHeight; ++i) image.pixels.emplace_back(float(i), 0.0f, 0.0f);
    const auto map = std::make_shared<const EnvironmentMap>(image, "index.exr");
    std::mt19937 random(11);
    std::normal_distribution<float> normal;
    for (float rotation : {0.0f, 30.0f, -135.0f}) {
        const EnvironmentMapLight light(map, rotation, 1.0f);
        const glm::mat3 frame = cyclesEnvironmentFrame(rotation);
        // The axes first (where the conventions are easiest to get backwards), then random ones.
        std::vector<glm::vec3> directions = {{0.3f, 0.9f, -0.2f}, {0.9f, 0.1f, 0.2f}, {-0.9f, -0.1f, 0.3f},
                                             {0.1f, -0.2f, 0.95f}, {0.2f, 0.3f, -0.9f}};
        for (int i = 0; i < 200; ++i) directions.emplace_back(normal(random), normal(random), normal(random));
        int compared = 0;
        for (glm::vec3 d : directions) {
            d = glm::normalize(d);
            const glm::vec2 uv = cyclesEquirectangular(frame * d);
            const float column = uv.x * kWidth, row = (1.0f - uv.y) * kHeight;  // Blender: v = 1 is the top row
            // Directions within float noise of a texel edge can fall either side in either code.
            if (std::abs(column - std::round(column)) < 1e-3f || std::abs(row - std::round(row)) < 1e-3f) continue;
            const int cell = int(std::floor(row)) * kWidth + (int(std::floor(column)) % kWidth);
            CHECK_MESSAGE(light.emitted(d, {}).x == float(cell), "rotation ", rotation, ", direction ", d.x, " ",
                          d.y, " ", d.z);
            ++compared;
        }
        CHECK(compared > 190);
    }
    // A rotation, not a reflection: the image is not mirrored in Cycles either.
    CHECK(glm::determinant(cyclesEnvironmentFrame(30.0f)) == doctest::Approx(1.0));
}

TEST_CASE("cycles inputs: the white-metal glTF is the model with every material metal of one roughness") {
    const auto dir = scratchDir("cycles-white-metal");
    {
        std::ofstream(dir / "triangle.glb", std::ios::binary) << triangleGlb();
    }
    writeWhiteMetalGlb(dir / "triangle.glb", dir / "metal.glb", 0.3f);
    const std::string bytes = fileBytes(dir / "metal.glb");
    REQUIRE(bytes.size() > 28);
    CHECK(u32(bytes, 8) == bytes.size());
    const uint32_t jsonLength = u32(bytes, 12);
    CHECK(jsonLength % 4 == 0);
    const auto gltf = nlohmann::json::parse(bytes.substr(20, jsonLength));
    REQUIRE(gltf["materials"].size() == 1);
    const auto& pbr = gltf["materials"][0]["pbrMetallicRoughness"];
    CHECK(pbr["metallicFactor"] == 1.0);
    CHECK(pbr["roughnessFactor"].get<double>() == doctest::Approx(0.3));
    CHECK(pbr["baseColorFactor"] == nlohmann::json::array({1.0, 1.0, 1.0, 1.0}));
    CHECK(gltf["meshes"][0]["primitives"][0]["material"] == 0);
    // The binary chunk is carried over as it was.
    const std::string original = triangleGlb();
    CHECK(bytes.substr(20 + jsonLength) == original.substr(20 + u32(original, 12)));

    // Strata reads it as Ks = 1 (F0 = base colour), no diffuse, alpha = 0.3^2: the one glossy
    // material the script gives Cycles.
    const LoadedScene loaded = loadScene(dir / "metal.glb");
    REQUIRE(loaded.scene.mesh().materials.size() >= 1);
    const Material& metal = loaded.scene.mesh().materials[loaded.scene.mesh().triangleMaterials.at(0)];
    CHECK(metal.specular == glm::vec3(1.0f));
    CHECK(metal.diffuse == glm::vec3(0.0f));
    CHECK(metal.roughness == doctest::Approx(0.3f));

    std::ofstream(dir / "not.glb") << "{\"asset\": {}}";
    CHECK_THROWS_AS(writeWhiteMetalGlb(dir / "not.glb", dir / "out.glb", 0.3f), Error);
}

TEST_CASE("cycles inputs: the mesh OBJ holds Strata's world triangles, shared meshes at each placement") {
    const auto dir = scratchDir("cycles-mesh-obj");
    MeshData mesh;
    mesh.materials = {Material{}, Material{}};
    mesh.materials[0].name = "plain";
    mesh.materials[0].diffuse = glm::vec3(0.5f);
    mesh.materials[1].name = "placed";
    mesh.materials[1].diffuse = glm::vec3(0.25f);
    // Triangle 0, flat, in world coordinates; triangle 1, smooth, shared: moved up, and mirrored in x.
    mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 0}, {1, 0, 0}, {0, 0, 1}};
    mesh.triangles = {{0, 1, 2}, {3, 4, 5}};
    mesh.triangleMaterials = {0, 1};
    mesh.normals = {glm::normalize(glm::vec3(0.2f, -1.0f, 0.1f))};
    mesh.triangleNormals = {kNoNormals, {0, 0, 0}};
    glm::mat4 up(1.0f);
    up[3] = glm::vec4(0.0f, 2.0f, 0.0f, 1.0f);
    glm::mat4 mirror(1.0f);
    mirror[0][0] = -1.0f;
    mesh.sharedMeshes = {{1, 1, {up, mirror}}};
    writeMeshObj(mesh, dir / "mesh.obj");

    const LoadedScene loaded = loadScene(dir / "mesh.obj");
    const MeshData& read = loaded.scene.mesh();
    REQUIRE(read.triangles.size() == 3);
    REQUIRE(read.materials.size() == 2);
    int placed = 0;
    for (size_t t = 0; t < read.triangles.size(); ++t) {
        const auto& v = read.triangles[t];
        const glm::vec3 a = read.positions[v[0]], b = read.positions[v[1]], c = read.positions[v[2]];
        const glm::vec3 front = glm::cross(b - a, c - a);
        const std::string& name = read.materials[read.triangleMaterials[t]].name;
        if (name == "plain") {
            CHECK(a + b + c == glm::vec3(1.0f, 1.0f, 0.0f));
            CHECK(front.z > 0.0f);
            continue;
        }
        ++placed;
        const glm::vec3 n = read.normals[read.triangleNormals[t][0]];
        if (a.y == 2.0f) {  // moved up: the normal as it was
            CHECK(a + b + c == glm::vec3(1.0f, 6.0f, 1.0f));
            CHECK(n.x == doctest::Approx(mesh.normals[0].x));
        } else {  // mirrored: the normal's x turned, and the winding reversed so the front follows it
            CHECK(a + b + c == glm::vec3(-1.0f, 0.0f, 1.0f));
            CHECK(n.x == doctest::Approx(-mesh.normals[0].x));
        }
        CHECK(glm::dot(front, n) > 0.0f);  // the front where the normal points, mirrored or not
    }
    CHECK(placed == 2);
}
