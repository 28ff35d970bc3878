// glTF materials' KHR_texture_transform (gltf_materials.h): the offset, rotation and scale move a
// primitive's UVs as the extension's T * R * S says, its texCoord overrides the reference's, and
// textures of one material with different transforms are a warning.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "scene/gltf_loader.h"
#include "scene/gltf_test_model.h"
#include "util/error.h"

using namespace strata;
using nlohmann::json;

namespace {

// A triangle whose every corner is at glTF UV (0.25, 0.5), with a base colour texture (a data:
// PNG is not needed: the UVs are what is checked) under `transform`.
test::Model transformed(const json& transform, int texCoord = 0) {
    test::Model model;
    const int positions = model.positions({0, 0, 0, 1, 0, 0, 0, 1, 0});
    const int uvs = model.accessor(std::vector<float>{0.25f, 0.5f, 0.25f, 0.5f, 0.25f, 0.5f}, "VEC2", 5126, 3);
    model.doc["images"] = json::array({{{"uri", "absent.png"}}});
    model.doc["textures"] = json::array({{{"source", 0}}});
    json reference = {{"index", 0}, {"texCoord", texCoord}};
    if (!transform.is_null()) reference["extensions"]["KHR_texture_transform"] = transform;
    model.doc["materials"] = json::array({{{"pbrMetallicRoughness", {{"baseColorTexture", reference}}}}});
    model.meshNode({{"attributes", {{"POSITION", positions}, {"TEXCOORD_0", uvs}}}, {"material", 0}});
    return model;
}

// The stored UV of the first corner, in glTF's convention again (v down).
glm::dvec2 gltfUv(const test::Model& model, LoadReport* report = nullptr) {
    const MeshData mesh = parseGltfScene(test::bundleOf(model.gltf()), report).mesh;
    REQUIRE(!mesh.uvs.empty());
    return {mesh.uvs[0].x, 1.0 - mesh.uvs[0].y};
}

void checkUv(const glm::dvec2& uv, double u, double v) {
    CHECK(uv.x == doctest::Approx(u).epsilon(1e-6));
    CHECK(uv.y == doctest::Approx(v).epsilon(1e-6));
}

}  // namespace

TEST_CASE("gltf materials: KHR_texture_transform offset, rotation and scale, composed as T * R * S") {
    checkUv(gltfUv(transformed(nullptr)), 0.25, 0.5);
    checkUv(gltfUv(transformed({{"offset", {0.5, -0.25}}})), 0.75, 0.25);
    checkUv(gltfUv(transformed({{"scale", {2, 3}}})), 0.5, 1.5);
    // A quarter turn counter-clockwise in UV space: (u, v) -> (v, -u).
    checkUv(gltfUv(transformed({{"rotation", M_PI / 2}})), 0.5, -0.25);
    // Scaled first, then turned, then offset: (0.25, 0.5) -> (0.5, 1.5) -> (1.5, -0.5) -> (2.5, -0.5).
    checkUv(gltfUv(transformed({{"offset", {1, 0}}, {"rotation", M_PI / 2}, {"scale", {2, 3}}})), 2.5, -0.5);
}

TEST_CASE("gltf materials: KHR_texture_transform's texCoord overrides the reference's set") {
    LoadReport report;
    gltfUv(transformed({{"texCoord", 0}}, 1), &report);
    for (const std::string& warning : report.warnings) CHECK(warning.find("TEXCOORD_") == std::string::npos);
    LoadReport other;
    gltfUv(transformed({{"texCoord", 1}}, 0), &other);
    CHECK(std::count(other.warnings.begin(), other.warnings.end(),
                     "mem/model.gltf: material '' (0) baseColorTexture uses TEXCOORD_1, which Strata does not read; "
                     "ignored") == 1);
}

TEST_CASE("gltf materials: textures of one material with different transforms, or malformed ones") {
    test::Model model = transformed({{"offset", {0.5, 0}}});
    model.doc["materials"][0]["emissiveTexture"] = {{"index", 0}};
    LoadReport report;
    checkUv(gltfUv(model, &report), 0.75, 0.5);
    CHECK(std::count(report.warnings.begin(), report.warnings.end(),
                     "mem/model.gltf: material '' (0): emissiveTexture's KHR_texture_transform differs from "
                     "baseColorTexture's, which Strata applies to all its textures (one UV set per primitive)") == 1);
    CHECK_THROWS_WITH_AS(gltfUv(transformed({{"scale", {1}}})),
                         "mem/model.gltf: material '' (0) baseColorTexture: KHR_texture_transform scale needs 2 "
                         "finite numbers",
                         Error);
    CHECK_THROWS_WITH_AS(gltfUv(transformed({{"rotation", "half"}})),
                         "mem/model.gltf: material '' (0) baseColorTexture: KHR_texture_transform rotation needs 1 "
                         "finite number",
                         Error);
}
