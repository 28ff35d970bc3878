// What the glTF scene builder (gltf_nodes.h) leaves out and says so, as assimp does: vertices that
// make no whole triangle, triangles with an index past their vertices, points and lines; and the
// one line that refuses a file when nothing is left, naming why.
#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>
#include <glm/geometric.hpp>

#include "scene/gltf_loader.h"
#include "scene/gltf_test_model.h"
#include "scene/scene.h"
#include "test_support.h"
#include "scene/scene_loader.h"
#include "util/error.h"

using namespace strata;
using nlohmann::json;
using test::errorOf;

namespace {

const std::vector<float> kQuadPositions{0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};

bool warned(const LoadReport& report, const std::string& line) {
    return std::count(report.warnings.begin(), report.warnings.end(), "mem/model.gltf: " + line) == 1;
}


}  // namespace

TEST_CASE("gltf nodes: vertices that make no whole triangle are left out with a warning") {
    test::Model model;
    model.meshNode({{"attributes", {{"POSITION", model.positions({0, 0, 0, 1, 0, 0, 0, 1, 0, 5, 5, 5, 6, 6, 6})}}}});
    LoadReport report;
    const MeshData mesh = parseGltfScene(test::bundleOf(model.gltf()), &report).mesh;
    CHECK(mesh.triangles.size() == 1);
    CHECK(warned(report, "mesh 'm0' (0) primitive 0: 5 vertices do not make whole triangles; the last 2 left out"));
}

TEST_CASE("gltf nodes: a triangle with an index past the vertices is left out, the count in one warning") {
    test::Model model;
    const int positions = model.positions(kQuadPositions);
    const int indices = model.accessor(std::vector<uint16_t>{0, 1, 2, 0, 2, 9, 0, 2, 3}, "SCALAR", 5123, 9);
    model.meshNode({{"attributes", {{"POSITION", positions}}}, {"indices", indices}});
    LoadReport report;
    const MeshData mesh = parseGltfScene(test::bundleOf(model.gltf()), &report).mesh;
    REQUIRE(mesh.triangles.size() == 2);
    CHECK(mesh.triangles[1] == std::array<uint32_t, 3>{0, 2, 3});
    CHECK(warned(report, "mesh 'm0' (0) primitive 0: 1 of 3 triangles uses an index past its 4 vertices; left out"));
    // In a strip, the index leaves out every triangle that uses it: 3 of its 7; of the other 4,
    // (2, 0, 2) is degenerate.
    model.doc["meshes"][0]["primitives"][0]["mode"] = 5;
    LoadReport strip;
    CHECK(parseGltfScene(test::bundleOf(model.gltf()), &strip).mesh.triangles.size() == 3);
    CHECK(warned(strip, "mesh 'm0' (0) primitive 0: 3 of 7 triangles use an index past its 4 vertices; left out"));
}

TEST_CASE("gltf nodes: points and lines are skipped beside surfaces, and named when they are all there is") {
    test::Model model;
    const int positions = model.positions(kQuadPositions);
    model.meshNode({{"attributes", {{"POSITION", positions}}}, {"mode", 0}});
    CHECK(errorOf(model) == "mem/model.gltf: the file holds only points, no surfaces; Strata renders triangles, "
                            "strips and fans");
    model.meshNode({{"attributes", {{"POSITION", positions}}}, {"mode", 3}});
    CHECK(errorOf(model) == "mem/model.gltf: the file holds only points and lines, no surfaces; Strata renders "
                            "triangles, strips and fans");
    model.meshNode({{"attributes", {{"POSITION", positions}}}, {"mode", 6}}, {{"translation", {0, 0, 5}}});
    LoadReport report;
    const MeshData mesh = parseGltfScene(test::bundleOf(model.gltf()), &report).mesh;
    CHECK(mesh.triangles.size() == 2);
    CHECK(mesh.positions.size() == 4);  // the points' and lines' vertices are not kept (nor framed)
    CHECK(warned(report, "points and lines are not surfaces; their primitives are skipped"));
}

