#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <fstream>
#include <initializer_list>
#include <set>
#include <string>
#include <vector>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "util/error.h"
#include "scene/obj_loader.h"
#include "scene/scene_loader.h"
#include "materials/material_table.h"
#include "materials/microfacet.h"
#include "test_support.h"

using namespace strata;

namespace {
const char* kMtl = "newmtl white\nKd 0.5 0.6 0.7\nnewmtl lamp\nKd 0 0 0\nKe 3 2 1\n";

// An OBJ of scene.mtl's materials `names`, a triangle each, in that order.
std::string trianglePerMaterial(std::initializer_list<const char*> names) {
    std::string obj = "mtllib scene.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\n";
    for (const char* name : names) obj += std::string("usemtl ") + name + "\nf 1 2 3\n";
    return obj;
}

std::string objError(const std::string& obj, const std::string& mtl = kMtl) {
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
    CHECK(mesh.materials.back().name == "default");
    CHECK(mesh.materials.back().diffuse == glm::vec3(0.8f));
    CHECK(report.warnings.empty());
}

TEST_CASE("obj: malformed lines name the file and the line") {
        // errorOf puts an mtllib line first: OBJ line numbers below are one more than the string's.
    CHECK(objError("v 0 0 0\nv 1 x 0\n") == "scene.obj:3: 'x' is not a number");
    CHECK(objError("v 0 0\n") == "scene.obj:2: 'v' takes 3 to 7 numbers, got 2");
    CHECK(objError("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n") ==
          "scene.obj:5: vertex index 9 is out of range (3 vertices so far)");
    CHECK(objError("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\n") == "scene.obj:5: a face needs at least 3 vertices");
    CHECK(objError("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2/a 3\n") == "scene.obj:5: '2/a' is not a face vertex");
    CHECK(objError("v 0 0 0\n", "newmtl m\nKd 0.5 oops 1\n") == "scene.mtl:2: 'oops' is not a number");
    CHECK(objError("v 0 0 0\n", "Kd 1 1 1\n") == "scene.mtl:1: 'Kd' before any newmtl");
    CHECK(objError("v 0 0 0\n", "# hot\nnewmtl hot\nKd 1.5 0 0\n") ==
          "scene.mtl:2: material 'hot' has Kd above 1 (creates energy)");
    CHECK(objError("vn 0 x 1\n") == "scene.obj:2: 'x' is not a number");
    CHECK(objError("vn 0 1\n") == "scene.obj:2: 'vn' takes 3 numbers, got 2");
    CHECK(objError("vn 0 0 1e39\n") == "scene.obj:2: '1e39' is out of range for a 32-bit float");
    CHECK(objError("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//2\n") ==
          "scene.obj:6: normal index 2 is out of range (1 normals so far)");
    CHECK(objError("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/-2 3/1\n") ==
          "scene.obj:6: texture coordinate index -2 is out of range (1 texture coordinates so far)");
    CHECK(objError("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/1/1/1 2 3\n") == "scene.obj:5: '1/1/1/1' is not a face vertex");
    CHECK_THROWS_WITH_AS(parseObj(std::string("\xFF\xFEv\0 ", 5), "utf16.obj", "", "m.mtl"),
                         "utf16.obj: UTF-16 text of an odd number of bytes", Error);
}

TEST_CASE("obj: a file of only points or lines is refused as such, not as a scene without triangles") {
    const auto errorOfObj = [](const std::string& text) {
        try {
            parseObj(text, "scene.obj", "", "scene.mtl");
        } catch (const Error& error) {
            return std::string(error.what());
        }
        return std::string("(loaded)");
    };
    CHECK(errorOfObj("v 0 0 0\nv 1 0 0\nv 0 1 0\n") ==
          "scene.obj: the file holds only points (3 vertices, no faces); Strata renders faces");
    CHECK(errorOfObj("v 0 0 0\nv 1 0 0\nv 0 1 0\np 1 2 3\n") ==
          "scene.obj: the file holds only points (3 vertices, no faces); Strata renders faces");
    CHECK(errorOfObj("v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2 3\n") ==
          "scene.obj: the file holds only lines (3 vertices, no faces); Strata renders faces");
    CHECK(errorOfObj("v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2\nf 1 2 3\n") == "(loaded)");
}

TEST_CASE("obj: UTF-16 text with its byte-order mark, either byte order, is read as UTF-8") {
    // A comment with a character beyond the BMP (a surrogate pair) and one with an unpaired
    // surrogate, before a triangle.
    const std::u16string text = u"# \U0001F600 \xD800\nv 0 0 0\nv 2 0 0\nv 0 3 0\nf 1 2 3\n";
    for (const bool bigEndian : {true, false}) {
        CAPTURE(bigEndian);
        std::string bytes = bigEndian ? "\xFE\xFF" : "\xFF\xFE";
        for (const char16_t unit : text) {
            const auto hi = static_cast<char>(unit >> 8);
            const auto lo = static_cast<char>(unit & 0xFF);
            bytes += bigEndian ? std::string{hi, lo} : std::string{lo, hi};
        }
        const MeshData mesh = parseObj(bytes, "utf16.obj", "", "m.mtl");
        REQUIRE(mesh.triangles.size() == 1);
        CHECK(mesh.positions[1] == glm::vec3(2, 0, 0));
        CHECK(mesh.positions[2] == glm::vec3(0, 3, 0));
    }
}


TEST_CASE("obj: a UTF-8 byte-order mark is read past") {
    const MeshData mesh = parseObj("\xEF\xBB\xBFv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "bom.obj", "", "m.mtl");
    CHECK(mesh.triangles.size() == 1);
}

TEST_CASE("obj: a usemtl of an undefined material renders grey, with one warning per name") {
    LoadReport report;
    const MeshData mesh = parseObj(
        "mtllib scene.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nusemtl red\nf 1 2 3\nusemtl white\nf 2 4 3\n"
        "usemtl red\nf 3 2 4\n",
        "scene.obj", kMtl, "scene.mtl", &report);
    REQUIRE(mesh.triangles.size() == 3);
    REQUIRE(report.warnings.size() == 1);
    CHECK(report.warnings[0] == "scene.obj:6: material 'red' is not defined; using grey Kd 0.8");
    const Material& grey = mesh.materials[mesh.triangleMaterials[0]];
    CHECK(grey.name == "default");
    CHECK(grey.diffuse == glm::vec3(0.8f));
    CHECK(grey.emission == glm::vec3(0.0f));
    CHECK(mesh.materials[mesh.triangleMaterials[1]].name == "white");
    CHECK(mesh.triangleMaterials[2] == mesh.triangleMaterials[0]);
    // Without any mtllib no material is defined.
    LoadReport bare;
    parseObj("v 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl Default\nf 1 2 3\n", "box.obj", "", "box.mtl", &bare);
    CHECK(bare.warnings == std::vector<std::string>{"box.obj:4: material 'Default' is not defined; using grey Kd 0.8"});
}

TEST_CASE("obj: an empty usemtl renders grey with a warning, even beside a newmtl without a name") {
    LoadReport report;
    const MeshData mesh = parseObj("mtllib scene.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl   \t\nf 1 2 3\n",
                                   "scene.obj", "newmtl \nKd 0.1 0.1 0.1\n", "scene.mtl", &report);
    REQUIRE(mesh.triangles.size() == 1);
    CHECK(mesh.materials[mesh.triangleMaterials[0]].diffuse == glm::vec3(0.8f));
    CHECK(report.warnings == std::vector<std::string>{"scene.obj:5: usemtl names no material; using grey Kd 0.8"});
}

TEST_CASE("obj: material names are the whole trimmed rest of the line, spaces inside kept") {
    // tinyobjloader alone cuts a usemtl name at its first space, which would pick "Hard".
    const char* mtl = "newmtl Hard\nKd 0.9 0.9 0.9\nnewmtl Hard Shiny  Plastic \t\nKd 0.1 0.2 0.3\n"
                      "newmtl Hard Shiny Plastic\nKd 0.4 0.4 0.4\n";
    LoadReport report;
    const MeshData mesh = parseObj(
        "mtllib scene.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl  Hard Shiny  Plastic   \nf 1 2 3\n"
        "usemtl Hard Shiny Plastic\nf 1 2 3\nusemtl Hard Shiny\nf 1 2 3\n",
        "scene.obj", mtl, "scene.mtl", &report);
    REQUIRE(mesh.triangles.size() == 3);
    CHECK(mesh.materials[mesh.triangleMaterials[0]].name == "Hard Shiny  Plastic");
    CHECK(mesh.materials[mesh.triangleMaterials[0]].diffuse == glm::vec3(0.1f, 0.2f, 0.3f));
    CHECK(mesh.materials[mesh.triangleMaterials[1]].diffuse == glm::vec3(0.4f));
    CHECK(mesh.materials[mesh.triangleMaterials[2]].name == "default");
    CHECK(report.warnings ==
          std::vector<std::string>{"scene.obj:9: material 'Hard Shiny' is not defined; using grey Kd 0.8"});
}

TEST_CASE("obj: a usemtl before its mtllib line finds the material, a repeated name its first") {
    LoadReport report;
    const MeshData mesh =
        parseObj("v 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl twice\nf 1 2 3\nmtllib scene.mtl\n", "scene.obj",
                 "newmtl twice\nKd 0.25 0.25 0.25\nnewmtl twice\nKd 0.75 0.75 0.75\n", "scene.mtl", &report);
    REQUIRE(mesh.triangles.size() == 1);
    CHECK(mesh.materials[mesh.triangleMaterials[0]].diffuse == glm::vec3(0.25f));
    CHECK(report.warnings.empty());
}

TEST_CASE("obj: MTL statements the renderer does not use are accepted as real files write them") {
    const char* mtl =
        "newmtl skin\nKa 0.2 0.2 0.2\nKd 0.5 0.25 0.125\nKs 0 0 0\nKe 0 0 0\nNs 10\nNi 1.45\nd 1\nTr 0\n"
        "Tf 1 1 1\nTf xyz 1 1 1\nillum 2\nKm 0.05\nmap_Kd -bm 1.0 -o 0 0 0 .\\skin tex.jpg\n"
        "map_d alpha.png\nmap_Ke glow.png\nnorm -bm 0.5 normal.png\nmap_Bump -bm 1.0 bump.png\n"
        "bump bump.png\nmap_Ks spec.png\nrefl -type sphere env.png\nsharpness 60\n";
    LoadReport report;
    const MeshData mesh = parseObj("mtllib scene.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0 0\n"
                                   "usemtl skin\nf 1/1 2/2 3/1\n",
                                   "scene.obj", mtl, "scene.mtl", &report);
    REQUIRE(mesh.triangles.size() == 1);
    CHECK(mesh.materials[mesh.triangleMaterials[0]].diffuse == glm::vec3(0.5f, 0.25f, 0.125f));
    // The texture statements Strata reads name files that an inline MTL has not got: each one
    // is a warning, the '\\' and the space read as a path; the others are silent.
    CHECK(report.warnings.size() == 6);
    for (const std::string& warning : report.warnings) {
        CHECK(warning.find("is missing; using the factor alone") != std::string::npos);
    }
    CHECK(report.warnings.front() == "scene.mtl:14: map_Kd: texture file 'skin tex.jpg' is missing; using the factor alone");
}

TEST_CASE("obj: vn gives unit shading normals per corner, in the order of the triangle's vertices") {
    LoadReport report;
    const MeshData mesh = parseObj("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 2\nvn 0 3 4\nvn -1 0 0\n"
                                   "f 1//2 2//3 3//1\nf 2//1 3 1//2\n",
                                   "scene.obj", "", "m.mtl", &report);
    REQUIRE(mesh.triangles.size() == 2);
    REQUIRE(mesh.normals.size() == 3);
    CHECK(mesh.normals[0] == glm::vec3(0.0f, 0.0f, 1.0f));
    CHECK(mesh.normals[1].y == doctest::Approx(0.6));
    CHECK(mesh.normals[1].z == doctest::Approx(0.8));
    CHECK(mesh.normals[2] == glm::vec3(-1.0f, 0.0f, 0.0f));
    REQUIRE(mesh.triangleNormals.size() == 2);
    CHECK(mesh.triangles[0] == std::array<uint32_t, 3>{0, 1, 2});
    CHECK(mesh.triangleNormals[0] == std::array<uint32_t, 3>{1, 2, 0});
    // A corner without vn makes its face flat.
    CHECK(mesh.triangleNormals[1] == kNoNormals);
    CHECK(report.warnings.empty());
}

TEST_CASE("obj: faces without vn leave the mesh without normals") {
    const MeshData mesh = parseObj("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1 2 3\n", "scene.obj", "", "m.mtl");
    CHECK(mesh.triangles.size() == 1);
    CHECK(mesh.normals.empty());
    CHECK(mesh.triangleNormals.empty());
}

TEST_CASE("obj: faces in a smoothing group without vn share normals within the group, edges between groups kept") {
    // A roof of two slopes meeting at the ridge x = 0 (normals (-1, 0, 1) and (1, 0, 1)), a
    // quad each, then a gable face and a face given its own vn.
    const MeshData mesh = parseObj("v -1 0 0\nv 0 0 1\nv 0 1 1\nv -1 1 0\nv 1 0 0\nv 1 1 0\nvn 0 1 0\n"
                                   "s 1\nf 1 2 3 4\nf 2 5 6 3\n"
                                   "s off\nf 1 5 2\n"
                                   "s 2\nf 4 3//1 6\n",
                                   "scene.obj", "", "m.mtl");
    REQUIRE(mesh.triangles.size() == 6);
    REQUIRE(mesh.triangleNormals.size() == 6);
    const auto normalAt = [&](size_t t, uint32_t vertex) {
        for (size_t k = 0; k < 3; ++k) {
            if (mesh.triangles[t][k] == vertex) return mesh.normals.at(mesh.triangleNormals[t][k]);
        }
        FAIL("vertex not in triangle");
        return glm::vec3(0.0f);
    };
    // The slopes in group 1: each ridge corner's normal is +z, each eave corner its slope's.
    for (size_t t = 0; t < 4; ++t) {
        CAPTURE(t);
        REQUIRE(mesh.triangleNormals[t] != kNoNormals);
        for (uint32_t v : mesh.triangles[t]) {
            const glm::vec3 n = normalAt(t, v);
            const glm::vec3 expected = mesh.positions[v].z == 1.0f ? glm::vec3(0, 0, 1)
                                                                    : glm::normalize(glm::vec3(mesh.positions[v].x, 0, 1));
            CHECK(glm::dot(n, expected) == doctest::Approx(1.0f));
        }
    }
    // `s off`: flat. A face with vn on some corners only takes its group's normals on all of
    // them: here, alone in group 2, its own (+y), not the file's vn.
    CHECK(mesh.triangleNormals[4] == kNoNormals);
    REQUIRE(mesh.triangleNormals[5] != kNoNormals);
    for (uint32_t v : mesh.triangles[5]) CHECK(normalAt(5, v) == glm::vec3(0.0f, 1.0f, 0.0f));
}

TEST_CASE("obj: v x y z r g b gives each vertex its colour, a vertex without one white, past 0..1 clamped") {
    LoadReport report;
    const MeshData mesh = parseObj("v 0 0 0\nv 1 0 0 0.2 0.4 0.6\nv 0 1 0 1 0.5 0.25 1\nv 1 1 0 2 -1 0.5\n"
                                   "f 1 2 3\nf 2 4 3\n",
                                   "scene.obj", "", "m.mtl", &report);
    REQUIRE(mesh.colours.size() == 4);
    CHECK(mesh.colours[0] == glm::vec3(1.0f));                 // no colour: white
    CHECK(mesh.colours[1] == glm::vec3(0.2f, 0.4f, 0.6f));     // x y z r g b
    CHECK(mesh.colours[2] == glm::vec3(0.5f, 0.25f, 1.0f));    // x y z w r g b: the last three
    CHECK(mesh.colours[3] == glm::vec3(1.0f, 0.0f, 0.5f));     // clamped
    // A triangle's colours are its vertices'.
    CHECK(mesh.triangleColours == mesh.triangles);
    REQUIRE(report.warnings.size() == 1);
    CHECK(report.warnings[0] == "scene.obj:4: vertex colours outside 0..1 are clamped to it (OBJ colours are fractions, not bytes)");
    // Without a colour on any v line, none.
    const MeshData plain = parseObj("v 0 0 0\nv 1 0 0 1\nv 0 1 0\nf 1 2 3\n", "scene.obj", "", "m.mtl");
    CHECK(plain.colours.empty());
    CHECK(plain.triangleColours.empty());
}

TEST_CASE("obj: a split polygon keeps each corner's normal, a dropped triangle its normals too") {
    // Vertex i has normal i on every corner, so each kept triangle's normals equal its vertices.
    const MeshData mesh = parseObj(
        "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nv 0.5 1.5 0\n"
        "vn 0 0 1\nvn 0 0.1 1\nvn 0.1 0 1\nvn 0 -0.1 1\nvn -0.1 0 1\nvn 0.1 0.1 1\n"
        "f 1//1 2//2 3//3 4//4\nf 1//1 2//2 5//5\nf 1//1 2//2 3//3 6//6 4//4\n",
        "scene.obj", "", "m.mtl");
    // The quad gives 2 triangles, the collinear triangle is dropped, the pentagon gives 3.
    REQUIRE(mesh.triangles.size() == 5);
    REQUIRE(mesh.triangleNormals.size() == 5);
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        CAPTURE(t);
        CHECK(mesh.triangleNormals[t] == mesh.triangles[t]);
    }
}

TEST_CASE("obj: a concave face is split inside its outline, its texture coordinates kept per corner") {
    // A C of area 7 seen from +z, in a plane the file tilts; corner i has vt i. A fan from the
    // first corner would cover the notch (area 9 in all) and hold triangles facing -z.
    LoadReport report;
    const MeshData mesh = parseObj(
        "v 0 0 0\nv 3 0 0\nv 3 1 0\nv 1 1 0\nv 1 2 0\nv 3 2 0\nv 3 3 0\nv 0 3 0\n"
        "vt 0 0\nvt 1 0\nvt 2 0\nvt 3 0\nvt 4 0\nvt 5 0\nvt 6 0\nvt 7 0\n"
        "f 1/1 2/2 3/3 4/4 5/5 6/6 7/7 8/8\n",
        "scene.obj", "", "m.mtl", &report);
    REQUIRE(mesh.triangles.size() == 6);
    CHECK(report.warnings.empty());
    float area = 0.0f;
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        CAPTURE(t);
        const auto& [a, b, c] = mesh.triangles[t];
        const glm::vec3 normal =
            glm::cross(mesh.positions[b] - mesh.positions[a], mesh.positions[c] - mesh.positions[a]);
        CHECK(normal.z > 0.0f);
        area += 0.5f * normal.z;
        for (size_t k = 0; k < 3; ++k) CHECK(mesh.uvs[mesh.triangleUvs[t][k]].x == float(mesh.triangles[t][k]));
    }
    CHECK(area == doctest::Approx(7.0));
}

