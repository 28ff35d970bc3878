#include <doctest/doctest.h>

#include "util/error.h"
#include "scene/scene_loader.h"
#include "test_support.h"

using namespace strata;

TEST_CASE("scene loader: files read once then parsed give the scene loadScene gives") {
    const auto obj = test::sourceDir() / "assets/cornell/cornell.obj";
    const SceneFiles files = readSceneFiles(obj);
    CHECK(files.cameraPath == test::sourceDir() / "assets/cornell/cornell.json");
    CHECK(files.obj.mtlName.find("cornell.mtl") != std::string::npos);
    CHECK(!files.cameraText.empty());
    // A copy of the bytes, as another MPI rank would receive them.
    const SceneFiles received = files;
    const LoadedScene parsed = parseScene(received);
    const LoadedScene loaded = loadScene(obj);
    CHECK(parsed.scene.summary().triangles == loaded.scene.summary().triangles);
    CHECK(parsed.scene.summary().emittingArea == loaded.scene.summary().emittingArea);
    CHECK(parsed.settings.width == loaded.settings.width);
    CHECK(parsed.settings.pose.lookAt == loaded.settings.pose.lookAt);
    CHECK(parsed.objPath == obj);
}

TEST_CASE("scene loader: a missing scene or camera file is named when reading") {
    const auto dir = test::scratchDir("scene-files");
    CHECK_THROWS_WITH_AS(readSceneFiles(dir / "absent.obj"),
                         doctest::Contains("absent.obj: no such scene file"), Error);
    CHECK_THROWS_WITH_AS(readSceneFiles(test::sourceDir() / "assets/cornell/cornell.obj",
                                        dir / "absent.json"),
                         doctest::Contains("absent.json: cannot open camera file"), Error);
}
