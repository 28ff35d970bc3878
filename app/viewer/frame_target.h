#pragma once
// Where a viewer frame is drawn: the window's default framebuffer, or (offscreen, where there is
// none) a framebuffer object of the requested size. Both can be read back as a screenshot.
#include <cstdint>
#include <filesystem>
#include <vector>

#include "gl_loader.h"

namespace strata::viewer {

struct Viewport {
    int x = 0;  // lower-left corner, window pixels (OpenGL convention)
    int y = 0;
    int width = 0;
    int height = 0;
};

class FrameTarget {
public:
    // The default framebuffer of the current (windowed) context.
    static FrameTarget defaultFramebuffer(int width, int height);
    // A new RGBA8 framebuffer object; throws strata::Error when incomplete.
    static FrameTarget offscreen(int width, int height);
    ~FrameTarget();
    FrameTarget(FrameTarget&& other) noexcept;
    FrameTarget& operator=(FrameTarget&&) = delete;
    FrameTarget(const FrameTarget&) = delete;

    void bind() const;
    // Copies this target's pixels over `area` of `target` (nearest: scaling up keeps pixels
    // crisp), and binds `target`.
    void blitTo(const FrameTarget& target, const Viewport& area) const;
    void resize(int width, int height);  // default framebuffer only: follows the window
    int width() const { return width_; }
    int height() const { return height_; }
    // 8-bit RGB, top row first.
    std::vector<uint8_t> readRgb() const;
    void writePng(const std::filesystem::path& path) const;

private:
    FrameTarget(GLuint framebuffer, GLuint colour, int width, int height)
        : framebuffer_(framebuffer), colour_(colour), width_(width), height_(height) {}

    GLuint framebuffer_ = 0;
    GLuint colour_ = 0;  // renderbuffer of an offscreen target
    int width_;
    int height_;
};

}  // namespace strata::viewer
