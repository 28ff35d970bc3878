// The glTF loader (gltf_loader.h): models written here as .gltf (a base64 data: buffer) and .glb
// (assembled in memory), parsed from a bundle; and, when assimp's test models are installed,
// every glTF among them either loads or fails with one line naming the file.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>
#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>
#include <stb_image_write.h>
#include <webp/encode.h>

#include "io/image_io.h"
#include "materials/material_table.h"
#include "scene/gltf_loader.h"
#include "scene/scene.h"
#include "scene/scene_loader.h"
#include "util/error.h"
#include "scene/gltf_test_model.h"
#include "test_support.h"

using namespace strata;
using nlohmann::json;
using test::append;
using test::base64;
using test::bundleOf;
using test::errorOf;
using test::Model;

namespace {

constexpr float kHalfRoot2 = 0.70710678118654752f;

ParsedScene parse(const std::string& bytes, LoadReport* report = nullptr) {
    return parseGltfScene(bundleOf(bytes), report);
}

const std::vector<float> kTriangle{0, 0, 0, 1, 0, 0, 0, 1, 0};

glm::vec3 geometricNormal(const MeshData& mesh, size_t triangle) {
    const auto& t = mesh.triangles[triangle];
    return glm::normalize(glm::cross(mesh.positions[t[1]] - mesh.positions[t[0]],
                                     mesh.positions[t[2]] - mesh.positions[t[0]]));
}

void checkApprox(const glm::vec3& a, const glm::vec3& b) {
    CHECK(a.x == doctest::Approx(b.x));
    CHECK(a.y == doctest::Approx(b.y));
    CHECK(a.z == doctest::Approx(b.z));
}

}  // namespace

TEST_CASE("gltf: a triangle, positions exact, the spec's default material") {
    Model model;
    model.meshNode({{"attributes", {{"POSITION", model.positions(kTriangle)}}}});
    LoadReport report;
    const MeshData mesh = parse(model.gltf(), &report).mesh;
    REQUIRE(mesh.positions.size() == 3);
    CHECK(mesh.positions[1] == glm::vec3(1, 0, 0));
    CHECK(mesh.positions[2] == glm::vec3(0, 1, 0));
    REQUIRE(mesh.triangles.size() == 1);
    CHECK(mesh.triangles[0] == std::array<uint32_t, 3>{0, 1, 2});
    CHECK(mesh.normals.empty());
    CHECK(mesh.triangleNormals.empty());
    // Base colour 1, metallic 1, roughness 1: a rough white metal.
    REQUIRE(mesh.materials.size() == 1);
    CHECK(mesh.triangleMaterials[0] == 0);
    CHECK(mesh.materials[0].diffuse == glm::vec3(0.0f));
    CHECK(mesh.materials[0].specular == glm::vec3(1.0f));
    CHECK(mesh.materials[0].roughness == 1.0f);
    CHECK(report.faces == 1);
    CHECK(report.warnings.empty());
}

TEST_CASE("gltf: an indexed quad in a .glb, indices of every type") {
    for (int componentType : {5121, 5123, 5125}) {
        CAPTURE(componentType);
        Model model;
        const int positions = model.positions({0, 0, 0, 2, 0, 0, 2, 3, 0, 0, 3, 0});
        const std::vector<uint32_t> corners{0, 1, 2, 0, 2, 3};
        int indices = 0;
        if (componentType == 5121) indices = model.accessor(std::vector<uint8_t>(corners.begin(), corners.end()), "SCALAR", 5121, 6);
        if (componentType == 5123) indices = model.accessor(std::vector<uint16_t>(corners.begin(), corners.end()), "SCALAR", 5123, 6);
        if (componentType == 5125) indices = model.accessor(corners, "SCALAR", 5125, 6);
        model.meshNode({{"attributes", {{"POSITION", positions}}}, {"indices", indices}});
        const MeshData mesh = parseGltfScene(bundleOf(model.glb(), "model.glb")).mesh;
        REQUIRE(mesh.triangles.size() == 2);
        CHECK(mesh.triangles[1] == std::array<uint32_t, 3>{0, 2, 3});
        CHECK(mesh.positions[2] == glm::vec3(2, 3, 0));
    }
}

TEST_CASE("gltf: quantized positions and normals (KHR_mesh_quantization)") {
    Model model;
    const int positions = model.accessor(std::vector<uint16_t>{0, 0, 0, 2, 0, 0, 0, 3, 0}, "VEC3", 5123, 3);
    const int normals = model.accessor(std::vector<int8_t>{0, 0, 127, 0, 0, -128, 0, 127, 0}, "VEC3", 5120, 3);
    model.doc["accessors"][normals]["normalized"] = true;
    model.doc["extensionsUsed"] = {"KHR_mesh_quantization"};
    model.doc["extensionsRequired"] = {"KHR_mesh_quantization"};
    model.meshNode({{"attributes", {{"POSITION", positions}, {"NORMAL", normals}}}});
    const MeshData mesh = parse(model.gltf()).mesh;
    REQUIRE(mesh.positions.size() == 3);
    CHECK(mesh.positions[1] == glm::vec3(2, 0, 0));
    CHECK(mesh.positions[2] == glm::vec3(0, 3, 0));
    CHECK(mesh.normals[0] == glm::vec3(0, 0, 1));
    CHECK(mesh.normals[1] == glm::vec3(0, 0, -1));  // -128 clamps to -1
    // Normals must be normalized integers: plain bytes are refused.
    model.doc["accessors"][normals]["normalized"] = false;
    CHECK(errorOf(model.gltf()) == "mem/model.gltf: mesh 'm0' (0) primitive 0: NORMAL accessor 1 has component "
                                     "type 5120, which glTF does not allow for it");
}

TEST_CASE("gltf: interleaved positions (byteStride), strips and fans as triangles") {
    Model model;
    // Four vertices, each followed by a float of something else.
    const int view = 0;
    model.doc["bufferViews"].push_back({{"buffer", 0}, {"byteLength", 64}, {"byteStride", 16}});
    append(model.bin, std::vector<float>{0, 0, 0, 9, 1, 0, 0, 9, 0, 1, 0, 9, 1, 1, 0, 9});
    model.doc["accessors"].push_back({{"bufferView", view}, {"componentType", 5126}, {"count", 4}, {"type", "VEC3"}});
    model.meshNode({{"attributes", {{"POSITION", 0}}}, {"mode", 5}});
    model.meshNode({{"attributes", {{"POSITION", 0}}}, {"mode", 6}});
    const MeshData mesh = parse(model.gltf()).mesh;
    REQUIRE(mesh.triangles.size() == 4);
    CHECK(mesh.positions[3] == glm::vec3(1, 1, 0));
    CHECK(mesh.triangles[0] == std::array<uint32_t, 3>{0, 1, 2});
    CHECK(mesh.triangles[1] == std::array<uint32_t, 3>{1, 3, 2});  // the strip's winding kept
    CHECK(mesh.triangles[2] == std::array<uint32_t, 3>{5, 6, 4});  // the fan about its first
    CHECK(mesh.triangles[3] == std::array<uint32_t, 3>{6, 7, 4});
}

