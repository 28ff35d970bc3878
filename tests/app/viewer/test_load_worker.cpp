// The viewer's loading thread on its own (no OpenGL): a scene loads through its stages in order
// while the caller goes on; a cancel takes effect where the load enters its next stage and
// leaves nothing; a newer request supersedes the one in flight; a failure is its one line. The
// loading thread's notifications come at each stage, before the load leaves it: the tests act
// from them, so what they check does not depend on how fast the machine is. Named "threads" for
// scripts/check.sh tsan.
#include <doctest/doctest.h>

#include <atomic>
#include <chrono>
#include <fstream>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "io/image_io.h"
#include "load_worker.h"
#include "test_support.h"

using namespace strata;
using namespace strata::viewer;

namespace {

// The outcome, waiting for it; fails after a generous bound (a stuck loader, not a slow one).
LoadOutcome outcomeOf(LoadWorker& loader) {
    for (int i = 0; i < 60000; ++i) {
        if (auto outcome = loader.take()) return std::move(*outcome);
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    FAIL("the load never ended");
    return {};
}

// The stages the loader announced, as its notifications saw them.
struct StageLog {
    std::mutex mutex;
    std::vector<std::string> stages;
    void add(const LoadWorker& loader) {
        const auto progress = loader.progress();
        std::lock_guard lock(mutex);
        if (progress && (stages.empty() || stages.back() != progress->stage)) {
            stages.emplace_back(progress->stage);
        }
    }
};

LoadRequest sceneRequest(const std::filesystem::path& path) {
    return {LoadRequest::Kind::Scene, path, Traversal::Automatic, SceneBudget{}, SceneReadOptions{}};
}

}  // namespace

TEST_CASE("load worker threads: a scene loads through its stages on the loading thread") {
    StageLog log;  // before the loader: its callback uses it
    LoadWorker loader;
    loader.setNotifyCallback([&] { log.add(loader); });
    CHECK(!loader.progress());
    loader.start(sceneRequest(test::cornellScene()));
    // At once, before the load has begun or while it runs; unless it has ended already (the
    // Cornell box loads in a millisecond, and a busy machine can deschedule this thread that
    // long), when its outcome waits to be taken.
    const bool announced = loader.progress().has_value();
    std::optional<LoadOutcome> ended = announced ? std::nullopt : loader.take();
    CHECK((announced || ended));
    const LoadOutcome outcome = ended ? std::move(*ended) : outcomeOf(loader);
    REQUIRE(outcome.scene);
    CHECK(outcome.error.empty());
    CHECK(!outcome.cancelled);
    CHECK(outcome.scene->scene.summary().triangles == 32);
    CHECK(outcome.request.path == test::cornellScene());
    CHECK(!loader.progress());
    CHECK(!loader.take());  // taken once
    std::lock_guard lock(log.mutex);
    CHECK(log.stages == std::vector<std::string>{"reading files", "parsing", "building the BVH", "done"});
}

TEST_CASE("load worker threads: a cancel takes effect at the next stage and builds nothing") {
    StageLog log;
    LoadWorker loader;
    loader.setNotifyCallback([&] {
        log.add(loader);
        const auto progress = loader.progress();
        if (progress && std::string(progress->stage) == "parsing") loader.cancel();  // as the Cancel button
    });
    loader.start(sceneRequest(test::cornellScene()));
    const LoadOutcome outcome = outcomeOf(loader);
    CHECK(outcome.cancelled);
    CHECK(!outcome.scene);
    CHECK(outcome.error.empty());
    std::lock_guard lock(log.mutex);
    CHECK(log.stages == std::vector<std::string>{"reading files", "parsing"});
}

TEST_CASE("load worker threads: a newer request supersedes the load in flight, whose outcome is dropped") {
    const auto dir = test::scratchDir("load-worker-supersede");
    std::ofstream(dir / "quad.obj") << "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n";
    std::string waiting;  // what progress() said right after the second start
    LoadWorker loader;
    loader.setNotifyCallback([&] {
        const auto progress = loader.progress();
        if (waiting.empty() && progress && std::string(progress->stage) == "parsing") {
            loader.start(sceneRequest(dir / "quad.obj"));
            waiting = loader.progress()->stage;
        }
    });
    loader.start(sceneRequest(test::cornellScene()));
    const LoadOutcome outcome = outcomeOf(loader);
    REQUIRE(outcome.scene);
    CHECK(outcome.request.path == dir / "quad.obj");
    CHECK(outcome.scene->scene.summary().triangles == 2);
    CHECK(waiting == "waiting");
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    CHECK(!loader.take());  // the Cornell box's outcome never comes
}

TEST_CASE("load worker threads: a failing load is its one line, and a map loads as a map") {
    const auto dir = test::scratchDir("load-worker-fail");
    LoadWorker loader;
    loader.start(sceneRequest(dir / "missing.obj"));
    const LoadOutcome missing = outcomeOf(loader);
    CHECK(!missing.scene);
    CHECK(missing.error == (dir / "missing.obj").string() + ": no such scene file");

    writeImage(dir / "sky.exr", Image{4, 2, std::vector<glm::vec3>(8, glm::vec3(0.5f))});
    loader.start({LoadRequest::Kind::EnvironmentMap, dir / "sky.exr", Traversal::Automatic, SceneBudget{}, SceneReadOptions{}});
    const LoadOutcome map = outcomeOf(loader);
    REQUIRE(map.map);
    CHECK(map.map->map->image().width == 4);
    writeImage(dir / "square.exr", Image{2, 2, std::vector<glm::vec3>(4, glm::vec3(1.0f))});
    loader.start({LoadRequest::Kind::EnvironmentMap, dir / "square.exr", Traversal::Automatic, SceneBudget{}, SceneReadOptions{}});
    const LoadOutcome square = outcomeOf(loader);
    CHECK(!square.map);
    const std::string notLatLong =
        (dir / "square.exr").string() + ": an environment map must be a latitude-longitude image";
    CHECK(square.error.rfind(notLatLong, 0) == 0);
}

TEST_CASE("load worker threads: a scene over the request's triangle budget is refused before it is built") {
    LoadWorker loader;
    LoadRequest request = sceneRequest(test::cornellScene());
    request.budget = SceneBudget{31};  // the box has 32
    loader.start(request);
    const LoadOutcome refused = outcomeOf(loader);
    CHECK(!refused.scene);
    CHECK(refused.error.find("exceed the budget of 31 triangles") != std::string::npos);
    request.budget = SceneBudget{32};
    loader.start(request);
    const LoadOutcome loaded = outcomeOf(loader);
    REQUIRE(loaded.scene);
    CHECK(loaded.scene->scene.summary().triangles == 32);
}

TEST_CASE("load worker threads: going away mid-load cancels it and waits for its stage to end") {
    std::atomic<bool> parsing{false};
    {
        LoadWorker loader;
        loader.setNotifyCallback([&] {
            const auto progress = loader.progress();
            if (progress && std::string(progress->stage) == "parsing") parsing = true;
        });
        loader.start(sceneRequest(test::cornellScene()));
        while (!parsing) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }  // no crash, no hang: the destructor joined the thread
    CHECK(parsing);
}

TEST_CASE("load worker threads: a cancel before the load has begun ends it at once, cancelled") {
    // The loading thread is held in its notification of the first load's first stage, so that
    // the second request is still waiting when it is cancelled.
    std::mutex gate;
    std::unique_lock hold(gate);
    LoadWorker loader;
    loader.setNotifyCallback([&] { std::lock_guard wait(gate); });
    loader.start(sceneRequest(test::cornellScene()));
    while (std::string(loader.progress()->stage) != "reading files") std::this_thread::yield();
    loader.start(sceneRequest(test::cornellScene().parent_path() / "second.obj"));
    CHECK(std::string(loader.progress()->stage) == "waiting");
    loader.cancel();
    const auto outcome = loader.take();
    REQUIRE(outcome);
    CHECK(outcome->cancelled);
    CHECK(outcome->request.path.filename() == "second.obj");
    hold.unlock();
    // The first load, superseded, ends cancelled at its next stage and leaves no outcome.
    while (loader.progress()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    CHECK(!loader.take());
}