TEST_CASE("obj: a face of more than 255 corners keeps them all, between groups and materials") {
    // A quad, then a star of 300 corners (concave at every other one), then a triangle, each in a
    // group of its own and the star with another material: tinyobjloader counts a face's corners
    // in a byte, which would lose 256 of the star's.
    const int corners = 300;
    std::string obj = "mtllib scene.mtl\nv 10 0 0\nv 11 0 0\nv 11 1 0\nv 10 1 0\n";
    double starArea = 0.0;
    for (int i = 0; i < corners; ++i) {
        const double angle = 2.0 * std::numbers::pi * i / corners;
        const double radius = i % 2 ? 0.5 : 1.0;
        obj += "v " + std::to_string(radius * std::cos(angle)) + " " + std::to_string(radius * std::sin(angle)) +
               " 0\n";
    }
    obj += "v 20 0 0\nv 21 0 0\nv 20 1 0\ng quad\nusemtl white\nf 1 2 3 4\ng star\nusemtl lamp\nf";
    for (int i = 0; i < corners; ++i) obj += " " + std::to_string(5 + i);
    obj += "\ng last\nusemtl white\nf -3 -2 -1\n";
    const MeshData mesh = parseObj(obj, "scene.obj", kMtl, "scene.mtl");
    REQUIRE(mesh.triangles.size() == 2 + (corners - 2) + 1);
    for (int i = 0; i < corners; ++i) {
        const glm::dvec2 a(mesh.positions[4 + i]);
        const glm::dvec2 b(mesh.positions[4 + (i + 1) % corners]);
        starArea += 0.5 * (a.x * b.y - a.y * b.x);
    }
    double area = 0.0;
    for (size_t t = 2; t < 2 + corners - 2; ++t) {
        CAPTURE(t);
        CHECK(mesh.materials[mesh.triangleMaterials[t]].name == "lamp");
        const auto& [a, b, c] = mesh.triangles[t];
        for (uint32_t v : mesh.triangles[t]) CHECK((v >= 4 && v < 4 + corners));
        area += 0.5 * glm::cross(mesh.positions[b] - mesh.positions[a], mesh.positions[c] - mesh.positions[a]).z;
    }
    CHECK(area == doctest::Approx(starArea).epsilon(1e-5));
    CHECK(mesh.materials[mesh.triangleMaterials[0]].name == "white");
    CHECK(mesh.materials[mesh.triangleMaterials.back()].name == "white");
    CHECK(mesh.triangles.back() == std::array<uint32_t, 3>{4 + corners, 5 + corners, 6 + corners});
}

