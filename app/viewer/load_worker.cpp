#include "load_worker.h"

#include <exception>
#include <utility>
#include <sys/resource.h>
#include <unistd.h>

#include "render_worker.h"

namespace strata::viewer {

LoadWorker::LoadWorker() : thread_([this] { run(); }) {}

LoadWorker::~LoadWorker() {
    {
        std::lock_guard lock(mutex_);
        stop_ = true;
        cancel_ = true;
        pending_.reset();
    }
    wake_.notify_all();
    thread_.join();
}

void LoadWorker::start(LoadRequest request) {
    {
        std::lock_guard lock(mutex_);
        pending_ = std::move(request);
        outcome_.reset();
        if (inFlight_) cancel_ = superseded_ = true;
    }
    wake_.notify_all();
}

void LoadWorker::cancel() {
    std::lock_guard lock(mutex_);
    if (inFlight_) {
        cancel_ = true;
        inFlight_->cancelling = true;
    }
    // A request not started yet ends here; the one in flight, if it superseded none, ends when
    // it reaches its next stage.
    if (pending_) {
        LoadOutcome outcome;
        outcome.request = std::move(*pending_);
        outcome.cancelled = true;
        outcome_ = std::move(outcome);
        pending_.reset();
    }
}

std::optional<LoadProgress> LoadWorker::progress() const {
    std::lock_guard lock(mutex_);
    if (pending_) return LoadProgress{*pending_, "waiting", 0.0, false};
    if (!inFlight_) return std::nullopt;
    LoadProgress progress = *inFlight_;
    progress.seconds = std::chrono::duration<double>(Clock::now() - started_).count();
    return progress;
}

std::optional<LoadOutcome> LoadWorker::take() {
    std::lock_guard lock(mutex_);
    return std::exchange(outcome_, std::nullopt);
}

void LoadWorker::setNotifyCallback(std::function<void()> onNotify) {
    std::lock_guard lock(mutex_);
    onNotify_ = std::move(onNotify);
}

void LoadWorker::notify() {
    std::function<void()> onNotify;
    {
        std::lock_guard lock(mutex_);
        if (stop_) return;  // the owner is going: nothing to wake
        onNotify = onNotify_;
    }
    if (onNotify) onNotify();
}

void LoadWorker::enter(const char* stage) {
    {
        std::lock_guard lock(mutex_);
        inFlight_->stage = stage;
    }
    notify();
    // After the notification, so that what it woke sees the stage before the load leaves it.
    std::lock_guard lock(mutex_);
    if (cancel_) throw Cancelled{};
}

void LoadWorker::run() {
    // Nice values are per thread on Linux; best effort.
    setpriority(PRIO_PROCESS, static_cast<id_t>(gettid()), kWorkerNiceness);
    for (;;) {
        LoadRequest request;
        {
            std::unique_lock lock(mutex_);
            wake_.wait(lock, [&] { return stop_ || pending_; });
            if (stop_) return;
            request = std::move(*pending_);
            pending_.reset();
            cancel_ = superseded_ = false;
            inFlight_ = LoadProgress{request, "starting", 0.0, false};
            started_ = Clock::now();
        }
        LoadOutcome outcome = load(request);
        {
            std::lock_guard lock(mutex_);
            inFlight_.reset();
            // A newer request superseded this load: its outcome is the one to take.
            if (!superseded_) outcome_ = std::move(outcome);
        }
        notify();
    }
}

LoadOutcome LoadWorker::load(const LoadRequest& request) {
    LoadOutcome outcome;
    outcome.request = request;
    try {
        if (request.kind == LoadRequest::Kind::Scene) {
            enter("reading files");
            SceneBundle bundle = readSceneBundle(request.path, std::nullopt, request.files);
            auto scene = std::make_shared<LoadedScene>(
                parseScene(std::move(bundle), request.traversal, request.budget, [&](ParseStage stage) {
                    enter(stage == ParseStage::Parsing ? "parsing" : "building the BVH");
                }));
            enter("done");  // a cancel during the build drops what it built
            outcome.scene = std::move(scene);
        } else {
            enter("reading the map");
            EnvironmentMapFile map = readEnvironmentMap(request.path, TextureBudget(request.budget.textureBytes));
            enter("done");
            outcome.map = std::move(map);
        }
    } catch (const Cancelled&) {
        outcome.cancelled = true;
    } catch (const std::exception& e) {
        outcome.error = e.what();
    }
    std::lock_guard lock(mutex_);
    outcome.seconds = std::chrono::duration<double>(Clock::now() - started_).count();
    return outcome;
}

}  // namespace strata::viewer