TEST_CASE("gltf nodes: assimp's incomplete and out-of-range test models open as assimp opens them") {
    const std::filesystem::path root = "/usr/share/assimp/models/glTF2";
    if (!std::filesystem::is_directory(root)) {
        MESSAGE("assimp-testmodels not installed: " << root << " is absent, skipped");
        return;
    }
    const LoadedScene cube = loadScene(root / "IncorrectVertexArrays/Cube.gltf");
    CHECK(cube.scene.summary().triangles > 0);
    const LoadedScene index = loadScene(root / "IndexOutOfRange/IndexOutOfRange.gltf");
    CHECK(index.scene.summary().triangles == 11);  // assimp: 1 of 12 faces dropped
    const std::string warning = (root / "IndexOutOfRange/IndexOutOfRange.gltf").string() +
                                ": mesh 'Mesh' (0) primitive 0: 1 of 12 triangles uses an index past its 24 vertices; "
                                "left out";
    CHECK(std::count(index.report.warnings.begin(), index.report.warnings.end(), warning) == 1);
}

TEST_CASE("gltf nodes: COLOR_0 gives vertex colours, RGB of float VEC3 or normalized VEC4, white elsewhere") {
    test::Model model;
    const int positions = model.positions(kQuadPositions);
    const int floats =
        model.accessor(std::vector<float>{0.1f, 0.2f, 0.3f, 1, 1, 1, 0, 0, 0, 0.5f, 2.0f, -1}, "VEC3", 5126, 4);
    const int indices = model.accessor(std::vector<uint16_t>{0, 1, 2, 0, 2, 3}, "SCALAR", 5123, 6);
    model.meshNode({{"attributes", {{"POSITION", positions}, {"COLOR_0", floats}}}, {"indices", indices}});
    const int bytes = model.accessor(std::vector<uint8_t>{255, 0, 51, 7, 0, 255, 102, 7, 0, 0, 0, 0}, "VEC4", 5121, 3);
    model.doc["accessors"][bytes]["normalized"] = true;
    model.meshNode({{"attributes", {{"POSITION", model.positions({0, 0, 1, 1, 0, 1, 0, 1, 1})}, {"COLOR_0", bytes}}}});
    model.meshNode({{"attributes", {{"POSITION", model.positions({0, 0, 2, 1, 0, 2, 0, 1, 2})}}}});
    const MeshData mesh = parseGltfScene(test::bundleOf(model.gltf())).mesh;
    REQUIRE(mesh.triangles.size() == 4);
    REQUIRE(mesh.colours.size() == 7);
    CHECK(mesh.colours[0] == glm::vec3(0.1f, 0.2f, 0.3f));
    CHECK(mesh.colours[3] == glm::vec3(0.5f, 1.0f, 0.0f));  // clamped to [0, 1]
    CHECK(mesh.colours[4] == glm::vec3(1.0f, 0.0f, 0.2f));  // 255 0 51 of 255; alpha not read
    CHECK(mesh.colours[5] == glm::vec3(0.0f, 1.0f, 0.4f));
    CHECK(mesh.triangleColours[0] == std::array<uint32_t, 3>{0, 1, 2});
    CHECK(mesh.triangleColours[2] == std::array<uint32_t, 3>{4, 5, 6});
    CHECK(mesh.triangleColours[3] == kNoColours);
    // What glTF does not allow for COLOR_0 is refused by name.
    model.doc["accessors"][bytes]["normalized"] = false;
    CHECK(errorOf(model).find("COLOR_0 accessor " + std::to_string(bytes) +
                              " has component type 5121, which glTF does not allow for it") != std::string::npos);
    model.doc["accessors"][bytes]["normalized"] = true;
    model.doc["accessors"][bytes]["type"] = "VEC2";
    CHECK(errorOf(model).find("is not a VEC3 or VEC4") != std::string::npos);
    model.doc["accessors"][bytes]["type"] = "VEC4";
    model.doc["meshes"][1]["primitives"][0]["attributes"]["COLOR_0"] = floats;
    CHECK(errorOf(model).find("COLOR_0 has 4 elements, POSITION 3") != std::string::npos);
}

namespace {

json gpuInstancing(const json& attributes) { return {{"EXT_mesh_gpu_instancing", {{"attributes", attributes}}}}; }

// Vertex `vertex` of the shared mesh `shared` at its placement `placement`.
glm::vec3 placed(const MeshData& mesh, size_t shared, size_t placement, size_t vertex) {
    const SharedMesh& sharedMesh = mesh.sharedMeshes[shared];
    const uint32_t index = mesh.triangles[sharedMesh.firstTriangle][vertex];
    return glm::vec3(sharedMesh.placements[placement] * glm::vec4(mesh.positions[index], 1.0f));
}

}  // namespace