TEST_CASE("gltf: node transforms, T*R*S and matrix, through the hierarchy") {
    Model model;
    const int positions = model.positions(kTriangle);
    const json primitive = {{"attributes", {{"POSITION", positions}}}};
    // Scale 2, then 90 degrees about z, then translate (1, 2, 3): (1,0,0) -> (1,4,3).
    model.meshNode(primitive, {{"translation", {1, 2, 3}}, {"rotation", {0, 0, kHalfRoot2, kHalfRoot2}}, {"scale", {2, 2, 2}}});
    // A child's matrix (column-major: translate by (0,0,10)) under a parent's translation (5,0,0).
    model.doc["meshes"].push_back({{"primitives", json::array({primitive})}});
    const int child = model.addNode({{"mesh", 1}, {"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 10, 1}}}, false);
    model.addNode({{"translation", {5, 0, 0}}, {"children", {child}}});
    // The two nodes use one primitive: stored once, placed twice.
    const MeshData mesh = parse(model.gltf()).mesh;
    REQUIRE(mesh.positions.size() == 3);
    REQUIRE(mesh.sharedMeshes.size() == 1);
    REQUIRE(mesh.sharedMeshes[0].placements.size() == 2);
    const auto placed = [&](size_t placement, size_t vertex) {
        return glm::vec3(mesh.sharedMeshes[0].placements[placement] * glm::vec4(mesh.positions[vertex], 1.0f));
    };
    checkApprox(placed(0, 0), {1, 2, 3});
    checkApprox(placed(0, 1), {1, 4, 3});
    checkApprox(placed(0, 2), {-1, 2, 3});
    CHECK(placed(1, 1) == glm::vec3(6, 0, 10));
    CHECK(geometricNormal(mesh, 0).z == doctest::Approx(1.0f));
    // Used once each, the primitives are flattened into world space as they always were.
    model.doc["meshes"][1]["primitives"][0]["material"] = 0;
    model.doc["materials"] = json::array({json::object()});
    const MeshData flat = parse(model.gltf()).mesh;
    REQUIRE(flat.positions.size() == 6);
    CHECK(flat.sharedMeshes.empty());
    checkApprox(flat.positions[1], {1, 4, 3});
    CHECK(flat.positions[4] == glm::vec3(6, 0, 10));
}

TEST_CASE("gltf: a negative determinant flips the winding, so the front stays the front") {
    Model model;
    model.meshNode({{"attributes", {{"POSITION", model.positions(kTriangle)}}}}, {{"scale", {-1, 1, 1}}});
    const MeshData mesh = parse(model.gltf()).mesh;
    REQUIRE(mesh.triangles.size() == 1);
    CHECK(mesh.positions[1] == glm::vec3(-1, 0, 0));
    CHECK(mesh.triangles[0] == std::array<uint32_t, 3>{0, 2, 1});
    CHECK(geometricNormal(mesh, 0) == glm::vec3(0, 0, 1));
}

TEST_CASE("gltf: normals go through the inverse transpose, per corner") {
    Model model;
    const int positions = model.positions(kTriangle);
    const int normals = model.accessor(std::vector<float>{0, 0, 1, kHalfRoot2, kHalfRoot2, 0, 0, 0, 1}, "VEC3", 5126, 3);
    model.meshNode({{"attributes", {{"POSITION", positions}, {"NORMAL", normals}}}}, {{"scale", {2, 1, 1}}});
    const MeshData mesh = parse(model.gltf()).mesh;
    REQUIRE(mesh.normals.size() == 3);
    REQUIRE(mesh.triangleNormals.size() == 1);
    CHECK(mesh.triangleNormals[0] == std::array<uint32_t, 3>{0, 1, 2});
    CHECK(mesh.normals[0] == glm::vec3(0, 0, 1));
    // (1, 1, 0) under diag(1/2, 1, 1), unit: (1, 2, 0) / sqrt 5.
    checkApprox(mesh.normals[1], glm::vec3(1, 2, 0) / std::sqrt(5.0f));
}

TEST_CASE("gltf: metallic-roughness factors onto Kd, Ks, Pr, and emission times its strength") {
    Model model;
    const int positions = model.positions(kTriangle);
    model.doc["materials"] = json::array({
        {{"name", "plastic"},
         {"pbrMetallicRoughness", {{"baseColorFactor", {0.5, 0.25, 1, 1}}, {"metallicFactor", 0}, {"roughnessFactor", 0.3}}}},
        {{"name", "gold"},
         {"pbrMetallicRoughness", {{"baseColorFactor", {1, 0.75, 0.25, 1}}, {"metallicFactor", 1}, {"roughnessFactor", 0.5}}}},
        {{"name", "lamp"},
         {"emissiveFactor", {1, 0.5, 0}},
         {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 4}}}}}},
    });
    for (int m = 0; m < 3; ++m) model.meshNode({{"attributes", {{"POSITION", positions}}}, {"material", m}});
    const MeshData mesh = parse(model.gltf()).mesh;
    REQUIRE(mesh.materials.size() == 3);
    CHECK(mesh.triangleMaterials == std::vector<uint32_t>{0, 1, 2});
    const Material& plastic = mesh.materials[0];
    CHECK(plastic.name == "plastic");
    CHECK(plastic.diffuse == glm::vec3(0.5f, 0.25f, 1.0f));
    CHECK(plastic.specular == glm::vec3(0.04f));
    CHECK(plastic.roughness == 0.3f);
    CHECK(plastic.emission == glm::vec3(0.0f));
    const Material& gold = mesh.materials[1];
    CHECK(gold.diffuse == glm::vec3(0.0f));
    CHECK(gold.specular == glm::vec3(1.0f, 0.75f, 0.25f));
    CHECK(gold.roughness == 0.5f);
    // Defaults: base colour 1 and metallic 1, so no diffuse; emission 4 x (1, 0.5, 0).
    CHECK(mesh.materials[2].emission == glm::vec3(4.0f, 2.0f, 0.0f));
    CHECK(mesh.materials[2].diffuse == glm::vec3(0.0f));
}

TEST_CASE("gltf: transmission, ior, volume, specular and clearcoat onto the dielectric, its volume and the coat") {
    Model model;
    const int positions = model.positions(kTriangle);
    model.doc["extensionsUsed"] = {"KHR_materials_transmission", "KHR_materials_ior", "KHR_materials_volume",
                                   "KHR_materials_specular", "KHR_materials_clearcoat", "EXT_unknown_thing"};
    const json base = {{"baseColorFactor", {0.9, 0.8, 0.7, 1}}, {"metallicFactor", 0}, {"roughnessFactor", 0}};
    model.doc["materials"] = json::array({
        {{"name", "glass"},
         {"pbrMetallicRoughness", base},
         {"extensions",
          {{"KHR_materials_transmission", {{"transmissionFactor", 1}}},
           {"KHR_materials_ior", {{"ior", 1.33}}},
           {"KHR_materials_volume", {{"thicknessFactor", 0.5}, {"attenuationDistance", 2}, {"attenuationColor", {0.5, 1, 1}}}}}}},
        {{"name", "pane"}, {"pbrMetallicRoughness", base}, {"extensions", {{"KHR_materials_transmission", {{"transmissionFactor", 0.5}}}}}},
        {{"name", "coated"},
         {"pbrMetallicRoughness", {{"baseColorFactor", {0.5, 0.1, 0.1, 1}}, {"metallicFactor", 0}, {"roughnessFactor", 0.5}}},
         {"extensions",
          {{"KHR_materials_clearcoat", {{"clearcoatFactor", 0.8}, {"clearcoatRoughnessFactor", 0.1}}},
           {"KHR_materials_specular", {{"specularFactor", 0.5}, {"specularColorFactor", {1, 0.5, 0.5}}}}}}},
        {{"name", "chrome"}, {"pbrMetallicRoughness", {{"baseColorFactor", {0.9, 0.9, 0.9, 1}}, {"metallicFactor", 1}, {"roughnessFactor", 0}}}},
    });
    for (int m = 0; m < 4; ++m) model.meshNode({{"attributes", {{"POSITION", positions}}}, {"material", m}});
    LoadReport report;
    const MeshData mesh = parse(model.gltf(), &report).mesh;
    REQUIRE(mesh.materials.size() == 4);
    const Material& glass = mesh.materials[0];
    CHECK(glass.transmission == 1.0f);
    CHECK(glass.ior == doctest::Approx(1.33));
    CHECK(glass.transmissionFilter == glm::vec3(0.9f, 0.8f, 0.7f));
    CHECK_FALSE(glass.thinWalled);
    CHECK(glass.attenuationDistance == 2.0f);
    CHECK(glass.attenuationColor == glm::vec3(0.5f, 1.0f, 1.0f));
    const Material& pane = mesh.materials[1];
    CHECK(pane.transmission == 0.5f);
    CHECK(pane.thinWalled);  // no KHR_materials_volume
    const Material& coated = mesh.materials[2];
    CHECK(coated.clearcoat == 0.8f);
    CHECK(coated.clearcoatRoughness == doctest::Approx(0.1));
    checkApprox(coated.specular, glm::vec3(0.02f, 0.01f, 0.01f));  // 0.04 x (1, 0.5, 0.5) x 0.5
    const MaterialTable table(mesh.materials);
    CHECK(table.bsdf(0).as<SmoothDielectric>() != nullptr);
    CHECK(table.bsdf(0).as<SmoothDielectric>()->eta() == doctest::Approx(1.33));
    CHECK(table.bsdf(0, {}, false).as<SmoothDielectric>()->eta() == doctest::Approx(1.0 / 1.33));
    // Beer-Lambert: exp(-sigma 2) = attenuationColor.
    CHECK(std::exp(-2.0f * table.absorption(0).x) == doctest::Approx(0.5));
    CHECK(table.absorption(0).y == 0.0f);
    CHECK(table.bsdf(1).as<TransmissionBlend<ThinDielectric>>() != nullptr);
    CHECK(table.bsdf(2).as<Coated<LayeredBsdf>>() != nullptr);
    CHECK(table.bsdf(3).as<SmoothConductor>() != nullptr);
    // The extensions read are not warned about; one that is not read is.
    int unread = 0;
    for (const std::string& warning : report.warnings) {
        INFO(warning);
        CHECK(warning.find("KHR_materials") == std::string::npos);
        if (warning.find("EXT_unknown_thing") != std::string::npos) ++unread;
    }
    CHECK(unread == 1);
}

