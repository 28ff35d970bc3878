#pragma once
// The viewer's loading thread. A scene (its files read, parsed, its BVH built) or an environment
// map (read, its sampling distribution built) is made here while the UI thread goes on drawing
// and the render worker goes on rendering the open scene, which stays until the new one is ready
// and is never touched from here. One load at a time: starting another cancels the one in flight.
// Cancelling is cooperative: it takes effect where the load enters its next stage (reading,
// parsing, building, done), since neither a format's parser nor Embree's BVH build stops midway.
#include <chrono>
#include <condition_variable>
#include <filesystem>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "lights/environment.h"
#include "scene/scene_folder.h"
#include "scene/scene_loader.h"
#include "scene/traversal_precision.h"

namespace strata::viewer {

struct LoadRequest {
    enum class Kind { Scene, EnvironmentMap };
    Kind kind = Kind::Scene;
    std::filesystem::path path;
    Traversal traversal = Traversal::Automatic;  // a scene's triangle test
    SceneBudget budget;                          // what a scene or map may take
    SceneReadOptions files;                      // what a scene may read (--allow-outside-files)
};

// The load in flight, for the panel's progress line.
struct LoadProgress {
    LoadRequest request;
    const char* stage = "";  // "reading files", "parsing", "building the BVH", "reading the map"
    double seconds = 0.0;    // since it started
    bool cancelling = false;
};

// How a load ended: what it made, or why not.
struct LoadOutcome {
    LoadRequest request;
    std::shared_ptr<LoadedScene> scene;     // a scene that loaded
    std::optional<EnvironmentMapFile> map;  // a map that loaded
    std::string error;                      // the failure's one line (strata::Error's message)
    bool cancelled = false;
    double seconds = 0.0;
};

class LoadWorker {
public:
    LoadWorker();
    // Cancels a load in flight and waits for it to reach its next stage.
    ~LoadWorker();
    LoadWorker(const LoadWorker&) = delete;
    LoadWorker& operator=(const LoadWorker&) = delete;

    // Loads `request` next; a load in flight is cancelled and its outcome, like any not yet
    // taken, dropped: only the newest request's outcome is ever taken.
    void start(LoadRequest request);
    // Cancels the load in flight or waiting to start, if any; its outcome says so.
    void cancel();
    // The load in flight or waiting to start; none when idle.
    std::optional<LoadProgress> progress() const;
    // The outcome of the last load once it has ended, once.
    std::optional<LoadOutcome> take();
    // Called on the loading thread as a load enters each stage and when it ends: wakes a UI that
    // sleeps until an event (see RenderWorker::setPublishCallback).
    void setNotifyCallback(std::function<void()> onNotify);

private:
    using Clock = std::chrono::steady_clock;
    struct Cancelled {};

    void run();
    LoadOutcome load(const LoadRequest& request);
    // Names the stage the load enters; throws Cancelled when it has been cancelled.
    void enter(const char* stage);
    void notify();

    mutable std::mutex mutex_;  // guards everything below but the thread
    std::condition_variable wake_;
    std::optional<LoadRequest> pending_;
    std::optional<LoadProgress> inFlight_;
    Clock::time_point started_{};
    std::optional<LoadOutcome> outcome_;
    bool cancel_ = false;
    bool superseded_ = false;  // by a request started while this one was in flight
    bool stop_ = false;
    std::function<void()> onNotify_;
    std::thread thread_;  // last: it starts when everything else is ready
};

}  // namespace strata::viewer
