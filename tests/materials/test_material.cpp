// Materials as the MTL gives them: Ks, Pr (or Ns) reach Material, and bad values are refused with
// the file named.
#include <doctest/doctest.h>

#include <cmath>
#include <string>

#include "util/error.h"
#include "materials/microfacet.h"
#include "scene/obj_loader.h"
#include "test_support.h"

using namespace strata;

namespace {
const std::string kObj = "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\nf 1 2 3\nusemtl b\nf 1 2 3\n";
}

TEST_CASE("material: Ks, Pr and Ns are read from the MTL") {
    const std::string mtl =
        "newmtl a\nKd 0.2 0.3 0.4\nKs 0.5 0.6 0.7\nPr 0.3\nNs 10\n"
        "newmtl b\nKd 0.5 0.5 0.5\nKs 0.04 0.04 0.04\nNs 98\n";
    const MeshData mesh = parseObj(kObj, "t.obj", mtl, "m.mtl");
    REQUIRE(mesh.materials.size() == 2);
    const Material& a = mesh.materials[0];
    CHECK(a.specular.y == doctest::Approx(0.6f));
    CHECK(a.roughness == doctest::Approx(0.3f));  // Pr wins over Ns
    CHECK(ggxAlphaFromRoughness(a.roughness) == doctest::Approx(0.09f));
    // Ns 98 without Pr: alpha = sqrt(2 / 100), Pr = alpha^(1/2).
    const Material& b = mesh.materials[1];
    CHECK(ggxAlphaFromRoughness(b.roughness) == doctest::Approx(std::sqrt(0.02)).epsilon(1e-5));
}

TEST_CASE("material: Ks above 1 or a negative Pr is refused naming the file") {
    for (const std::string bad : {"newmtl a\nKs 1.5 0 0\nnewmtl b\n", "newmtl a\nPr -0.2\nnewmtl b\n"}) {
        try {
            parseObj(kObj, "t.obj", bad, "m.mtl");
            FAIL("accepted: " << bad);
        } catch (const Error& e) {
            CHECK(std::string(e.what()).find("m.mtl") != std::string::npos);
        }
    }
}

TEST_CASE("material: the bundled glossy scene has its Cook-Torrance materials") {
    const MeshData mesh = loadObjFile(test::sourceDir() / "assets/glossy/glossy.obj");
    int glossy = 0;
    for (const Material& m : mesh.materials) {
        if (m.specular.x > 0.0f) ++glossy;
        if (m.name == "gold") {
            CHECK(m.specular.y == doctest::Approx(0.71f));
            CHECK(m.roughness == doctest::Approx(0.3f));
            CHECK(m.diffuse.x == 0.0f);
        }
    }
    CHECK(glossy == 4);  // floor, gold, plastic, copper
}
