// glTF 1.0 read as 2.0 (gltf_version1.h): files written here in 1.0's form, text and binary,
// and assimp's glTF 1.0 test models when they are installed.
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>
#include <nlohmann/json.hpp>
#include <stb_image_write.h>

#include "materials/microfacet.h"
#include "scene/gltf_loader.h"
#include "scene/gltf_test_model.h"
#include "scene/scene.h"
#include "scene/scene_loader.h"
#include "util/error.h"

using namespace strata;
using nlohmann::json;
using test::append;
using test::base64;
using test::bundleOf;
using test::errorOf;

namespace {

constexpr const char* kNote =
    "mem/model.gltf: glTF 1.0, read as 2.0: its Blinn-Phong materials as specular-glossiness ones; shaders, "
    "skins, animations and lights not read";

// One triangle in the z = 0 plane, facing +z: positions and normals interleaved (a 24-byte
// stride, as collada2gltf wrote them), UVs, then uint16 indices.
std::string triangleBuffer() {
    std::string bin;
    append(bin, std::vector<float>{0, 0, 0, 0, 0, 1, 1, 0, 0, 0, 0, 1, 0, 1, 0, 0, 0, 1});
    append(bin, std::vector<float>{0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f});
    append(bin, std::vector<uint16_t>{0, 1, 2});
    return bin;
}

// A glTF 1.0 document over buffer `buffer` (triangleBuffer's layout): node "root" holds meshes
// "a" and "b", each the triangle, "a" with the technique material "phong" (named "Phong"), "b"
// with the KHR_materials_common one "common" (unnamed) and UVs on a TEXCOORD without a set index,
// as some exporters wrote it.
json version1Document(const json& buffer) {
    return {
        {"asset", {{"version", "1.0"}}},
        {"buffers", {{"buf", buffer}}},
        {"bufferViews",
         {{"vertices", {{"buffer", "buf"}, {"byteOffset", 0}, {"byteLength", 96}, {"target", 34962}}},
          {"indices", {{"buffer", "buf"}, {"byteOffset", 96}, {"byteLength", 6}, {"target", 34963}}}}},
        {"accessors",
         {{"position",
           {{"bufferView", "vertices"}, {"byteOffset", 0}, {"byteStride", 24}, {"componentType", 5126},
            {"count", 3}, {"type", "VEC3"}}},
          {"normal",
           {{"bufferView", "vertices"}, {"byteOffset", 12}, {"byteStride", 24}, {"componentType", 5126},
            {"count", 3}, {"type", "VEC3"}}},
          {"uv",
           {{"bufferView", "vertices"}, {"byteOffset", 72}, {"byteStride", 0}, {"componentType", 5126},
            {"count", 3}, {"type", "VEC2"}}},
          {"index",
           {{"bufferView", "indices"}, {"byteOffset", 0}, {"componentType", 5123}, {"count", 3}, {"type", "SCALAR"}}}}},
        {"techniques", {{"t", {{"parameters", {{"diffuse", {{"type", 35666}, {"value", {0.5, 0.5, 0.5, 1}}}}}}}}}},
        {"materials",
         {{"phong",
           {{"name", "Phong"}, {"technique", "t"}, {"values", {{"specular", {0.04, 0.04, 0.04, 1}}, {"shininess", 256}}}}},
          {"common",
           {{"extensions",
             {{"KHR_materials_common",
               {{"technique", "LAMBERT"}, {"values", {{"diffuse", {0.2, 0.4, 0.6, 1}}, {"emission", {2, 1, 0, 1}}}}}}}}}}}},
        {"meshes",
         {{"a",
           {{"primitives",
             {{{"attributes", {{"POSITION", "position"}, {"NORMAL", "normal"}, {"JOINT", "uv"}}},
               {"indices", "index"},
               {"material", "phong"}}}}}},
          {"b",
           {{"primitives",
             {{{"attributes", {{"POSITION", "position"}, {"TEXCOORD", "uv"}}},
               {"indices", "index"},
               {"material", "common"}}}}}}}},
        {"nodes", {{"root", {{"meshes", {"a", "b"}}, {"translation", {0, 0, 1}}}}}},
        {"scenes", {{"s", {{"nodes", {"root"}}}}}},
        {"scene", "s"}};
}

const Material& named(const MeshData& mesh, const std::string& name) {
    const auto it = std::find_if(mesh.materials.begin(), mesh.materials.end(),
                                 [&](const Material& m) { return m.name == name; });
    REQUIRE(it != mesh.materials.end());
    return *it;
}

std::string pngOf(const std::vector<unsigned char>& rgba) {
    std::string png;
    stbi_write_png_to_func(
        [](void* out, void* data, int size) { static_cast<std::string*>(out)->append(static_cast<char*>(data), size); },
        &png, 1, 1, 4, rgba.data(), 4);
    return png;
}

// KHR_binary_glTF's layout: "glTF", version 1, the total length, the content's length and
// format (0, JSON), the content, the body.
std::string binaryVersion1(std::string content, const std::string& body) {
    while (content.size() % 4) content += ' ';
    std::string out = "glTF";
    append(out, std::vector<uint32_t>{1, static_cast<uint32_t>(20 + content.size() + body.size()),
                                      static_cast<uint32_t>(content.size()), 0});
    return out + content + body;
}

}  // namespace