// The BSDF of the textured material at `uv` is that of the untextured `expected`: the same values
// in two pairs of directions.
void checkSameBsdf(const Material& textured, glm::vec2 uv, const Material& expected) {
    const MaterialTable table({textured, expected});
    const glm::vec3 wo = glm::normalize(glm::vec3(0.3f, 0.1f, 0.9f));
    for (const glm::vec3& wi : {glm::vec3(0.0f, 0.0f, 1.0f), glm::normalize(glm::vec3(-0.6f, 0.2f, 0.5f))}) {
        const glm::vec3 atTexel = table.bsdf(0, uv).evaluate(wo, wi);
        const glm::vec3 constant = table.bsdf(1).evaluate(wo, wi);
        for (int c = 0; c < 3; ++c) CHECK(atTexel[c] == doctest::Approx(constant[c]).epsilon(1e-5));
    }
}

// A PNG of 8-bit RGBA pixels in memory.
std::string rgbaPng(int width, int height, const std::vector<unsigned char>& pixels) {
    std::string out;
    stbi_write_png_to_func(
        [](void* context, void* data, int size) {
            static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<size_t>(size));
        },
        &out, width, height, 4, pixels.data(), width * 4);
    return out;
}

// A triangle whose corners all have UV (0.5, 0.5), so that every texture is read at one texel,
// with material `material`; and 1 x 1 RGBA PNGs (data: URIs) as the model's images, each the
// source of the texture of the same index.
json triangleAtOneTexel(Model& model, int material) {
    const int positions = model.positions(kTriangle);
    const int uvs = model.accessor(std::vector<float>(6, 0.5f), "VEC2", 5126, 3);
    return {{"attributes", {{"POSITION", positions}, {"TEXCOORD_0", uvs}}}, {"material", material}};
}
void addPngTextures(Model& model, const std::vector<std::vector<unsigned char>>& texels) {
    for (const auto& texel : texels) {
        model.doc["images"].push_back({{"uri", "data:image/png;base64," + base64(rgbaPng(1, 1, texel))}});
        model.doc["textures"].push_back({{"source", model.doc["textures"].size()}});
    }
}

TEST_CASE("gltf: base colour, metallic-roughness and emissive textures at TEXCOORD_0, MASK alpha cut-outs") {
    Model model;
    const int positions = model.positions(kTriangle);
    // glTF's v runs down: texel row 0 is at v = 0, stored as 1 - v.
    const int uvs = model.accessor(std::vector<float>{0.25f, 0.5f, 0.75f, 0.5f, 0.25f, 0.5f}, "VEC2", 5126, 3);
    // Base colour: left texel red with alpha 255, right texel green with alpha 0 (cut out).
    // Metallic-roughness: G = roughness 128/255... of 0.5 factor, B = metallic 255 (a metal).
    model.doc["images"] = json::array({
        {{"uri", "data:image/png;base64," + base64(rgbaPng(2, 1, {255, 0, 0, 255, 0, 255, 0, 0}))}},
        {{"uri", "data:image/png;base64," + base64(rgbaPng(1, 1, {0, 255, 255, 255}))}},
        {{"uri", "data:image/png;base64," + base64(std::string("not a PNG"))}},
    });
    model.doc["textures"] = json::array({{{"source", 0}}, {{"source", 1}}, {{"source", 2}}});
    model.doc["materials"] = json::array({
        {{"pbrMetallicRoughness",
          {{"baseColorTexture", {{"index", 0}}}, {"metallicRoughnessTexture", {{"index", 1}}},
           {"baseColorFactor", {0.5, 1.0, 1.0, 1.0}}, {"metallicFactor", 0.0}, {"roughnessFactor", 0.5}}},
         {"alphaMode", "MASK"}, {"alphaCutoff", 0.25}},
        {{"emissiveTexture", {{"index", 2}}}, {"emissiveFactor", {1.0, 1.0, 1.0}}, {"alphaMode", "BLEND"}},
    });
    model.meshNode({{"attributes", {{"POSITION", positions}, {"TEXCOORD_0", uvs}}}, {"material", 0}});
    model.meshNode({{"attributes", {{"POSITION", positions}}}, {"material", 1}});
    LoadReport report;
    const MeshData mesh = parse(model.gltf(), &report).mesh;
    CHECK(report.warnings == std::vector<std::string>{
                                 "mem/model.gltf: material '' (1) emissiveTexture: image 2: cannot decode the texture "
                                 "(unknown image type); using the factor alone"});
    REQUIRE(mesh.uvs.size() == 3);
    CHECK(mesh.uvs[0] == glm::vec2(0.25f, 0.5f));  // 1 - 0.5
    const Material& m = mesh.materials[0];
    REQUIRE(m.textures.colour);
    REQUIRE(m.textures.roughness);
    CHECK(m.textures.metallic == m.textures.roughness);
    CHECK(m.textures.roughnessChannel == 1);
    CHECK(m.textures.metallicChannel == 2);
    REQUIRE(m.metallicRoughness);
    CHECK(m.metallicRoughness->baseColor == glm::vec3(0.5f, 1.0f, 1.0f));
    // Coverage is the base colour's alpha against the cutoff.
    CHECK_FALSE(m.cutOut({0.25f, 0.5f}));
    CHECK(m.cutOut({0.75f, 0.5f}));
    // The per-hit BSDF: base colour (0.5, 0, 0) at the red texel, metallic 0 x 1 = 0: a dielectric.
    const MaterialTable table(mesh.materials);
    const Bsdf bsdf = table.bsdf(0, {0.25f, 0.5f});
    const LayeredBsdf& red = *bsdf.as<LayeredBsdf>();
    const glm::vec3 albedo = red.albedo({0.0f, 0.0f, 1.0f});
    CHECK(albedo.x > albedo.y);
    CHECK(albedo.y == albedo.z);
    // Roughness 0.5 x 1 quantised to level 8 of 16: exactly 0.5, the factor's own lobe.
    CHECK(red.lobe()->distribution.alpha() == doctest::Approx(0.25));
    CHECK(!mesh.materials[1].textures.emission);
    // BLEND, an emitter's as any other's, with a base colour alpha factor of 1 and no texture:
    // wholly opaque, no coverage to test.
    CHECK_FALSE(mesh.materials[1].textures.coverage);
}

TEST_CASE("gltf: alphaMode BLEND is an opacity, the base colour's alpha factor times its texture's") {
    Model model;
    const int positions = model.positions(kTriangle);
    const int uvs = model.accessor(std::vector<float>{0.25f, 0.5f, 0.25f, 0.5f, 0.25f, 0.5f}, "VEC2", 5126, 3);
    model.doc["images"] = json::array({{{"uri", "data:image/png;base64," + base64(rgbaPng(1, 1, {255, 255, 255, 128}))}}});
    model.doc["textures"] = json::array({{{"source", 0}}});
    model.doc["materials"] = json::array({
        {{"pbrMetallicRoughness", {{"baseColorFactor", {1.0, 1.0, 1.0, 0.4}}}}, {"alphaMode", "BLEND"}},
        {{"pbrMetallicRoughness", {{"baseColorFactor", {1.0, 1.0, 1.0, 0.5}}, {"baseColorTexture", {{"index", 0}}}}},
         {"alphaMode", "BLEND"}},
        {{"alphaMode", "BLEND"}},
    });
    for (int m = 0; m < 3; ++m) {
        model.meshNode({{"attributes", {{"POSITION", positions}, {"TEXCOORD_0", uvs}}}, {"material", m}});
    }
    LoadReport report;
    const MeshData mesh = parse(model.gltf(), &report).mesh;
    CHECK(report.warnings.empty());
    const Material& factor = mesh.materials[0];
    REQUIRE(factor.textures.coverage);
    CHECK(factor.textures.blended);
    CHECK(factor.textures.opacity == 0.4f);
    // Cut out where the number the ray gives is at least the opacity.
    CHECK_FALSE(factor.cutOut({0.5f, 0.5f}, 0.39f));
    CHECK(factor.cutOut({0.5f, 0.5f}, 0.4f));
    // 0.5 x 128/255.
    const Material& textured = mesh.materials[1];
    CHECK(textured.textures.blended);
    CHECK_FALSE(textured.cutOut({0.25f, 0.5f}, 0.25f));
    CHECK(textured.cutOut({0.25f, 0.5f}, 0.26f));
    // Opaque throughout: nothing to test, no cut-out geometry.
    CHECK_FALSE(mesh.materials[2].textures.coverage);
}

