// glTF cameras (gltf_cameras_lights.h): an orthographic camera is the scene's camera, its ymag the
// half-height it sees, and renders the parallel projection it describes; a malformed one is one
// line naming it.
#include <doctest/doctest.h>

#include <string>
#include <vector>

#include "scene/gltf_loader.h"
#include "scene/gltf_test_model.h"
#include "scene/scene.h"
#include "util/error.h"

using namespace strata;
using nlohmann::json;

namespace {

// A square of side 2 about the origin in z = 0, and an orthographic camera at z = 5 (after a
// perspective one that a later node holds).
test::Model orthographicModel(double ymag) {
    test::Model model;
    model.meshNode({{"attributes", {{"POSITION", model.positions({-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, -1, 0, 1, 1, 0, -1, 1, 0})}}}});
    model.doc["cameras"] = json::array({
        {{"type", "orthographic"}, {"orthographic", {{"xmag", 3}, {"ymag", ymag}, {"znear", 0.1}, {"zfar", 10}}}},
        {{"type", "perspective"}, {"perspective", {{"yfov", 0.5}, {"znear", 0.1}}}},
    });
    model.addNode({{"camera", 0}, {"translation", {0, 0, 5}}});
    model.addNode({{"camera", 1}, {"translation", {0, 0, 9}}});
    return model;
}

}  // namespace

TEST_CASE("gltf cameras: an orthographic camera is rendered as one, ymag its half-height") {
    LoadReport report;
    const ParsedScene parsed = parseGltfScene(test::bundleOf(orthographicModel(2.0).gltf()), &report);
    REQUIRE(parsed.camera);
    CHECK(parsed.camera->position == glm::vec3(0, 0, 5));
    CHECK(parsed.camera->orthographicHalfHeight == 2.0f);
    CHECK(report.warnings.empty());
    // Seen through it at 32 x 16 pixels, the square covers the middle half of the rows (2 of the
    // 4 units of height) and, at aspect 2, the middle quarter of the columns: the pixels whose
    // centre ray hits it, counted exactly.
    const Scene scene(parsed.mesh);
    const Camera camera(*parsed.camera, 32, 16);
    int hits = 0;
    for (int y = 0; y < 16; ++y) {
        for (int x = 0; x < 32; ++x) hits += scene.intersect(camera.generateRay(x, y, {0.5f, 0.5f})).has_value();
    }
    CHECK(hits == 8 * 8);
}

TEST_CASE("gltf cameras: an orthographic camera without a usable ymag is one line naming it") {
    try {
        parseGltfScene(test::bundleOf(orthographicModel(0.0).gltf()));
        FAIL("loaded");
    } catch (const Error& error) {
        CHECK(std::string(error.what()) == "mem/model.gltf: camera 0: ymag is not a finite nonzero number");
    }
}