TEST_CASE("gltf nodes: EXT_mesh_gpu_instancing places the mesh at each instance's T*R*S after the node's transform") {
    test::Model model;
    model.doc["extensionsUsed"] = {"EXT_mesh_gpu_instancing"};
    model.doc["extensionsRequired"] = {"EXT_mesh_gpu_instancing"};
    const int positions = model.positions({0, 0, 0, 1, 0, 0, 0, 1, 0});
    const int translations = model.accessor(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 2, 0}, "VEC3", 5126, 3);
    const float h = 0.70710678f;  // 90 degrees about z: (0, 0, sin 45, cos 45)
    const int rotations = model.accessor(std::vector<float>{0, 0, 0, 1, 0, 0, h, h, 0, 0, 0, 1}, "VEC4", 5126, 3);
    const int scales = model.accessor(std::vector<float>{1, 1, 1, 1, 1, 1, 3, 3, 3}, "VEC3", 5126, 3);
    model.meshNode({{"attributes", {{"POSITION", positions}}}},
                   {{"translation", {5, 0, 0}},
                    {"extensions", gpuInstancing({{"TRANSLATION", translations}, {"ROTATION", rotations},
                                                  {"SCALE", scales}, {"_ID", translations}})}});
    LoadReport report;
    const MeshData mesh = parseGltfScene(test::bundleOf(model.gltf()), &report).mesh;
    CHECK(report.warnings.empty());
    // Stored once, placed three times, and not at the node itself.
    REQUIRE(mesh.triangles.size() == 1);
    REQUIRE(mesh.sharedMeshes.size() == 1);
    REQUIRE(mesh.sharedMeshes[0].placements.size() == 3);
    test::checkNear(placed(mesh, 0, 0, 1), {6, 0, 0});
    test::checkNear(placed(mesh, 0, 1, 0), {6, 0, 0});  // (0,0,0) turned, moved by (1,0,0), then by the node's (5,0,0)
    test::checkNear(placed(mesh, 0, 1, 1), {6, 1, 0});  // (1,0,0) turned to (0,1,0)
    test::checkNear(placed(mesh, 0, 2, 1), {8, 2, 0});  // (1,0,0) scaled by 3, moved by (0,2,0) and (5,0,0)
    test::checkNear(placed(mesh, 0, 2, 2), {5, 5, 0});

    // Without TRANSLATION and SCALE, their parts are the identity; quantized (KHR_mesh_quantization)
    // rotations are normalized shorts.
    const int shortRotations =
        model.accessor(std::vector<int16_t>{0, 0, 0, 32767, 0, 0, 23170, 23170, 0, 0, 0, 32767}, "VEC4", 5122, 3);
    model.doc["accessors"][shortRotations]["normalized"] = true;
    model.doc["nodes"][0]["extensions"] = gpuInstancing({{"ROTATION", shortRotations}});
    const MeshData quantized = parseGltfScene(test::bundleOf(model.gltf())).mesh;
    REQUIRE(quantized.sharedMeshes.size() == 1);
    REQUIRE(quantized.sharedMeshes[0].placements.size() == 3);
    test::checkNear(placed(quantized, 0, 1, 1), {5, 1, 0});
    test::checkNear(placed(quantized, 0, 2, 1), {6, 0, 0});

    // One instance is a single use: flattened into world space, as a node without the extension.
    const int one = model.accessor(std::vector<float>{0, 0, 7}, "VEC3", 5126, 1);
    model.doc["nodes"][0]["extensions"] = gpuInstancing({{"TRANSLATION", one}});
    const MeshData single = parseGltfScene(test::bundleOf(model.gltf())).mesh;
    CHECK(single.sharedMeshes.empty());
    REQUIRE(single.positions.size() == 3);
    CHECK(single.positions[1] == glm::vec3(6, 0, 7));
}