TEST_CASE("gltf: KHR_materials_pbrSpecularGlossiness onto Kd, Ks and Pr, in place of its fallback") {
    Model model;
    const int positions = model.positions(kTriangle);
    const int uvs = model.accessor(std::vector<float>{0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f}, "VEC2", 5126, 3);
    model.doc["extensionsUsed"] = {"KHR_materials_pbrSpecularGlossiness"};
    // Codes 255 and 0 decode to 1 and 0 exactly in sRGB; the glossiness alpha 51 is 0.2, linear.
    model.doc["images"] = json::array({
        {{"uri", "data:image/png;base64," + base64(rgbaPng(1, 1, {255, 255, 0, 255}))}},
        {{"uri", "data:image/png;base64," + base64(rgbaPng(1, 1, {255, 0, 255, 51}))}},
        {{"uri", "absent.png"}},
    });
    model.doc["textures"] = json::array({{{"source", 0}}, {{"source", 1}}, {{"source", 2}}});
    // The fallback's texture is missing: it is not read, so nothing warns of it.
    const json fallback = {{"baseColorTexture", {{"index", 2}}}, {"metallicFactor", 0}};
    model.doc["materials"] = json::array({
        {{"pbrMetallicRoughness", fallback},
         {"alphaMode", "MASK"},
         {"extensions",
          {{"KHR_materials_pbrSpecularGlossiness",
            {{"diffuseFactor", {0.5, 0.6, 0.8, 0.2}}, {"specularFactor", {0.2, 0.4, 0.1}}, {"glossinessFactor", 0.75}}}}}},
        {{"pbrMetallicRoughness", fallback},
         {"extensions",
          {{"KHR_materials_pbrSpecularGlossiness",
            {{"diffuseTexture", {{"index", 0}}}, {"specularFactor", {0.5, 0.5, 0.5}},
             {"specularGlossinessTexture", {{"index", 1}}}}}}}},
    });
    for (int m = 0; m < 2; ++m) {
        model.meshNode({{"attributes", {{"POSITION", positions}, {"TEXCOORD_0", uvs}}}, {"material", m}});
    }
    LoadReport report;
    const MeshData mesh = parse(model.gltf(), &report).mesh;
    CHECK(report.warnings.empty());
    // Kd = diffuse (1 - max specular), Ks = specular, Pr = 1 - glossiness.
    const Material& factors = mesh.materials[0];
    checkApprox(factors.diffuse, glm::vec3(0.3f, 0.36f, 0.48f));
    CHECK(factors.specular == glm::vec3(0.2f, 0.4f, 0.1f));
    CHECK(factors.roughness == doctest::Approx(0.25));
    CHECK_FALSE(factors.metallicRoughness);
    // MASK reads the diffuse factor's alpha: 0.2 < 0.5.
    CHECK(factors.cutOut({0.5f, 0.5f}));
    // Textured: at the texel, diffuse (1, 1, 0), specular 0.5 x (1, 0, 1), glossiness 1 x 0.2,
    // so Kd = (0.5, 0.5, 0), Ks = (0.5, 0, 0.5) and Pr 0.8, quantised to 13/16.
    const Material& textured = mesh.materials[1];
    REQUIRE(textured.textures.colour);
    REQUIRE(textured.textures.specularGlossiness);
    REQUIRE(textured.specularGlossiness);
    Material expected;
    expected.diffuse = glm::vec3(0.5f, 0.5f, 0.0f);
    expected.specular = glm::vec3(0.5f, 0.0f, 0.5f);
    expected.roughness = 13.0f / 16.0f;
    checkSameBsdf(textured, {0.5f, 0.5f}, expected);
    // A malformed factor is named.
    model.doc["materials"][0]["extensions"]["KHR_materials_pbrSpecularGlossiness"]["specularFactor"] = {0.2, 0.4};
    CHECK_THROWS_WITH_AS(parse(model.gltf()),
                         "mem/model.gltf: material '' (0): KHR_materials_pbrSpecularGlossiness: specularFactor needs 3 "
                         "numbers in 0..1",
                         Error);
}

TEST_CASE("gltf: KHR_materials_specular's textures scale the dielectric's F0 at each hit") {
    Model model;
    model.doc["extensionsUsed"] = {"KHR_materials_specular"};
    // The factor texel: alpha 51 = 0.2 (linear); the colour texel: 255, 0, 255 = 1, 0, 1 (sRGB).
    addPngTextures(model, {{0, 0, 0, 51}, {255, 0, 255, 255}});
    model.doc["materials"] = json::array({
        {{"pbrMetallicRoughness", {{"baseColorFactor", {0.5, 0.5, 0.5, 1}}, {"metallicFactor", 0}, {"roughnessFactor", 0.5}}},
         {"extensions",
          {{"KHR_materials_specular",
            {{"specularFactor", 0.5}, {"specularColorFactor", {30, 1, 1}}, {"specularTexture", {{"index", 0}}},
             {"specularColorTexture", {{"index", 1}}}}}}}},
    });
    model.meshNode(triangleAtOneTexel(model, 0));
    LoadReport report;
    const MeshData mesh = parse(model.gltf(), &report).mesh;
    CHECK(report.warnings.empty());
    const Material& m = mesh.materials[0];
    REQUIRE(m.textures.specular);
    REQUIRE(m.textures.specularColour);
    REQUIRE(m.metallicRoughness);
    // Untextured: min(0.04 x (30, 1, 1), 1) x 0.5.
    checkApprox(m.specular, glm::vec3(0.5f, 0.02f, 0.02f));
    // At the texel: min(0.04 x (30, 1, 1) x (1, 0, 1), 1) x 0.5 x 0.2 = (0.1, 0, 0.004).
    Material expected;
    expected.diffuse = glm::vec3(0.5f);
    expected.specular = glm::vec3(0.1f, 0.0f, 0.004f);
    expected.roughness = 0.5f;
    checkSameBsdf(m, {0.5f, 0.5f}, expected);
}

TEST_CASE("gltf: KHR_materials_sheen's factors and textures onto the sheen, which a transmitting material does without") {
    Model model;
    model.doc["extensionsUsed"] = {"KHR_materials_sheen", "KHR_materials_transmission"};
    // The colour texel 255, 0, 255 = 1, 0, 1 (sRGB); the roughness texel's alpha 128 = 0.502 (linear).
    addPngTextures(model, {{255, 0, 255, 255}, {0, 0, 0, 128}});
    const json base = {{"baseColorFactor", {0.2, 0.1, 0.3, 1}}, {"metallicFactor", 0}, {"roughnessFactor", 0.6}};
    const json sheen = {{"sheenColorFactor", {1, 0.5, 0.25}}, {"sheenRoughnessFactor", 0.8}};
    json textured = sheen;
    textured["sheenColorTexture"] = {{"index", 0}};
    textured["sheenRoughnessTexture"] = {{"index", 1}};
    model.doc["materials"] = json::array({
        {{"name", "velvet"}, {"pbrMetallicRoughness", base}, {"extensions", {{"KHR_materials_sheen", sheen}}}},
        {{"name", "printed"}, {"pbrMetallicRoughness", base}, {"extensions", {{"KHR_materials_sheen", textured}}}},
        {{"name", "glass"},
         {"pbrMetallicRoughness", base},
         {"extensions", {{"KHR_materials_sheen", sheen}, {"KHR_materials_transmission", {{"transmissionFactor", 1}}}}}},
    });
    for (int m = 0; m < 3; ++m) model.meshNode(triangleAtOneTexel(model, m));
    LoadReport report;
    const MeshData mesh = parse(model.gltf(), &report).mesh;
    // The one warning that names the extension: read, but not applied to the glass.
    const auto sheenWarnings = std::count_if(report.warnings.begin(), report.warnings.end(), [](const std::string& w) {
        return w.find("KHR_materials_sheen") != std::string::npos;
    });
    CHECK(sheenWarnings == 1);
    CHECK(std::count(report.warnings.begin(), report.warnings.end(),
                     "mem/model.gltf: material 'glass' (2): KHR_materials_sheen: not applied to a transmitting or "
                     "perfectly smooth (roughness 0) material") == 1);
    const Material& velvet = mesh.materials[0];
    CHECK(velvet.sheenColour == glm::vec3(1.0f, 0.5f, 0.25f));
    CHECK(velvet.sheenRoughness == doctest::Approx(0.8));
    const MaterialTable table(mesh.materials);
    CHECK(table.bsdf(0).as<Sheened>() != nullptr);
    CHECK(table.bsdf(2).as<Sheened>() == nullptr);
    // At the texel: colour (1, 0.5, 0.25) x (1, 0, 1), roughness 0.8 x 0.502 quantised to 6/16.
    const Material& printed = mesh.materials[1];
    REQUIRE(printed.textures.sheenColour);
    REQUIRE(printed.textures.sheenRoughness);
    Material expected = printed;
    expected.textures = {};
    expected.metallicRoughness.reset();
    expected.sheenColour = glm::vec3(1.0f, 0.0f, 0.25f);
    expected.sheenRoughness = 6.0f / 16.0f;
    checkSameBsdf(printed, {0.5f, 0.5f}, expected);
}