TEST_CASE("obj: a zero or non-finite vn shades its triangles flat, with one warning for the file") {
    LoadReport report;
    const MeshData mesh = parseObj("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nvn 0 0 0\nvn nan 0 1\nvn 0 0 1e-50\n"
                                   "f 1//1 2//2 3//1\nf 1//3 2//1 3//1\nf 1//4 2//1 3//1\nf 1//1 2//1 3//1\n",
                                   "scene.obj", "", "m.mtl", &report);
    REQUIRE(mesh.triangles.size() == 4);
    REQUIRE(mesh.normals.size() == 1);
    CHECK(mesh.triangleNormals[0] == kNoNormals);
    CHECK(mesh.triangleNormals[1] == kNoNormals);
    CHECK(mesh.triangleNormals[2] == kNoNormals);
    CHECK(mesh.triangleNormals[3] == std::array<uint32_t, 3>{0, 0, 0});
    CHECK(report.warnings == std::vector<std::string>{
                                 "scene.obj:5: vn is zero or not finite; 3 triangles using such normals are shaded flat"});
}

TEST_CASE("obj: files on disk, a missing MTL is a warning naming it and its line") {
    const auto dir = test::scratchDir("obj-files");
    std::ofstream(dir / "a.obj") << "mtllib a.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl white\nf 1 2 3\n";
    std::ofstream(dir / "a.mtl") << kMtl;
    LoadReport found;
    CHECK(loadObjFile(dir / "a.obj", &found).materials.at(0).name == "white");
    CHECK(found.warnings.empty());

    std::ofstream(dir / "b.obj") << "# b\nmtllib gone.mtl a.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl white\nf 1 2 3\n"
                                    "mtllib\nusemtl lost\nf 1 2 3\n";
    // Reading leaves the missing library out rather than failing.
    SceneFolder folder(dir / "b.obj", {});
    const auto files = readObjScene(dir / "b.obj", folder);
    REQUIRE(files.size() == 2);
    CHECK(files[1].name == "a.mtl");
    LoadReport report;
    const MeshData mesh = loadObjFile(dir / "b.obj", &report);
    REQUIRE(mesh.triangles.size() == 2);
    CHECK(mesh.materials[mesh.triangleMaterials[0]].name == "white");
    CHECK(mesh.materials[mesh.triangleMaterials[1]].name == "default");
    const std::string b = (dir / "b.obj").string();
    CHECK(report.warnings == std::vector<std::string>{
                                 b + ":8: mtllib names no file",
                                 b + ":2: material library 'gone.mtl' is missing; its materials are not defined",
                                 b + ":9: material 'lost' is not defined; using grey Kd 0.8"});
    CHECK_THROWS_WITH_AS(loadObjFile(dir / "none.obj"), doctest::Contains("none.obj: cannot open"), Error);
}

