#include <doctest/doctest.h>

#include <fstream>
#include <sstream>

#include "scene/gltf_loader.h"
#include "scene/obj_loader.h"
#include "scene/scene_format.h"
#include "scene/scene_loader.h"
#include "util/error.h"
#include "test_support.h"

using namespace strata;

namespace {

std::string formatError(const std::filesystem::path& path) {
    try {
        sceneFormatOf(path);
    } catch (const Error& e) {
        return e.what();
    }
    return "no error";
}

void checkSameMesh(const MeshData& a, const MeshData& b) {
    CHECK(a.positions == b.positions);
    CHECK(a.triangles == b.triangles);
    CHECK(a.triangleMaterials == b.triangleMaterials);
    REQUIRE(a.materials.size() == b.materials.size());
    for (size_t i = 0; i < a.materials.size(); ++i) {
        CAPTURE(i);
        CHECK(a.materials[i].name == b.materials[i].name);
        CHECK(a.materials[i].diffuse == b.materials[i].diffuse);
        CHECK(a.materials[i].emission == b.materials[i].emission);
        CHECK(a.materials[i].specular == b.materials[i].specular);
        CHECK(a.materials[i].roughness == b.materials[i].roughness);
    }
}

}  // namespace

TEST_CASE("scene formats: the extension picks the format, in any case") {
    const SceneFormat& obj = sceneFormatOf("scene.obj");
    CHECK((obj.read == &readObjScene));
    CHECK(&sceneFormatOf("SCENE.OBJ") == &obj);
    CHECK(&sceneFormatOf("some/folder.x/Scene.Obj") == &obj);
    const SceneFormat& gltf = sceneFormatOf("scene.gltf");
    CHECK((gltf.read == &readGltfScene));
    CHECK((gltf.parse == &parseGltfScene));
    CHECK(&sceneFormatOf("dir/Scene.GLB") == &gltf);
    CHECK(knownSceneExtensions() == ".obj, .gltf, .glb");
    CHECK(sceneExtensions() == std::vector<std::string_view>{".obj", ".gltf", ".glb"});
    CHECK(lowerCaseExtension("some/folder.X/Scene.GLB") == ".glb");
    CHECK(lowerCaseExtension("some/folder.X/Scene").empty());
}

TEST_CASE("scene formats: an unknown extension is one line naming the file, it and the known ones") {
    CHECK(formatError("model.fbx") == "model.fbx: unknown scene format '.fbx' (known: .obj, .gltf, .glb)");
    CHECK(formatError("dir/model.FBX") == "dir/model.FBX: unknown scene format '.FBX' (known: .obj, .gltf, .glb)");
    CHECK(formatError("model.obj.bak") == "model.obj.bak: unknown scene format '.bak' (known: .obj, .gltf, .glb)");
    CHECK(formatError("model") == "model: no extension to tell the scene format (known: .obj, .gltf, .glb)");

    // Refused before any parsing: this file would fail as an OBJ with a message of its own.
    const auto dir = test::scratchDir("scene-format-unknown");
    std::ofstream(dir / "model.fbx") << "v 0 0 0\nf 1 2\n";
    CHECK_THROWS_WITH_AS(readSceneBundle(dir / "model.fbx"),
                         ((dir / "model.fbx").string() + ": unknown scene format '.fbx' (known: .obj, .gltf, .glb)").c_str(),
                         Error);
    // A missing file is missing whatever its extension.
    CHECK_THROWS_WITH_AS(readSceneBundle(dir / "absent.fbx"),
                         ((dir / "absent.fbx").string() + ": no such scene file").c_str(), Error);
    // A scene file named in capitals loads as one in lower case.
    std::ofstream(dir / "TRI.OBJ") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    CHECK(loadScene(dir / "TRI.OBJ").scene.summary().triangles == 1);
}

TEST_CASE("scene formats: a bundle read from disk parses from memory, on any host, to the same mesh") {
    const auto obj = test::sourceDir() / "assets/glossy/glossy.obj";
    const SceneBundle read = readSceneBundle(obj);
    CHECK(read.path == obj);
    REQUIRE(read.files.size() == 2);
    CHECK(read.files[0].name == "glossy.obj");
    CHECK(read.files[1].name == "glossy.mtl");
    CHECK(read.files[0].bytes == test::fileBytes(obj));
    REQUIRE(read.description);
    CHECK(read.description->name == "glossy.json");
    CHECK_FALSE(read.camera);

    // The bytes as another rank receives them, where the scene's folder does not exist.
    SceneBundle received = read;
    received.path = "/nowhere/glossy.obj";
    const MeshData fromMemory = parseSceneMesh(received);
    checkSameMesh(fromMemory, loadObjFile(obj));
    checkSameMesh(fromMemory, parseObj(read.files[0].bytes, "glossy.obj", read.files[1].bytes + "\n",
                                       "glossy.mtl"));
    // The same bundle written by hand.
    const SceneBundle byHand{"glossy.obj",
                             {{"glossy.obj", test::fileBytes(obj)},
                              {"glossy.mtl", test::fileBytes(test::sourceDir() / "assets/glossy/glossy.mtl")}},
                             std::nullopt,
                             std::nullopt};
    checkSameMesh(parseSceneMesh(byHand), fromMemory);
}

TEST_CASE("scene formats: an OBJ's MTL files travel by the names its mtllib lines give") {
    const auto dir = test::scratchDir("scene-format-mtl");
    std::filesystem::create_directories(dir / "materials");
    std::ofstream(dir / "a.obj") << "mtllib materials/one.mtl two.mtl materials/one.mtl\n"
                                    "v 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl lamp\nf 1 2 3\nusemtl white\nf 1 3 2\n";
    std::ofstream(dir / "materials/one.mtl") << "newmtl white\nKd 0.5 0.6 0.7\n";
    std::ofstream(dir / "two.mtl") << "newmtl lamp\nKd 0 0 0\nKe 3 2 1\nKs 0.04 0.04 0.04\nPr 0.3\n";
    const SceneBundle bundle = readSceneBundle(dir / "a.obj");
    REQUIRE(bundle.files.size() == 3);  // each file once, however often it is named
    CHECK(bundle.files[1].name == "materials/one.mtl");
    CHECK(bundle.files[2].name == "two.mtl");
    CHECK_FALSE(bundle.description);

    SceneBundle elsewhere = bundle;
    elsewhere.path = "other/host/a.obj";
    const MeshData mesh = parseSceneMesh(elsewhere);
    checkSameMesh(mesh, loadObjFile(dir / "a.obj"));
    REQUIRE(mesh.triangles.size() == 2);
    const Material& lamp = mesh.materials[mesh.triangleMaterials[0]];
    CHECK(lamp.emission == glm::vec3(3, 2, 1));
    CHECK(lamp.roughness == doctest::Approx(0.3));  // Pr of the second file read as given

    // A bad line is named by its file and line, under the name the bundle was read from.
    elsewhere.files[2].bytes = "newmtl lamp\nKd 0 oops 0\n";
    CHECK_THROWS_WITH_AS(parseSceneMesh(elsewhere), "other/host/two.mtl:2: 'oops' is not a number", Error);
    // A library the bundle lacks is a warning, as a missing file is where the bundle was read.
    elsewhere.files.pop_back();
    LoadReport report;
    parseSceneMesh(elsewhere, &report);
    CHECK(report.warnings ==
          std::vector<std::string>{
              "other/host/a.obj:1: material library 'two.mtl' is missing; its materials are not defined",
              "other/host/a.obj:5: material 'lamp' is not defined; using grey Kd 0.8"});
}