TEST_CASE("gltf 1.0: named lists, strided accessors, a node's meshes and Blinn-Phong materials read as 2.0") {
    const std::string bin = triangleBuffer();
    const json document = version1Document(
        {{"byteLength", bin.size()}, {"type", "arraybuffer"}, {"uri", "data:application/octet-stream;base64," + base64(bin)}});
    LoadReport report;
    const MeshData mesh = parseGltfScene(bundleOf(document.dump()), &report).mesh;
    CHECK(report.warnings == std::vector<std::string>{kNote});
    // Both meshes, placed by the node; positions and normals read through their 24-byte stride.
    REQUIRE(mesh.triangles.size() == 2);
    for (const auto& triangle : mesh.triangles) {
        CHECK(mesh.positions[triangle[0]] == glm::vec3(0, 0, 1));
        CHECK(mesh.positions[triangle[1]] == glm::vec3(1, 0, 1));
        CHECK(mesh.positions[triangle[2]] == glm::vec3(0, 1, 1));
    }
    REQUIRE_FALSE(mesh.normals.empty());
    for (const glm::vec3& normal : mesh.normals) CHECK(normal == glm::vec3(0, 0, 1));
    // The technique's default diffuse under the values' specular (F0 0.04): specular-glossiness
    // takes max(specular) from the diffuse; the shininess 256 read as an MTL's Ns is.
    const Material& phong = named(mesh, "Phong");
    CHECK(phong.diffuse.x == doctest::Approx(0.5 * 0.96));
    CHECK(phong.specular == glm::vec3(0.04f));
    CHECK(phong.roughness == doctest::Approx(roughnessFromShininess(256.0f)));
    // LAMBERT: no specular; an emission above 1 keeps its brightness. Unnamed, the material takes
    // its 1.0 name; its mesh's TEXCOORD is set 0.
    const Material& common = named(mesh, "common");
    CHECK(std::count(mesh.triangleUvs.begin(), mesh.triangleUvs.end(), kNoUvs) == 1);
    CHECK(common.diffuse.x == doctest::Approx(0.2));
    CHECK(common.diffuse.z == doctest::Approx(0.6));
    CHECK(common.specular == glm::vec3(0.0f));
    CHECK(common.emission.x == doctest::Approx(2.0));
    CHECK(common.emission.y == doctest::Approx(1.0));
    CHECK(common.emission.z == 0.0f);
}