TEST_CASE("obj: reading finds the mtllib files as parsing does, and leaves the other lines to parsing") {
    const auto dir = test::scratchDir("obj-libraries");
    for (const char* name : {"a.mtl", "b.mtl", "c.mtl", "d.mtl"}) std::ofstream(dir / name) << kMtl;
    // Indented, tab-separated, commented; a word that only starts with mtllib and a comment are not
    // statements. Line 6 is malformed: reading does not check it, parsing names it.
    std::ofstream(dir / "s.obj") << "  mtllib a.mtl\n\tmtllib\tb.mtl c.mtl # d.mtl\nmtllibs d.mtl\n# mtllib d.mtl\n"
                                    "v 0 0 0\nv 1 0\n";
    SceneFolder folder(dir / "s.obj", {});
    const auto files = readObjScene(dir / "s.obj", folder);
    std::vector<std::string> names;
    for (const SceneFile& file : files) names.push_back(file.name);
    CHECK(names == std::vector<std::string>{"s.obj", "a.mtl", "b.mtl", "c.mtl"});
    CHECK_THROWS_WITH_AS(loadObjFile(dir / "s.obj"), doctest::Contains("s.obj:6: 'v' takes 3 to 7 numbers, got 2"),
                         Error);
}

TEST_CASE("obj: the models of Debian's assimp-testmodels load or are refused in one line") {
    const std::filesystem::path folder = "/usr/share/assimp/models/OBJ";
    if (!std::filesystem::is_directory(folder)) {
        MESSAGE("skipped: " << folder.string() << " is absent (Debian package assimp-testmodels)");
        return;
    }
    // Models that assimp and Blender open; the others are test files of broken input.
    const std::set<std::string> mustLoad = {
        "box.obj", "box_longline.obj", "box_mat_with_spaces.obj", "box_UTF16BE.obj", "box_without_lineending.obj",
        "concave_polygon.obj", "cube_mtllib_after_g.obj", "cube_usemtl.obj",
        "cube_with_vertexcolors.obj", "cube_with_vertexcolors_uni.obj", "empty_mat.obj",
        "multiple_spaces.obj", "regr01.obj", "regr_3429812.obj", "space_in_material_name.obj",
        "spider.obj", "testmixed.obj", "WusonOBJ.obj"};
    // Loading is linear in the file size; a larger file of a later package is not worth the time.
    constexpr std::uintmax_t kLargestBytes = 4 << 20;
    size_t loaded = 0;
    size_t models = 0;
    for (const auto& entry : std::filesystem::directory_iterator(folder)) {
        const std::filesystem::path& path = entry.path();
        if (path.extension() != ".obj" || entry.file_size() > kLargestBytes) continue;
        ++models;
        const std::string name = path.filename().string();
        CAPTURE(name);
        try {
            const LoadedScene scene = parseScene(readSceneBundle(path));
            CHECK(scene.scene.summary().triangles > 0);
            ++loaded;
        } catch (const Error& e) {
            const std::string message = e.what();
            MESSAGE("refused: " << message);
            CHECK(message.find(path.string()) != std::string::npos);
            CHECK(message.find('\n') == std::string::npos);
            CHECK(mustLoad.count(name) == 0);
        }
    }
    MESSAGE(loaded << " of " << models << " models in " << folder.string() << " loaded");
}