TEST_CASE("gltf nodes: an emitting mesh is placed at each of its instances, and no instance places nothing") {
    test::Model model;
    model.doc["materials"] = json::array({{{"emissiveFactor", {1, 1, 1}}}});
    const int positions = model.positions({0, 0, 0, 1, 0, 0, 0, 1, 0});
    const int translations = model.accessor(std::vector<float>{0, 0, 0, 0, 0, 1, 0, 0, 2, 0, 0, 3}, "VEC3", 5126, 4);
    model.meshNode({{"attributes", {{"POSITION", positions}}}, {"material", 0}},
                   {{"extensions", gpuInstancing({{"TRANSLATION", translations}})}});
    const MeshData mesh = parseGltfScene(test::bundleOf(model.gltf())).mesh;
    REQUIRE(mesh.sharedMeshes.size() == 1);
    REQUIRE(mesh.sharedMeshes[0].placements.size() == 4);
    test::checkNear(placed(mesh, 0, 3, 1), {1, 0, 3});
    // The scene copies each placement of an emitter into the world, a light of its own (scene.h).
    const Scene scene(parseGltfScene(test::bundleOf(model.gltf())).mesh);
    CHECK(scene.lights().size() == 4);
    // Zero instances: the mesh is drawn nowhere.
    model.doc["accessors"][translations]["count"] = 0;
    CHECK(parseGltfScene(test::bundleOf(model.gltf())).mesh.triangles.empty());
}

TEST_CASE("gltf nodes: EXT_mesh_gpu_instancing's malformed attributes are refused in one line, counted before read") {
    test::Model model;
    const int positions = model.positions({0, 0, 0, 1, 0, 0, 0, 1, 0});
    const int three = model.accessor(std::vector<float>{0, 0, 0, 1, 0, 0, 2, 0, 0}, "VEC3", 5126, 3);
    const int two = model.accessor(std::vector<float>{1, 1, 1, 2, 2, 2}, "VEC3", 5126, 2);
    const int zeroRotation = model.accessor(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 0}, "VEC4", 5126, 2);
    model.meshNode({{"attributes", {{"POSITION", positions}}}},
                   {{"extensions", gpuInstancing({{"TRANSLATION", three}, {"SCALE", two}})}});
    CHECK(errorOf(model) == "mem/model.gltf: node 0: EXT_mesh_gpu_instancing: SCALE has 2 elements, TRANSLATION 3; "
                            "every attribute needs one per instance");
    model.doc["nodes"][0]["extensions"] = gpuInstancing(json::object());
    CHECK(errorOf(model) == "mem/model.gltf: node 0: EXT_mesh_gpu_instancing has no TRANSLATION, ROTATION or SCALE "
                            "accessor");
    model.doc["nodes"][0]["extensions"] = {{"EXT_mesh_gpu_instancing", {{"attributes", 3}}}};
    CHECK(errorOf(model) == "mem/model.gltf: node 0: EXT_mesh_gpu_instancing needs an attributes object");
    model.doc["nodes"][0]["extensions"] = gpuInstancing({{"TRANSLATION", 99}});
    CHECK(errorOf(model).find("TRANSLATION accessor 99 does not exist") != std::string::npos);
    model.doc["nodes"][0]["extensions"] = gpuInstancing({{"ROTATION", three}});
    CHECK(errorOf(model).find("ROTATION accessor " + std::to_string(three) + " is not a VEC4") != std::string::npos);
    model.doc["nodes"][0]["extensions"] = gpuInstancing({{"ROTATION", zeroRotation}});
    CHECK(errorOf(model) == "mem/model.gltf: mesh 'm0' (0) EXT_mesh_gpu_instancing: instance 1's ROTATION is not a "
                            "unit quaternion");
    // An accessor that claims 2e8 instances in a 36-byte buffer is refused by the budget, from its
    // count, before anything is read or allocated for it.
    model.doc["nodes"][0]["extensions"] = gpuInstancing({{"TRANSLATION", three}});
    model.doc["accessors"][three]["count"] = 200000000;
    CHECK(errorOf(model).find("1 triangle after instancing and 200000000 instances") != std::string::npos);
    // On a node without a mesh it places nothing: a warning.
    model.doc["accessors"][three]["count"] = 3;
    model.addNode({{"extensions", gpuInstancing({{"TRANSLATION", three}})}});
    LoadReport report;
    parseGltfScene(test::bundleOf(model.gltf()), &report);
    CHECK(warned(report, "EXT_mesh_gpu_instancing on a node without a mesh places nothing; ignored"));
}
