// Which way an OBJ model stands (model_orientation.h): its up axis by the plane its bounding box
// rests on, its front by where its finer tessellation lies; on synthetic models and, when Debian's
// assimp-testmodels is installed, on real ones.
#include <doctest/doctest.h>

#include <filesystem>
#include <glm/vec3.hpp>

#include "scene/model_orientation.h"
#include "scene/scene_format.h"
#include "scene/scene_loader.h"
#include "test_support.h"

using namespace strata;

namespace {

const glm::vec3 kX{1, 0, 0}, kY{0, 1, 0}, kZ{0, 0, 1};

// The box [lower, upper]: each face one quad, or 8 x 8 quads where its outward normal is
// `detailed` (zero: none).
MeshData box(const glm::vec3& lower, const glm::vec3& upper, const glm::vec3& detailed = {}) {
    constexpr int cells = 8;
    MeshData mesh;
    mesh.materials.resize(1);
    for (int axis = 0; axis < 3; ++axis) {
        for (float sign : {-1.0f, 1.0f}) {
            glm::vec3 normal(0.0f);
            normal[axis] = sign;
            const int u = (axis + 1) % 3, v = (axis + 2) % 3;
            const int n = normal == detailed ? cells : 1;
            for (int i = 0; i < n; ++i) {
                for (int j = 0; j < n; ++j) {
                    const auto corner = [&](int a, int b) {
                        glm::vec3 p;
                        p[axis] = sign < 0.0f ? lower[axis] : upper[axis];
                        p[u] = lower[u] + (upper[u] - lower[u]) * static_cast<float>(a) / static_cast<float>(n);
                        p[v] = lower[v] + (upper[v] - lower[v]) * static_cast<float>(b) / static_cast<float>(n);
                        return p;
                    };
                    test::addQuad(mesh, corner(i, j), corner(i + 1, j), corner(i + 1, j + 1), corner(i, j + 1), 0);
                }
            }
        }
    }
    return mesh;
}

}  // namespace

TEST_CASE("model orientation: an OBJ standing on z = 0 and not on y = 0 is Z-up, with its front at -y") {
    const ModelOrientation tower = objOrientation(box({-0.5f, -0.5f, 0.0f}, {0.5f, 0.5f, 3.0f}));
    CHECK(tower.up == kZ);
    CHECK(tower.front == -kY);
    // Within 1% of the largest extent of the plane still rests on it.
    CHECK(objOrientation(box({-0.5f, -0.5f, 0.02f}, {0.5f, 0.5f, 3.0f})).up == kZ);
    CHECK(objOrientation(box({-0.5f, -0.5f, 0.04f}, {0.5f, 0.5f, 3.0f})).up == kY);
}

TEST_CASE("model orientation: an OBJ on y = 0, centred, or touching both planes is Y-up, front +z") {
    for (const auto& [lower, upper] : {std::pair{glm::vec3(-0.5f, 0.0f, -0.5f), glm::vec3(0.5f, 3.0f, 0.5f)},
                                       std::pair{glm::vec3(-1.0f), glm::vec3(1.0f)},
                                       std::pair{glm::vec3(0.0f), glm::vec3(1.0f, 2.0f, 3.0f)},
                                       std::pair{glm::vec3(-2.0f, 1.0f, 5.0f), glm::vec3(2.0f, 3.0f, 9.0f)}}) {
        const ModelOrientation orientation = objOrientation(box(lower, upper));
        CHECK(orientation.up == kY);
        CHECK(orientation.front == kZ);
    }
}

TEST_CASE("model orientation: the front is the horizontal side with the finer tessellation") {
    // A cube's triangles are spread evenly: the convention's front.
    CHECK(objOrientation(box(glm::vec3(-1.0f), glm::vec3(1.0f))).front == kZ);
    for (const glm::vec3& detailed : {-kZ, kX, -kX, kZ}) {
        CAPTURE(detailed);
        CHECK(objOrientation(box(glm::vec3(-1.0f), glm::vec3(1.0f), detailed)).front == detailed);
    }
    // Vertical detail does not turn the front: only the horizontal axes count.
    CHECK(objOrientation(box(glm::vec3(-1.0f), glm::vec3(1.0f), kY)).front == kZ);
    // Z-up: the horizontal axes are x and y.
    const ModelOrientation zUp = objOrientation(box({-1.0f, -1.0f, 0.0f}, {1.0f, 1.0f, 2.0f}, kY));
    CHECK(zUp.up == kZ);
    CHECK(zUp.front == kY);
}

TEST_CASE("model orientation: on the OBJ models of assimp-testmodels and the bundled Cornell box") {
    const std::filesystem::path models = "/usr/share/assimp/models/OBJ";
    const auto orientationOf = [](const std::filesystem::path& path) {
        return parseSceneFile(readSceneBundle(path)).orientation;
    };
    // The Cornell box: Y-up on y = 0 (as on z = 0), its open side (-z) the front.
    const ModelOrientation cornell = orientationOf(test::cornellScene());
    CHECK(cornell.up == kY);
    CHECK(cornell.front == -kZ);
    if (!std::filesystem::is_directory(models)) {
        MESSAGE("skipped: " << models << " is absent (apt-get install assimp-testmodels)");
        return;
    }
    // regr01: 3ds Max's floor plan of a house, on z = 0: the one Z-up model there.
    CHECK(orientationOf(models / "regr01.obj").up == kZ);
    // WusonOBJ, a bison on y = 0 with its head toward -z; the spider, head toward -x.
    const ModelOrientation wuson = orientationOf(models / "WusonOBJ.obj");
    CHECK(wuson.up == kY);
    CHECK(wuson.front == -kZ);
    const ModelOrientation spider = orientationOf(models / "spider.obj");
    CHECK(spider.up == kY);
    CHECK(spider.front == -kX);
    for (const char* name : {"box.obj", "cube_usemtl.obj", "concave_polygon.obj", "regr_3429812.obj",
                             "space_in_material_name.obj", "empty_mat.obj", "testmixed.obj"}) {
        CAPTURE(name);
        CHECK(orientationOf(models / name).up == kY);
    }
}