TEST_CASE("obj: illum 4, 6 and 7 are dielectrics, and illum 3 and 5 with Pr 0 or Ns >= 10000 are mirrors") {
    const std::string mtl =
        "newmtl glass\nKd 0.5 0.5 0.5\nKs 0.3 0.3 0.3\nillum 7\nNi 1.33\nTf 0.9 0.8 0.7\n"
        "newmtl frosted\nillum 4\nPr 0.4\n"
        "newmtl window\nillum 6\n"
        "newmtl mirror\nKs 0.9 0.8 0.7\nillum 3\nPr 0\n"
        "newmtl chrome\nKs 0.5 0.5 0.5\nillum 5\nNs 12000\n"
        "newmtl satin\nKs 0.5 0.5 0.5\nillum 3\nNs 200\n"
        "newmtl plastic\nKd 0.2 0.2 0.2\nKs 0.5 0.5 0.5\nillum 2\nPr 0\n";
    const std::string obj = trianglePerMaterial({"glass", "frosted", "window", "mirror", "chrome", "satin", "plastic"});
    const MeshData mesh = parseObj(obj, "scene.obj", mtl, "scene.mtl");
    REQUIRE(mesh.materials.size() >= 7);
    const auto byName = [&](const std::string& name) -> const Material& {
        for (const Material& m : mesh.materials) {
            if (m.name == name) return m;
        }
        FAIL("no material " << name);
        return mesh.materials.front();
    };
    const Material& glass = byName("glass");
    CHECK(glass.transmission == 1.0f);
    CHECK(glass.ior == doctest::Approx(1.33));
    CHECK(glass.transmissionFilter == glm::vec3(0.9f, 0.8f, 0.7f));
    CHECK(glass.roughness == 0.0f);                // no Pr: smooth
    CHECK(glass.diffuse == glm::vec3(0.0f));       // its Kd is ignored
    CHECK(glass.specular == glm::vec3(0.0f));
    CHECK(byName("frosted").roughness == doctest::Approx(0.4));
    CHECK(byName("frosted").ior == 1.5f);          // no Ni: 1.5
    CHECK(byName("frosted").transmissionFilter == glm::vec3(1.0f));
    CHECK(byName("window").transmission == 1.0f);
    CHECK(byName("mirror").roughness == 0.0f);
    CHECK(byName("mirror").specular == glm::vec3(0.9f, 0.8f, 0.7f));
    CHECK(byName("mirror").transmission == 0.0f);
    CHECK(byName("chrome").roughness == 0.0f);     // Ns 12000 without Pr
    CHECK(byName("satin").roughness > 0.1f);       // Ns 200: glossy, not a mirror
    CHECK(byName("plastic").roughness == 0.0f);    // Pr 0 under illum 2: the layered model's limit
    CHECK(byName("plastic").transmission == 0.0f);
    // What those become (material_table.h).
    const MaterialTable table(mesh.materials);
    const auto modelOf = [&](const std::string& name) {
        for (uint32_t i = 0; i < mesh.materials.size(); ++i) {
            if (mesh.materials[i].name == name) return table.bsdf(i);
        }
        return table.bsdf(0);
    };
    CHECK(modelOf("glass").as<SmoothDielectric>() != nullptr);
    CHECK(modelOf("frosted").as<RoughDielectric>() != nullptr);
    CHECK(modelOf("mirror").as<SmoothConductor>() != nullptr);
    CHECK(modelOf("chrome").as<SmoothConductor>() != nullptr);
    CHECK(modelOf("satin").as<LayeredBsdf>() != nullptr);
    CHECK(modelOf("plastic").as<Coated<LayeredBsdf>>() != nullptr);
}

