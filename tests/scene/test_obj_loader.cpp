#include <doctest/doctest.h>

#include <fstream>

#include "util/error.h"
#include "scene/obj_loader.h"
#include "test_support.h"

using namespace strata;

namespace {
const char* kMtl = "newmtl white\nKd 0.5 0.6 0.7\nnewmtl lamp\nKd 0 0 0\nKe 3 2 1\n";

std::string errorOf(const std::string& obj, const std::string& mtl = kMtl) {
    try {
        parseObj("mtllib scene.mtl\n" + obj, "scene.obj", mtl, "scene.mtl");
    } catch (const Error& e) {
        return e.what();
    }
    return "no error";
}
}  // namespace

TEST_CASE("obj: quads are triangulated, materials and emission read") {
    LoadReport report;
    const MeshData mesh = parseObj(
        "mtllib scene.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nusemtl white\nf 1 2 3 4\nusemtl lamp\nf -4 -2 -1\n",
        "scene.obj", kMtl, "scene.mtl", &report);
    CHECK(mesh.triangles.size() == 3);
    CHECK(report.faces == 3);
    REQUIRE(mesh.materials.size() == 2);
    CHECK(mesh.materials[mesh.triangleMaterials[0]].diffuse.y == doctest::Approx(0.6));
    CHECK(mesh.materials[mesh.triangleMaterials[2]].emission.x == doctest::Approx(3.0));
    // Negative indices count back from the last vertex: -4 -2 -1 = 1 3 4.
    CHECK(mesh.triangles[2] == std::array<uint32_t, 3>{0, 2, 3});
}

TEST_CASE("obj: degenerate triangles are dropped and counted") {
    LoadReport report;
    const MeshData mesh = parseObj("v 0 0 0\nv 1 0 0\nv 2 0 0\nv 0 1 0\nf 1 2 3\nf 1 1 4\nf 1 2 4\n",
                                   "scene.obj", "", "scene.mtl", &report);
    CHECK(mesh.triangles.size() == 1);
    CHECK(report.droppedTriangles == 2);
    CHECK(mesh.materials.back().name == "(default)");
}

TEST_CASE("obj: malformed lines name the file and the line") {
        // errorOf puts an mtllib line first: OBJ line numbers below are one more than the string's.
    CHECK(errorOf("v 0 0 0\nv 1 x 0\n") == "scene.obj:3: 'x' is not a number");
    CHECK(errorOf("v 0 0\n") == "scene.obj:2: 'v' takes 3 to 7 numbers, got 2");
    CHECK(errorOf("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n") ==
          "scene.obj:5: vertex index 9 is out of range (3 vertices so far)");
    CHECK(errorOf("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\n") == "scene.obj:5: a face needs at least 3 vertices");
    CHECK(errorOf("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2/a 3\n") == "scene.obj:5: '2/a' is not a face vertex");
    CHECK(errorOf("v 0 0 0\n", "newmtl m\nKd 0.5 oops 1\n") == "scene.mtl:2: 'oops' is not a number");
    CHECK(errorOf("v 0 0 0\n", "Kd 1 1 1\n") == "scene.mtl:1: 'Kd' before any newmtl");
    CHECK(errorOf("v 0 0 0\n", "newmtl hot\nKd 1.5 0 0\n").find("Kd above 1") != std::string::npos);
    CHECK(errorOf("v 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl nothere\nf 1 2 3\n").find("nothere") !=
          std::string::npos);
}

TEST_CASE("obj: files on disk, a missing MTL is an error naming it") {
    const auto dir = test::scratchDir("obj-files");
    std::ofstream(dir / "a.obj") << "mtllib a.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl white\nf 1 2 3\n";
    std::ofstream(dir / "a.mtl") << kMtl;
    CHECK(loadObjFile(dir / "a.obj").triangles.size() == 1);
    std::ofstream(dir / "b.obj") << "mtllib gone.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    try {
        loadObjFile(dir / "b.obj");
        FAIL("expected an error");
    } catch (const Error& e) {
        CHECK(std::string(e.what()).find("gone.mtl: cannot open") != std::string::npos);
    }
    CHECK_THROWS_WITH_AS(loadObjFile(dir / "none.obj"), doctest::Contains("none.obj: cannot open"), Error);
}