TEST_CASE("gltf: a texture's sampler sets its wrap modes and nearest filter, an unknown mode repeats with a warning") {
    Model model;
    addPngTextures(model, {{255, 0, 255, 255}, {0, 255, 0, 255}, {0, 0, 255, 255}});
    model.doc["samplers"] = json::array({{{"wrapS", 33071}, {"wrapT", 33648}, {"magFilter", 9728}},
                                         {{"wrapS", 10497}, {"wrapT", 12345}, {"magFilter", 9729}}});
    model.doc["textures"][0]["sampler"] = 0;
    model.doc["textures"][1]["sampler"] = 1;
    model.doc["materials"] = json::array({
        {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}, {"metallicRoughnessTexture", {{"index", 1}}}}},
         {"emissiveTexture", {{"index", 2}}}, {"emissiveFactor", {1, 1, 1}}},
    });
    model.meshNode(triangleAtOneTexel(model, 0));
    LoadReport report;
    const MeshData mesh = parse(model.gltf(), &report).mesh;
    const MaterialTextures& maps = mesh.materials[0].textures;
    REQUIRE(maps.colour);
    CHECK(maps.colour->sampling().u == TextureWrap::ClampToEdge);
    CHECK(maps.colour->sampling().v == TextureWrap::MirroredRepeat);
    CHECK(maps.colour->sampling().nearest);  // magFilter NEAREST
    CHECK_FALSE(maps.roughness->sampling().nearest);  // LINEAR
    REQUIRE(maps.roughness);
    CHECK(maps.roughness->sampling().u == TextureWrap::Repeat);
    CHECK(maps.roughness->sampling().v == TextureWrap::Repeat);
    REQUIRE(maps.emission);  // no sampler: repeat
    CHECK(maps.emission->sampling().u == TextureWrap::Repeat);
    CHECK(report.warnings == std::vector<std::string>{
                                 "mem/model.gltf: material '' (0) metallicRoughnessTexture: sampler 1 has an unknown wrapT "
                                 "12345; the texture repeats"});
}

TEST_CASE("gltf: KHR_materials_unlit shows the base colour and its texture, every other property dropped") {
    Model model;
    model.doc["extensionsUsed"] = {"KHR_materials_unlit", "KHR_materials_clearcoat"};
    model.doc["extensionsRequired"] = {"KHR_materials_unlit"};
    addPngTextures(model, {{255, 0, 255, 255}});
    model.doc["materials"] = json::array({
        {{"pbrMetallicRoughness",
          {{"baseColorFactor", {0.5, 0.25, 1, 1}}, {"baseColorTexture", {{"index", 0}}}, {"metallicFactor", 1}}},
         {"emissiveFactor", {1, 1, 1}},
         {"extensions", {{"KHR_materials_unlit", json::object()}, {"KHR_materials_clearcoat", {{"clearcoatFactor", 1}}}}}},
    });
    model.meshNode(triangleAtOneTexel(model, 0));
    LoadReport report;
    const MeshData mesh = parse(model.gltf(), &report).mesh;
    CHECK(report.warnings.empty());
    const Material& m = mesh.materials[0];
    CHECK(m.unlit);
    CHECK(m.diffuse == glm::vec3(0.5f, 0.25f, 1.0f));
    CHECK(m.emission == glm::vec3(0.0f));
    CHECK(m.clearcoat == 0.0f);
    CHECK(m.textures.colour);
    CHECK_FALSE(emitsLight(m));
    const MaterialTable table(mesh.materials);
    CHECK(table.isUnlit(0));
    CHECK(table.isBlack(0));
    checkApprox(table.unlitColour(0, {0.5f, 0.5f}, glm::vec3(1.0f, 1.0f, 0.5f)), {0.5f, 0.0f, 0.5f});
}

TEST_CASE("gltf: EXT_texture_webp's source is read in place of the core one, even where it is required") {
    Model model;
    const int positions = model.positions(kTriangle);
    const int uvs = model.accessor(std::vector<float>{0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f}, "VEC2", 5126, 3);
    model.doc["extensionsUsed"] = {"EXT_texture_webp"};
    model.doc["extensionsRequired"] = {"EXT_texture_webp"};
    // One lossless texel, code 255 0 255: sRGB 1 0 1.
    const std::vector<uint8_t> magenta{255, 0, 255};
    uint8_t* webp = nullptr;
    const size_t size = WebPEncodeLosslessRGB(magenta.data(), 1, 1, 3, &webp);
    REQUIRE(size > 0);
    const std::string webpBytes(reinterpret_cast<const char*>(webp), size);
    WebPFree(webp);
    // In a buffer view, as a .glb holds it (tinygltf decodes no data: URI of WebP).
    model.doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", model.bin.size()}, {"byteLength", size}});
    model.bin += webpBytes;
    model.bin.resize((model.bin.size() + 3) / 4 * 4, '\0');
    model.doc["images"] = json::array({{{"uri", "fallback-absent.png"}},
                                       {{"bufferView", model.doc["bufferViews"].size() - 1}, {"mimeType", "image/webp"}}});
    model.doc["textures"] = json::array({{{"source", 0}, {"extensions", {{"EXT_texture_webp", {{"source", 1}}}}}},
                                         {{"extensions", {{"EXT_texture_webp", {{"source", 1}}}}}}});
    model.doc["materials"] = json::array({
        {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}, {"metallicFactor", 0}}}},
        {{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 1}}}, {"metallicFactor", 0}}}},
    });
    for (int m = 0; m < 2; ++m) {
        model.meshNode({{"attributes", {{"POSITION", positions}, {"TEXCOORD_0", uvs}}}, {"material", m}});
    }
    LoadReport report;
    const MeshData mesh = parse(model.gltf(), &report).mesh;
    CHECK(report.warnings.empty());
    for (const Material& m : mesh.materials) {
        REQUIRE(m.textures.colour);
        CHECK(glm::vec3(m.textures.colour->lookup({0.5f, 0.5f})) == glm::vec3(1.0f, 0.0f, 1.0f));
    }
    model.doc["textures"][1]["extensions"]["EXT_texture_webp"] = json::object();
    CHECK_THROWS_WITH_AS(parse(model.gltf()),
                         "mem/model.gltf: material '' (1) baseColorTexture: texture 1: EXT_texture_webp needs a source",
                         Error);
}

TEST_CASE("gltf: a camera ray through a MASK-ed texel sees what is behind it") {
    Model model;
    // Two unit squares facing +z: the front one at z = 1 textured left opaque, right cut out.
    const int front = model.positions({0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 0, 1, 1, 1, 1, 0, 1, 1});
    const int back = model.positions({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 0, 0, 1, 1, 0, 0, 1, 0});
    const int uvs = model.accessor(std::vector<float>{0, 1, 1, 1, 1, 0, 0, 1, 1, 0, 0, 0}, "VEC2", 5126, 6);
    model.doc["images"] = json::array({{{"uri", "data:image/png;base64," +
                                                     base64(rgbaPng(2, 1, {255, 255, 255, 255, 255, 255, 255, 0}))}}});
    model.doc["textures"] = json::array({{{"source", 0}}});
    model.doc["materials"] = json::array({{{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}, {"alphaMode", "MASK"}},
                                          {{"emissiveFactor", {1.0, 1.0, 1.0}}}});
    model.meshNode({{"attributes", {{"POSITION", front}, {"TEXCOORD_0", uvs}}}, {"material", 0}});
    model.meshNode({{"attributes", {{"POSITION", back}}}, {"material", 1}});
    const Scene scene(parse(model.gltf()).mesh);
    const auto seen = [&](float x) {
        const auto hit = scene.intersect(Ray{{x, 0.5f, 2.0f}, {0.0f, 0.0f, -1.0f}});
        REQUIRE(hit);
        return hit->t;
    };
    CHECK(seen(0.25f) == doctest::Approx(1.0f));  // the opaque half of the front square
    CHECK(seen(0.75f) == doctest::Approx(2.0f));  // through the cut-out half onto the emitter
}