TEST_CASE("gltf 1.0: a binary file's body is its buffer, an image in it read through its buffer view") {
    std::string body = triangleBuffer();
    const size_t imageOffset = body.size();
    const std::string png = pngOf({255, 0, 255, 255});
    body += png;
    json document = version1Document({{"byteLength", body.size()}, {"uri", "data:,"}});
    document["buffers"] = {{"binary_glTF", document["buffers"]["buf"]}};
    for (auto& [name, view] : document["bufferViews"].items()) view["buffer"] = "binary_glTF";
    document["bufferViews"]["png"] = {{"buffer", "binary_glTF"}, {"byteOffset", imageOffset}, {"byteLength", png.size()}};
    document["images"] = {
        {"logo", {{"uri", "data:,"}, {"extensions", {{"KHR_binary_glTF", {{"bufferView", "png"}, {"mimeType", "image/png"}}}}}}}};
    document["samplers"] = {{"nearest", {{"magFilter", 9728}, {"minFilter", 9728}}}};
    document["textures"] = {{"logo", {{"source", "logo"}, {"sampler", "nearest"}}}};
    document["materials"]["common"]["extensions"]["KHR_materials_common"]["values"]["diffuse"] = "logo";
    document["extensionsUsed"] = {"KHR_binary_glTF", "KHR_materials_common"};
    const MeshData mesh = parseGltfScene(bundleOf(binaryVersion1(document.dump(), body), "model.glb")).mesh;
    REQUIRE(mesh.triangles.size() == 2);
    const Material& common = named(mesh, "common");
    REQUIRE(common.textures.colour);
    // Codes 255 and 0 decode to 1 and 0 exactly in sRGB.
    CHECK(common.textures.colour->lookup({0.5f, 0.5f}) == glm::vec4(1, 0, 1, 1));
}

TEST_CASE("gltf 1.0: bad input is one line naming the file and what is wrong") {
    const std::string bin = triangleBuffer();
    const json buffer = {{"byteLength", bin.size()}, {"uri", "data:application/octet-stream;base64," + base64(bin)}};
    json dangling = version1Document(buffer);
    dangling["meshes"]["a"]["primitives"][0]["attributes"]["POSITION"] = "nope";
    CHECK(errorOf(dangling.dump()) ==
          "mem/model.gltf: glTF 1.0: mesh 'a': POSITION names accessor \"nope\", which does not exist");
    json array = version1Document(buffer);
    array["meshes"] = json::array();
    CHECK(errorOf(array.dump()) ==
          "mem/model.gltf: glTF 1.0: \"meshes\" is not an object keyed by name, as glTF 1.0's lists are");
    json notObject = version1Document(buffer);
    notObject["nodes"]["root"] = 7;
    CHECK(errorOf(notObject.dump()) == "mem/model.gltf: glTF 1.0: node 'root' is not an object");
    // A binary header that claims more than the file holds, or content that is not JSON.
    std::string truncated = binaryVersion1(version1Document(buffer).dump(), "");
    truncated.resize(truncated.size() - 8);
    CHECK(errorOf(truncated, "model.glb").find("mem/model.glb: glTF 1.0: the binary header gives a length of ") == 0);
    std::string format = binaryVersion1("{}", "");
    format[16] = 1;
    CHECK(errorOf(format, "model.glb") == "mem/model.glb: glTF 1.0: the binary content is not JSON (format 0)");
    CHECK(errorOf(R"({"asset": {"version": "3.0"}})") == "mem/model.gltf: glTF version 3.0; Strata reads version 2");
}

TEST_CASE("gltf 1.0: assimp's glTF 1.0 test models load, or fail with one line naming the file") {
    const std::filesystem::path root = "/usr/share/assimp/models/glTF";
    if (!std::filesystem::is_directory(root)) {
        MESSAGE("assimp-testmodels not installed: " << root << " is absent, skipped");
        return;
    }
    // Its binary box is cut 33 bytes short of what its header and its last buffer view give.
    const std::filesystem::path truncated = root / "BoxTextured-glTF-Binary/BoxTextured.glb";
    size_t loaded = 0;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(root)) {
        const std::string extension = entry.path().extension().string();
        if (extension != ".gltf" && extension != ".glb") continue;
        CAPTURE(entry.path());
        if (entry.path() == truncated) {
            CHECK_THROWS_WITH_AS(loadScene(entry.path()),
                                 (truncated.string() +
                                  ": glTF 1.0: the binary header gives a length of 17754 bytes, the file has 17721")
                                     .c_str(),
                                 Error);
            continue;
        }
        const LoadedScene scene = loadScene(entry.path());
        CHECK(scene.scene.summary().triangles > 0);
        ++loaded;
    }
    CHECK(loaded >= 6);
    // The milk truck: its body textured, its wheels one mesh placed twice.
    const LoadedScene truck = loadScene(root / "CesiumMilkTruck/CesiumMilkTruck.gltf");
    CHECK(truck.scene.summary().placedTriangles > truck.scene.summary().triangles);
    const auto& materials = truck.scene.mesh().materials;
    CHECK(std::any_of(materials.begin(), materials.end(), [](const Material& m) { return m.textures.colour != nullptr; }));
}