TEST_CASE("obj: a dielectric's Ni and Tf are checked") {
    const auto error = [](const std::string& material) {
        return objError("v 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl g\nf 1 2 3\n", "newmtl g\nillum 7\n" + material);
    };
    CHECK(error("Ni 0\n") == "scene.mtl:1: material 'g' (illum 7, a dielectric) has an Ni that is not a positive number");
    CHECK(error("Tf 1.5 1 1\n") == "scene.mtl:1: material 'g' has a Tf outside 0..1");
    CHECK(error("Ni x\n") == "scene.mtl:3: 'x' is not a number");
}

TEST_CASE("obj: a Tf in CIE XYZ or spectral form is skipped, with a warning only where it would be used") {
    const std::string obj = "mtllib scene.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl glass\nf 1 2 3\nusemtl paint\nf 1 2 3\n";
    const std::string mtl = "newmtl glass\nillum 7\nTf xyz 0.5 0.5 0.5\nnewmtl paint\nillum 2\nTf spectral glass.rfl\n";
    LoadReport report;
    const MeshData mesh = parseObj(obj, "scene.obj", mtl, "scene.mtl", &report);
    REQUIRE(mesh.materials.size() >= 2);
    CHECK(mesh.materials[0].transmissionFilter == glm::vec3(1.0f));
    CHECK(report.warnings ==
          std::vector<std::string>{"scene.mtl:3: Tf in CIE XYZ or spectral form is not read; the filter is 1 1 1"});
}