TEST_CASE("gltf: a clear coat takes its own normal map, and not the base's") {
    Model model;
    // Two unit squares facing +z with vertex normals +z: the first's coat has no normal map, the
    // second's has one of its own; both bases have the same normal map.
    const int first = model.positions({0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 0, 0, 1, 1, 0, 0, 1, 0});
    const int second = model.positions({2, 0, 0, 3, 0, 0, 3, 1, 0, 2, 0, 0, 3, 1, 0, 2, 1, 0});
    const int normals = model.positions({0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1});
    const int uvs = model.accessor(std::vector<float>{0, 1, 1, 1, 1, 0, 0, 1, 1, 0, 0, 0}, "VEC2", 5126, 6);
    // The base's texel tilts the normal along one tangent, the coat's along the other:
    // (0.6, 0, 0.8) and (0, 0.6, 0.8), 8 bits each.
    model.doc["images"] = json::array({
        {{"uri", "data:image/png;base64," + base64(rgbaPng(1, 1, {204, 128, 230, 255}))}},
        {{"uri", "data:image/png;base64," + base64(rgbaPng(1, 1, {128, 204, 230, 255}))}},
    });
    model.doc["textures"] = json::array({{{"source", 0}}, {{"source", 1}}});
    model.doc["extensionsUsed"] = {"KHR_materials_clearcoat"};
    model.doc["materials"] = json::array({
        {{"normalTexture", {{"index", 0}}}, {"extensions", {{"KHR_materials_clearcoat", {{"clearcoatFactor", 1}}}}}},
        {{"normalTexture", {{"index", 0}}},
         {"extensions",
          {{"KHR_materials_clearcoat",
            {{"clearcoatFactor", 1}, {"clearcoatNormalTexture", {{"index", 1}, {"scale", 0.5}}}}}}}},
    });
    model.meshNode({{"attributes", {{"POSITION", first}, {"NORMAL", normals}, {"TEXCOORD_0", uvs}}}, {"material", 0}});
    model.meshNode({{"attributes", {{"POSITION", second}, {"NORMAL", normals}, {"TEXCOORD_0", uvs}}}, {"material", 1}});
    LoadReport report;
    MeshData mesh = parse(model.gltf(), &report).mesh;
    for (const std::string& warning : report.warnings) CHECK(warning.find("clearcoatNormalTexture") == std::string::npos);
    REQUIRE(mesh.materials.size() == 2);
    CHECK_FALSE(mesh.materials[0].textures.clearcoatNormal);
    REQUIRE(mesh.materials[1].textures.clearcoatNormal);
    CHECK(mesh.materials[1].textures.clearcoatNormalScale == 0.5f);
    const Scene scene(std::move(mesh));
    CHECK(scene.materials().coatHasOwnNormal(0));
    CHECK(scene.materials().coatHasOwnNormal(1));
    const auto normalsAt = [&](float x) {
        const auto hit = scene.intersect(Ray{{x, 0.4f, 1.0f}, {0.0f, 0.0f, -1.0f}});
        REQUIRE(hit);
        return std::pair{scene.surface(*hit).shadingNormal, scene.coatNormal(*hit, scene.surface(*hit).uv)};
    };
    // The texel's 8-bit (0.6, 0, 0.8) is (0.6, 0, 0.804) decoded; 0.6 / |that| = 0.598.
    const auto [base0, coat0] = normalsAt(0.6f);
    CHECK(std::abs(base0.x) == doctest::Approx(0.598).epsilon(1e-2));
    CHECK(coat0 == glm::vec3(0.0f, 0.0f, 1.0f));
    // The coat's map at half scale: (0, 0.3, 0.804) normalised (the byte 128 decodes to 0.004).
    const auto [base1, coat1] = normalsAt(2.6f);
    CHECK(std::abs(base1.x) == doctest::Approx(0.598).epsilon(1e-2));
    CHECK(std::abs(coat1.x) < 3e-3f);
    CHECK(std::abs(coat1.y) == doctest::Approx(0.3 / std::sqrt(0.09 + 0.804 * 0.804)).epsilon(1e-2));
}

TEST_CASE("gltf: the first camera, from its node, looking down -Z") {
    Model model;
    model.meshNode({{"attributes", {{"POSITION", model.positions(kTriangle)}}}});
    model.doc["cameras"] = json::array({
        {{"type", "orthographic"}, {"orthographic", {{"xmag", 1}, {"ymag", 1}, {"znear", 0.1}, {"zfar", 10}}}},
        {{"type", "perspective"}, {"perspective", {{"yfov", 0.5}, {"znear", 0.1}}}},
    });
    // Turned 90 degrees about +y: its -Z is the world's -X.
    model.addNode({{"camera", 1}, {"translation", {4, 1, 0}}, {"rotation", {0, kHalfRoot2, 0, kHalfRoot2}}});
    model.addNode({{"camera", 0}});
    LoadReport report;
    const ParsedScene parsed = parse(model.gltf(), &report);
    REQUIRE(parsed.camera);
    CHECK(parsed.camera->position == glm::vec3(4, 1, 0));
    checkApprox(glm::normalize(parsed.camera->lookAt - parsed.camera->position), {-1, 0, 0});
    checkApprox(parsed.camera->up, {0, 1, 0});
    CHECK(parsed.camera->fovYDegrees == doctest::Approx(28.64788976f));
    // The look-at point lies ahead at the distance of the scene's centre (0.5, 0.5, 0).
    CHECK(glm::length(parsed.camera->lookAt - parsed.camera->position) ==
          doctest::Approx(glm::length(glm::vec3(3.5f, 0.5f, 0.0f))));
    CHECK(parsed.camera->orthographicHalfHeight == 0.0f);
    CHECK(report.warnings.empty());
}

TEST_CASE("gltf: the scene takes the file's camera unless a description or --camera gives one") {
    Model model;
    model.meshNode({{"attributes", {{"POSITION", model.positions(kTriangle)}}}});
    model.doc["cameras"] = json::array({{{"type", "perspective"}, {"perspective", {{"yfov", 1.0}, {"znear", 0.1}}}}});
    model.addNode({{"camera", 0}, {"translation", {0, 0, 7}}});
    const auto dir = test::scratchDir("gltf-camera");
    std::ofstream(dir / "s.gltf") << model.gltf();
    CHECK(loadScene(dir / "s.gltf").settings.pose.position == glm::vec3(0, 0, 7));
    std::ofstream(dir / "s.json") << R"({"position":[0,0,3],"look_at":[0,0,0],"up":[0,1,0],"fov_y":40})";
    CHECK(loadScene(dir / "s.gltf").settings.pose.position == glm::vec3(0, 0, 3));
    std::ofstream(dir / "c.json") << R"({"position":[0,0,2],"look_at":[0,0,0],"up":[0,1,0],"fov_y":40})";
    CHECK(loadScene(dir / "s.gltf", dir / "c.json").settings.pose.position == glm::vec3(0, 0, 2));
}

