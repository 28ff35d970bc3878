#pragma once
// An OpenGL 3.3 core context with no window, for `strata view --headless` and the tests. GLFW 3.3
// cannot start without a display, so these are made directly: EGL on Mesa's surfaceless platform,
// or OSMesa (software). Neither has a default framebuffer the viewer draws to: it renders into a
// FrameTarget (frame_target.h).
#include <memory>
#include <string_view>

namespace strata::viewer {

enum class OffscreenBackend { Auto, Egl, OsMesa };

// "" or "auto" -> Auto (EGL first, then OSMesa), "egl", "osmesa"; throws strata::Error otherwise.
OffscreenBackend parseOffscreenBackend(std::string_view name);

class OffscreenContext {
public:
    virtual ~OffscreenContext() = default;
    virtual std::string_view backendName() const = 0;

    // Creates the context, makes it current and loads OpenGL; throws strata::Error naming what
    // failed (for Auto, both backends' reasons).
    static std::unique_ptr<OffscreenContext> create(OffscreenBackend backend);
};

}  // namespace strata::viewer