TEST_CASE("obj: Pm makes Kd a base colour of glTF's metallic-roughness model, Pc and Pcr a clear coat") {
    // As Blender writes them (export_pbr_extensions): Ks is its Principled BSDF's Specular.
    const std::string mtl =
        "# Blender 3.4.1 MTL File: 'None'\n"
        "newmtl gold\nKd 1 0.7 0.3\nKs 0.5 0.5 0.5\nillum 3\nPr 0.3\nPm 1\nPs 0\nPc 0\nPcr 0.03\naniso 0\nanisor 0\n"
        "newmtl plastic\nKd 0.1 0.3 0.8\nKs 0.5 0.5 0.5\nillum 2\nPr 0.2\nPm 0\n"
        "newmtl half\nKd 0.6 0.6 0.2\nPm 0.5\n"
        "newmtl coated\nKd 0.6 0.05 0.05\nKs 0.25 0.25 0.25\nPr 0.6\nPm 0\nPc 1\nPcr 0.1\n"
        "newmtl velvet\nKd 0.3 0.05 0.3\nPm 0\nPs 1\n";
    const std::string obj = trianglePerMaterial({"gold", "plastic", "half", "coated", "velvet"});
    LoadReport report;
    const MeshData mesh = parseObj(obj, "scene.obj", mtl, "scene.mtl", &report);
    REQUIRE(mesh.materials.size() >= 5);
    const auto near = [](const glm::vec3& a, const glm::vec3& b) {
        return glm::all(glm::lessThanEqual(glm::abs(a - b), glm::vec3(1e-6f)));
    };
    // Metallic 1: no diffuse base, F0 the base colour (illum 3 changes nothing).
    const Material& gold = mesh.materials[0];
    CHECK(near(gold.diffuse, glm::vec3(0.0f)));
    CHECK(near(gold.specular, glm::vec3(1.0f, 0.7f, 0.3f)));
    CHECK(gold.roughness == doctest::Approx(0.3));
    CHECK(gold.clearcoat == 0.0f);
    // Untextured, the model needs no keeping per hit.
    CHECK_FALSE(gold.metallicRoughness);
    // Metallic 0: Kd as it is, F0 = 0.08 Ks = 0.04.
    const Material& plastic = mesh.materials[1];
    CHECK(near(plastic.diffuse, glm::vec3(0.1f, 0.3f, 0.8f)));
    CHECK(near(plastic.specular, glm::vec3(0.04f)));
    // Metallic 0.5 without Ks: half the base colour diffuse, F0 halfway from 0.04 to it.
    const Material& half = mesh.materials[2];
    CHECK(near(half.diffuse, glm::vec3(0.3f, 0.3f, 0.1f)));
    CHECK(near(half.specular, glm::vec3(0.32f, 0.32f, 0.12f)));
    const Material& coated = mesh.materials[3];
    CHECK(near(coated.specular, glm::vec3(0.02f)));
    CHECK(coated.clearcoat == 1.0f);
    CHECK(coated.clearcoatRoughness == doctest::Approx(0.1));
    // Ps is not read: the one warning, at its line, only where it is not 0.
    CHECK(mesh.materials[4].sheenColour == glm::vec3(0.0f));
    CHECK(report.warnings == std::vector<std::string>{"scene.mtl:32: Ps (a sheen) is not read"});
}

TEST_CASE("obj: Pm, Pc and Pcr outside 0..1 name the material") {
    const auto error = [](const std::string& material) {
        return objError("v 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl m\nf 1 2 3\n", "newmtl m\nKd 0.5 0.5 0.5\n" + material);
    };
    CHECK(error("Pm 1.5\n") == "scene.mtl:1: material 'm' has Pm outside 0..1");
    CHECK(error("Pc -1\n") == "scene.mtl:1: material 'm' has Pc outside 0..1");
    CHECK(error("Pcr 2\n") == "scene.mtl:1: material 'm' has Pcr outside 0..1");
    CHECK(error("Pm nan\n") == "scene.mtl:3: 'nan' is not a finite number");
    CHECK(error("Pm 0.5 1\n").find("scene.mtl:3:") == 0);
}

TEST_CASE("obj: d (or Tr) below 1 is an opacity of the opaque models, as Blender reads it") {
    const char* mtl =
        "newmtl pane\nKd 0.6 0.7 0.8\nd 0.4\n"
        "newmtl tinted\nKd 0.5 0.5 0.5\nTr 0.25\n"
        "newmtl halo\nKd 0.5 0.5 0.5\nd -halo 0.6\n"
        "newmtl glass\nillum 7\nNi 1.5\nd 0.3\n"
        "newmtl lamp\nKe 2 2 2\nd 0.5\n"
        "newmtl ghost\nKd 0.5 0.5 0.5\nd 0\n"
        "newmtl solid\nKd 0.5 0.5 0.5\nd 1\nTr 0\n";
    const std::string obj = trianglePerMaterial({"pane", "tinted", "halo", "glass", "lamp", "ghost", "solid"});
    LoadReport report;
    const MeshData mesh = parseObj(obj, "scene.obj", mtl, "scene.mtl", &report);
    REQUIRE(mesh.materials.size() >= 7);
    const auto opacityOf = [&](size_t m) {
        const MaterialTextures& t = mesh.materials[m].textures;
        return t.coverage && t.blended ? t.opacity : 1.0f;
    };
    CHECK(opacityOf(0) == 0.4f);
    CHECK(opacityOf(1) == 0.75f);
    CHECK(opacityOf(2) == 0.6f);
    // A dielectric's transparency is its illum; an emitter's d is its opacity as any other's
    // (lights/area_light.h).
    CHECK_FALSE(mesh.materials[3].textures.coverage);
    CHECK(opacityOf(4) == 0.5f);
    CHECK(opacityOf(5) == 0.0f);
    CHECK_FALSE(mesh.materials[6].textures.coverage);
    CHECK(report.warnings == std::vector<std::string>{
                                 "scene.mtl:9: d -halo is read as a plain d",
                                 "scene.mtl:17: material 'ghost': d 0 (or Tr 1) makes it wholly transparent"});
    const auto error = [](const std::string& material) {
        return objError("v 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl m\nf 1 2 3\n", "newmtl m\nKd 0.5 0.5 0.5\n" + material);
    };
    CHECK(error("d -0.5\n") == "scene.mtl:1: material 'm' has a d (or Tr) outside 0..1");
    CHECK(error("d half\n") == "scene.mtl:3: 'half' is not a number");
    CHECK(error("Tr 0.5 0.5\n").find("scene.mtl:3:") == 0);
}