TEST_CASE("gltf: KHR_lights_punctual point, spot and directional lights, intensity x color") {
    Model model;
    model.meshNode({{"attributes", {{"POSITION", model.positions(kTriangle)}}}});
    model.doc["extensionsUsed"] = {"KHR_lights_punctual"};
    model.doc["extensions"]["KHR_lights_punctual"]["lights"] = json::array({
        {{"type", "point"}, {"color", {1, 0.5, 0.25}}, {"intensity", 10}, {"range", 3}},
        {{"type", "directional"}, {"intensity", 2}},
        {{"type", "spot"}, {"intensity", 4}, {"spot", {{"innerConeAngle", 0.2}, {"outerConeAngle", 0.5}}}},
        {{"type", "spot"}, {"intensity", 4}, {"spot", {{"innerConeAngle", 0.7}, {"outerConeAngle", 2.0}}}},
    });
    model.addNode({{"translation", {1, 2, 3}}, {"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
    // Turned -90 degrees about +x: its -Z points down.
    model.addNode({{"rotation", {-kHalfRoot2, 0, 0, kHalfRoot2}}, {"extensions", {{"KHR_lights_punctual", {{"light", 1}}}}}});
    model.addNode({{"translation", {0, 5, 0}},
                   {"rotation", {-kHalfRoot2, 0, 0, kHalfRoot2}},
                   {"extensions", {{"KHR_lights_punctual", {{"light", 2}}}}}});
    model.addNode({{"extensions", {{"KHR_lights_punctual", {{"light", 3}}}}}});
    LoadReport report;
    const MeshData mesh = parse(model.gltf(), &report).mesh;
    REQUIRE(mesh.pointLights.size() == 1);
    CHECK(mesh.pointLights[0].position == glm::vec3(1, 2, 3));
    CHECK(mesh.pointLights[0].intensity == glm::vec3(10, 5, 2.5));
    REQUIRE(mesh.directionalLights.size() == 1);
    checkApprox(mesh.directionalLights[0].direction, {0, -1, 0});
    CHECK(mesh.directionalLights[0].irradiance == glm::vec3(2));
    // The spot at (0, 5, 0) points down: full intensity within 0.2 radians of its axis, none
    // beyond 0.5.
    REQUIRE(mesh.spotLights.size() == 2);
    const SpotLight& spot = mesh.spotLights[0];
    CHECK(spot.position == glm::vec3(0, 5, 0));
    checkApprox(spot.axis, {0, -1, 0});
    CHECK(spot.intensity == glm::vec3(4));
    CHECK(spot.falloff(std::cos(0.19f)) == 1.0f);
    CHECK(spot.falloff(std::cos(0.51f)) == 0.0f);
    // An outer angle past pi/2 is taken to pi/2, with a warning.
    CHECK(mesh.spotLights[1].falloff(std::cos(1.5f)) > 0.0f);
    CHECK(mesh.spotLights[1].falloff(std::cos(1.6f)) == 0.0f);
    CHECK(std::count(report.warnings.begin(), report.warnings.end(),
                     "mem/model.gltf: light '' (3): spot cone angles outside 0 <= inner < outer <= pi/2; taken "
                     "into that range") == 1);
}

TEST_CASE("gltf: reading gathers the buffers and images a .gltf names, parsing uses only them") {
    Model model;
    model.meshNode({{"attributes", {{"POSITION", model.positions(kTriangle)}}}});
    json doc = model.doc;
    doc["buffers"] = json::array({{{"byteLength", model.bin.size()}, {"uri", "data%20files/tri.bin"}}});
    doc["images"] = json::array({{{"uri", "tex.png"}}});
    const auto dir = test::scratchDir("gltf-read");
    std::filesystem::create_directories(dir / "data files");
    std::ofstream(dir / "s.gltf") << doc.dump();
    std::ofstream(dir / "data files" / "tri.bin", std::ios::binary) << model.bin;
    std::ofstream(dir / "tex.png") << "not decoded";
    SceneFolder folder(dir / "s.gltf", {});
    const std::vector<SceneFile> files = readGltfScene(dir / "s.gltf", folder);
    REQUIRE(files.size() == 3);
    CHECK(files[0].name == "s.gltf");
    CHECK(files[1].name == "data files/tri.bin");
    CHECK(files[1].bytes == model.bin);
    CHECK(files[2].name == "tex.png");
    // Elsewhere, with the folder gone: the bundle alone.
    const SceneBundle elsewhere{"other/host/s.gltf", files, std::nullopt, std::nullopt};
    std::filesystem::remove_all(dir / "data files");
    CHECK(parseGltfScene(elsewhere).mesh.triangles.size() == 1);
    CHECK_THROWS_WITH_AS(readGltfScene(dir / "s.gltf", folder),
                         ((dir / "s.gltf").string() + ": File not found : data files/tri.bin").c_str(), Error);
}

TEST_CASE("gltf: bad input is one line naming the file and what is wrong") {
    Model model;
    const int positions = model.positions(kTriangle);
    const int indices = model.accessor(std::vector<uint16_t>{0, 1, 7}, "SCALAR", 5123, 3);
    Model required = model;
    required.meshNode({{"attributes", {{"POSITION", positions}}}});
    required.doc["extensionsRequired"] = {"KHR_materials_iridescence"};
    CHECK(errorOf(required.gltf()) ==
          "mem/model.gltf: requires extension KHR_materials_iridescence, which Strata does not implement");
    Model lines = model;
    lines.meshNode({{"attributes", {{"POSITION", positions}}}, {"mode", 1}});
    CHECK(errorOf(lines.gltf()) == "mem/model.gltf: the file holds only lines, no surfaces; Strata renders "
                                     "triangles, strips and fans");
    Model outOfRange = model;
    outOfRange.meshNode({{"attributes", {{"POSITION", positions}}}, {"indices", indices}});
    CHECK(errorOf(outOfRange.gltf()) ==
          "mem/model.gltf: every triangle uses an index past its primitive's vertices; nothing is left");
    Model shortView = model;
    shortView.doc["accessors"][0]["count"] = 4;
    shortView.meshNode({{"attributes", {{"POSITION", positions}}}});
    CHECK(errorOf(shortView.gltf()) == "mem/model.gltf: mesh 'm0' (0) primitive 0: POSITION accessor 0: "
                                         "4 elements run past the end of bufferView 0");
    Model cycle = model;
    cycle.doc["nodes"] = json::array({{{"children", {1}}}, {{"children", {0}}}});
    cycle.doc["scenes"] = json::array({{{"nodes", {0}}}});
    CHECK(errorOf(cycle.gltf()) == "mem/model.gltf: node 0 is reached twice: the node hierarchy is not a tree");
    Model pastBuffer = model;  // an image's view must lie in its buffer: tinygltf reads it unchecked
    pastBuffer.meshNode({{"attributes", {{"POSITION", positions}}}});
    pastBuffer.doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", 36}, {"byteLength", 100}});
    pastBuffer.doc["images"] = json::array({{{"bufferView", 2}, {"mimeType", "image/png"}}});
    CHECK(errorOf(pastBuffer.gltf()) ==
          "mem/model.gltf: image 0: bufferView 2 (byteOffset 36, byteLength 100) runs past the end of buffer 0 "
          "(44 bytes)");
    json missing = model.doc;
    missing["buffers"] = json::array({{{"byteLength", 12}, {"uri", "absent.bin"}}});
    CHECK(errorOf(missing.dump()) == "mem/model.gltf: File not found : absent.bin");
    // glTF 1.0 (by its version, a string or a number) is upgraded (test_gltf_version1.cpp); a
    // version that is neither is refused by it, not by the first list it cannot read.
    CHECK(errorOf(R"({"asset": {"version": 1}, "accessors": []})") ==
          "mem/model.gltf: glTF 1.0: \"accessors\" is not an object keyed by name, as glTF 1.0's lists are");
    CHECK(errorOf(R"({"asset": {"version": "0.8"}, "accessors": {"a": {}}})") ==
          "mem/model.gltf: glTF version 0.8; Strata reads version 2");
    Model minor = model;  // a later 2.x is read
    minor.meshNode({{"attributes", {{"POSITION", positions}}}});
    minor.doc["asset"]["version"] = "2.1";
    CHECK(parseGltfScene(bundleOf(minor.gltf())).mesh.triangles.size() == 1);
    const std::string malformed = errorOf(R"({"asset": {"version": "2.0"}, "nodes": [)");
    CHECK(malformed.rfind("mem/model.gltf: ", 0) == 0);
    CHECK(malformed.find("parse error") != std::string::npos);
    CHECK(malformed.find('\n') == std::string::npos);
}

TEST_CASE("gltf: assimp's glTF 2.0 test models load or fail with one line naming the file") {
    const std::filesystem::path root = "/usr/share/assimp/models/glTF2";
    if (!std::filesystem::is_directory(root)) {
        MESSAGE("assimp-testmodels not installed: " << root << " is absent, skipped");
        return;
    }
    size_t loaded = 0;
    size_t refused = 0;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(root)) {
        const std::string extension = entry.path().extension().string();
        if (extension != ".gltf" && extension != ".glb") continue;
        CAPTURE(entry.path());
        try {
            const LoadedScene scene = loadScene(entry.path());
            CHECK(scene.scene.summary().triangles > 0);
            ++loaded;
        } catch (const Error& error) {
            const std::string message = error.what();
            CHECK(message.find(entry.path().string()) != std::string::npos);
            CHECK(message.find('\n') == std::string::npos);
            ++refused;
        }
    }
    MESSAGE(loaded << " glTF models loaded, " << refused << " refused");
    CHECK(loaded > 0);

    const auto errorOfFile = [&](const std::string& file) {
        try {
            loadScene(root / file);
        } catch (const Error& error) {
            return std::string(error.what());
        }
        return std::string("(loaded)");
    };
    const auto path = [&](const std::string& file) { return (root / file).string(); };
    CHECK(errorOfFile("IndexOutOfRange/AllIndicesOutOfRange.gltf") ==
          path("IndexOutOfRange/AllIndicesOutOfRange.gltf") +
              ": every triangle uses an index past its primitive's vertices; nothing is left");
    CHECK(errorOfFile("MissingBin/BoxTextured.gltf") == path("MissingBin/BoxTextured.gltf") + ": File not found : BoxTextured0.bin");
    CHECK(errorOfFile("RecursiveNodes/RecursiveNodes.gltf") ==
          path("RecursiveNodes/RecursiveNodes.gltf") + ": node 0 is reached twice: the node hierarchy is not a tree");
    CHECK(errorOfFile("BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb") ==
          path("BoxWithInfinites-glTF-Binary/BoxWithInfinites.glb") + ": mesh 'Mesh' (0) primitive 0: POSITION accessor 2 holds a non-finite number");
    // An empty default scene is valid glTF with nothing to render.
    CHECK(errorOfFile("TestNoRootNode/SceneWithoutNodes.gltf") ==
          path("TestNoRootNode/SceneWithoutNodes.gltf") + ": the scene has no usable triangles");

    // 75730 triangles in its meshes, 121496 as its nodes instance them, 11160 of those degenerate:
    // its primitives used more than once are stored once each.
    const LoadedScene engine = loadScene(root / "2CylinderEngine-glTF-Binary/2CylinderEngine.glb");
    CHECK(engine.scene.summary().placedTriangles == 110336);
    CHECK(engine.scene.summary().triangles == 65311);
    CHECK(engine.report.droppedTriangles == 11160);
}

TEST_CASE("gltf: strengths, intensities and scales are checked as the floats they become") {
    // 1e300 is a finite double and an infinite float: emission and light once rendered black.
    Model lamp;
    lamp.meshNode({{"attributes", {{"POSITION", lamp.positions(kTriangle)}}}, {"material", 0}});
    lamp.doc["materials"] = json::array(
        {{{"emissiveFactor", {1, 1, 1}}, {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 1e300}}}}}}});
    CHECK(errorOf(lamp.gltf()) == "mem/model.gltf: material '' (0): emissiveStrength x emissiveFactor is beyond float range");
    // Finite as a float, it stands.
    lamp.doc["materials"][0]["extensions"]["KHR_materials_emissive_strength"]["emissiveStrength"] = 1e30;
    CHECK(parse(lamp.gltf()).mesh.materials[0].emission == glm::vec3(1e30f));

    Model light;
    light.meshNode({{"attributes", {{"POSITION", light.positions(kTriangle)}}}});
    light.doc["extensions"]["KHR_lights_punctual"]["lights"] = json::array({{{"type", "point"}, {"intensity", 1e300}}});
    light.addNode({{"extensions", {{"KHR_lights_punctual", {{"light", 0}}}}}});
    CHECK(errorOf(light.gltf()) == "mem/model.gltf: light '' (0): intensity x color is beyond float range");
    light.doc["extensions"]["KHR_lights_punctual"]["lights"][0] = {{"type", "point"}, {"color", {1e20, 0, 0}}, {"intensity", 1e20}};
    CHECK(errorOf(light.gltf()) == "mem/model.gltf: light '' (0): intensity x color is beyond float range");
    light.doc["extensions"]["KHR_lights_punctual"]["lights"][0] = {{"type", "point"}, {"intensity", 1}};
    light.doc["nodes"][1]["translation"] = {1e300, 0, 0};
    CHECK(errorOf(light.gltf()) == "mem/model.gltf: light '' (0): its node's position is beyond float range");

    Model bumpy;
    bumpy.meshNode({{"attributes", {{"POSITION", bumpy.positions(kTriangle)}}}, {"material", 0}});
    bumpy.doc["images"] = json::array({{{"uri", "gone.png"}}});
    bumpy.doc["textures"] = json::array({{{"source", 0}}});
    bumpy.doc["materials"] = json::array({{{"normalTexture", {{"index", 0}, {"scale", 1e300}}}}});
    CHECK(errorOf(bumpy.gltf()) == "mem/model.gltf: material '' (0): normalTexture scale is beyond float range");

    Model camera;
    camera.meshNode({{"attributes", {{"POSITION", camera.positions(kTriangle)}}}});
    camera.doc["cameras"] = json::array({{{"type", "perspective"}, {"perspective", {{"yfov", 0.7}, {"znear", 0.1}}}}});
    camera.addNode({{"camera", 0}, {"translation", {0, 0, 1e300}}});
    LoadReport report;
    CHECK(!parse(camera.gltf(), &report).camera);
    CHECK(report.warnings ==
          std::vector<std::string>{"mem/model.gltf: camera 0 is beyond float range (the scene is framed instead)"});
}

