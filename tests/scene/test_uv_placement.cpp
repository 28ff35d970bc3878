// MTL's -s and -o moved onto a mesh's UVs (scene/uv_placement.h).
#include <doctest/doctest.h>

#include "scene/uv_placement.h"

using namespace strata;

TEST_CASE("uv placement: a placed material's triangles get copies of their vt, shared among them") {
    MeshData mesh;
    mesh.uvs = {{0.0f, 0.0f}, {1.0f, 0.0f}, {0.0f, 1.0f}, {1.0f, 1.0f}};
    // Material 0 placed, twice over vt 1 and 2; material 1 as it is; material 5 past the
    // placements; one triangle of material 0 without UVs.
    mesh.triangleMaterials = {0, 0, 1, 5, 0};
    mesh.triangleUvs = {{0, 1, 2}, {1, 3, 2}, {0, 1, 2}, {1, 2, 3}, kNoUvs};
    placeUvs(mesh, {UvPlacement{{2.0f, 3.0f}, {0.5f, -1.0f}}, UvPlacement{}});
    CHECK(mesh.triangleUvs[0] == std::array<uint32_t, 3>{4, 5, 6});
    CHECK(mesh.triangleUvs[1] == std::array<uint32_t, 3>{5, 7, 6});
    CHECK(mesh.triangleUvs[2] == std::array<uint32_t, 3>{0, 1, 2});
    CHECK(mesh.triangleUvs[3] == std::array<uint32_t, 3>{1, 2, 3});
    CHECK(mesh.triangleUvs[4] == kNoUvs);
    REQUIRE(mesh.uvs.size() == 8);
    CHECK(mesh.uvs[0] == glm::vec2(0.0f, 0.0f));  // the shared ones unchanged
    CHECK(mesh.uvs[4] == glm::vec2(0.5f, -1.0f));
    CHECK(mesh.uvs[5] == glm::vec2(2.5f, -1.0f));
    CHECK(mesh.uvs[6] == glm::vec2(0.5f, 2.0f));
    CHECK(mesh.uvs[7] == glm::vec2(2.5f, 2.0f));
}