TEST_CASE("obj: an MTL that Blender wrote is read as Blender's importer reads it") {
    // Blender 3.4.1's export of four Principled BSDFs (base colour 0.8 each): the defaults,
    // Metallic 0.5 with Roughness 0.4, Metallic 1 with Roughness 0, and Specular 0. Blender's
    // importer reads them back as (metallic, specular, roughness) = (0, 0.5, 0.5), (0.5, 0.5,
    // 0.4), (1, 0.5, 0) and (0, 0, 0.5).
    const std::string materials =
        "newmtl Default\nNs 250.000000\nKa 1.000000 1.000000 1.000000\nKd 0.800000 0.800000 0.800000\n"
        "Ks 0.500000 0.500000 0.500000\nKe 0.000000 0.000000 0.000000\nNi 1.450000\nd 1.000000\nillum 2\n"
        "newmtl HalfMetal\nNs 360.000000\nKa 0.500000 0.500000 0.500000\nKd 0.800000 0.800000 0.800000\n"
        "Ks 0.500000 0.500000 0.500000\nKe 0.000000 0.000000 0.000000\nNi 1.450000\nd 1.000000\nillum 3\n"
        "newmtl Mirror\nNs 1000.000000\nKa 1.000000 1.000000 1.000000\nKd 0.800000 0.800000 0.800000\n"
        "Ks 0.500000 0.500000 0.500000\nKe 0.000000 0.000000 0.000000\nNi 1.450000\nd 1.000000\nillum 3\n"
        "newmtl Spec0\nNs 250.000000\nKa 1.000000 1.000000 1.000000\nKd 0.800000 0.800000 0.800000\n"
        "Ks 0.000000 0.000000 0.000000\nKe 0.000000 0.000000 0.000000\nNi 1.450000\nd 1.000000\nillum 1\n";
    const std::string obj = trianglePerMaterial({"Default", "HalfMetal", "Mirror", "Spec0"});
    const auto near = [](const glm::vec3& a, float b) {
        return glm::all(glm::lessThanEqual(glm::abs(a - glm::vec3(b)), glm::vec3(1e-6f)));
    };
    // Blender 3.2 and later write their version; earlier exporters wrote none. A byte-order mark
    // is read past, as everywhere in the file.
    for (const char* header : {"# Blender 3.4.1 MTL File: 'None'\n# www.blender.org\n\n",
                               "# Blender MTL File: 'scene.blend'\n# Material Count: 4\n\n",
                               "\xEF\xBB\xBF# Blender 3.4.1 MTL File: 'None'\n"}) {
        const MeshData blender = parseObj(obj, "scene.obj", header + materials, "scene.mtl");
        REQUIRE(blender.materials.size() >= 4);
        const Material& plain = blender.materials[0];
        CHECK(near(plain.diffuse, 0.8f));
        CHECK(near(plain.specular, 0.04f));  // 0.08 Ks
        CHECK(plain.roughness == doctest::Approx(0.5));  // 1 - sqrt(250 / 1000)
        const Material& half = blender.materials[1];
        CHECK(near(half.diffuse, 0.4f));
        CHECK(near(half.specular, 0.42f));  // halfway from 0.04 to 0.8
        CHECK(half.roughness == doctest::Approx(0.4));
        const Material& mirror = blender.materials[2];
        CHECK(near(mirror.diffuse, 0.0f));
        CHECK(near(mirror.specular, 0.8f));
        CHECK(mirror.roughness == 0.0f);
        CHECK(MaterialTable(blender.materials).bsdf(2, glm::vec2(0.0f)).as<SmoothConductor>());
        CHECK(near(blender.materials[3].specular, 0.0f));
    }
    // The same lines under another header (or in a later line) are read as the MTL specification
    // says: Ks is the F0, Ns a Phong exponent.
    for (const char* header : {"", "# Exported\n# Blender 3.4.1 MTL File: 'None'\n"}) {
        const MeshData other = parseObj(obj, "scene.obj", std::string(header) + materials, "scene.mtl");
        CHECK(near(other.materials[0].specular, 0.5f));
        CHECK(near(other.materials[1].diffuse, 0.8f));
        CHECK(other.materials[0].roughness == doctest::Approx(roughnessFromShininess(250.0f)));
    }
    // Blender's Ka is its metallic where it is read: checked as the other numbers.
    CHECK(objError("v 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl m\nf 1 2 3\n",
                   "# Blender 3.4.1 MTL File: 'None'\nnewmtl m\nKa 2 2 2\nillum 3\n") ==
          "scene.mtl:2: material 'm' has Ka outside 0..1");
}