TEST_CASE("gltf: messages quote names with their control characters escaped and data: URIs cut short") {
    Model model;
    model.meshNode({{"attributes", {{"POSITION", model.positions(kTriangle)}}}, {"material", 0}});
    model.doc["materials"] = json::array({{{"name", "\x1b[2J\nred"}, {"emissiveFactor", {2, 0, 0}}}});
    CHECK(errorOf(model.gltf()) == "mem/model.gltf: material '\\x1b[2J\\nred' (0): emissiveFactor needs 3 numbers in 0..1");
    model.doc["materials"][0]["emissiveFactor"] = {1, 0, 0};
    model.doc["images"] = json::array({{{"uri", "gone\r.png"}}});
    model.doc["textures"] = json::array({{{"source", 0}}});
    model.doc["materials"][0]["emissiveTexture"] = {{"index", 0}};
    LoadReport report;
    parse(model.gltf(), &report);
    CHECK(report.warnings == std::vector<std::string>{"mem/model.gltf: material '\\x1b[2J\\nred' (0) emissiveTexture: "
                                                      "image 'gone\\r.png' is missing; using the factor alone"});
    // A data: URI that does not decode: tinygltf quotes it whole, the message does not.
    json broken = model.doc;
    broken["buffers"] = json::array({{{"byteLength", 36},
                                      {"uri", "data:application/octet-stream;base64," + std::string(50000, '!')}}});
    CHECK(errorOf(broken.dump()) ==
          "mem/model.gltf: Failed to decode 'uri' : data:application/octet-stream;base64,... (50037 bytes) in Buffer");
}

TEST_CASE("gltf: an EXR emissiveTexture's NaN, infinite and negative texels are a warning and read as 0 or its largest") {
    const test::ScratchDir dir = test::scratchDir("gltf-exr-emission");
    const float nan = std::nanf("");
    writeImage(dir / "glow.exr",
               Image{2, 2, {{1.0f, 0.5f, 0.25f}, {nan, 1.0f, 1.0f}, {INFINITY, -INFINITY, 0.0f}, {-5.0f, 2.0f, 3.0f}}});
    Model model;
    model.meshNode({{"attributes", {{"POSITION", model.positions(kTriangle)}}}, {"material", 0}});
    model.doc["images"] = json::array({{{"uri", "glow.exr"}}});
    model.doc["textures"] = json::array({{{"source", 0}}});
    model.doc["materials"] = json::array({{{"emissiveFactor", {1, 1, 1}}, {"emissiveTexture", {{"index", 0}}}}});
    SceneBundle bundle = bundleOf(model.gltf());
    bundle.files.push_back({"glow.exr", test::fileBytes(dir / "glow.exr")});
    LoadReport report;
    const MeshData mesh = parseGltfScene(bundle, &report).mesh;
    CHECK(report.warnings == std::vector<std::string>{
                                 "mem/model.gltf: material '' (0) emissiveTexture: 'glow.exr': 4 of 12 texel values are "
                                 "NaN, infinite or negative; read as 0, or as the texture's largest finite value for +inf"});
    const Texture& glow = *mesh.materials[0].textures.emission;
    CHECK(glm::vec3(glow.texel(0, 0)) == glm::vec3(1.0f, 0.5f, 0.25f));
    CHECK(glm::vec3(glow.texel(1, 0)) == glm::vec3(0.0f, 1.0f, 1.0f));
    CHECK(glm::vec3(glow.texel(0, 1)) == glm::vec3(3.0f, 0.0f, 0.0f));
    CHECK(glm::vec3(glow.texel(1, 1)) == glm::vec3(0.0f, 2.0f, 3.0f));
}

TEST_CASE("gltf: the triangle budget counts stored triangles and instances from the accessors, before reading them") {
    Model model;
    const int positions = model.positions(kTriangle);
    const json primitive = {{"attributes", {{"POSITION", positions}}}};
    model.meshNode(primitive);
    model.addNode({{"mesh", 0}});  // the same primitive again: stored once, placed twice
    model.meshNode(primitive, {{"scale", {2, 2, 2}}});
    CHECK_NOTHROW(parseGltfScene(bundleOf(model.gltf()), nullptr, SceneBudget{.triangles = 10}));
    CHECK_THROWS_WITH_AS(parseGltfScene(bundleOf(model.gltf()), nullptr, SceneBudget{.triangles = 9}),
                         "mem/model.gltf: 1 triangle after instancing and 3 instances (counted as 3 triangles each; "
                         "3 triangles placed) exceed the budget of 9 triangles (--max-triangles N raises it)",
                         Error);
    // An accessor that claims 3e8 positions in a 36-byte buffer is refused by the budget, from its
    // count, before anything would be read or allocated for it.
    model.doc["accessors"][positions]["count"] = 300000000;
    CHECK_THROWS_WITH_AS(parse(model.gltf()),
                         doctest::Contains("100000000 triangles after instancing and 3 instances"), Error);
}

TEST_CASE("gltf: a list of the wrong JSON type is named, not read as absent") {
    Model model;
    model.meshNode({{"attributes", {{"POSITION", model.positions(kTriangle)}}}});
    Model primitives = model;
    primitives.doc["meshes"][0]["primitives"] = {{"not an array", {{"POSITION", 0}}}};
    CHECK(errorOf(primitives.gltf()) == "mem/model.gltf: mesh 0: \"primitives\" is not an array (it is object)");
    Model children = model;
    children.doc["nodes"][0]["children"] = 1;
    CHECK(errorOf(children.gltf()) == "mem/model.gltf: node 0: \"children\" is not an array (it is number)");
    Model meshes = model;
    meshes.doc["meshes"] = "m";
    CHECK(errorOf(meshes.gltf()) == "mem/model.gltf: \"meshes\" is not an array (it is string)");
    const std::filesystem::path badArray = "/usr/share/assimp/models/glTF2/wrongTypes/badArray.gltf";
    if (!std::filesystem::exists(badArray)) {
        MESSAGE("assimp-testmodels not installed: " << badArray << " is absent, skipped");
        return;
    }
    CHECK_THROWS_WITH_AS(loadScene(badArray), (badArray.string() + ": mesh 0: \"primitives\" is not an array (it is object)").c_str(),
                         Error);
}
