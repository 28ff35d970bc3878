#include "frame_target.h"

#include <algorithm>
#include <utility>

#include "util/error.h"
#include "io/image_io.h"

namespace strata::viewer {

FrameTarget FrameTarget::defaultFramebuffer(int width, int height) { return {0, 0, width, height}; }

FrameTarget FrameTarget::offscreen(int width, int height) {
    GLuint colour = 0;
    glGenRenderbuffers(1, &colour);
    glBindRenderbuffer(GL_RENDERBUFFER, colour);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
    GLuint framebuffer = 0;
    glGenFramebuffers(1, &framebuffer);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour);
    FrameTarget target(framebuffer, colour, width, height);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
        throw Error("OpenGL: cannot make a " + std::to_string(width) + "x" + std::to_string(height) +
                    " framebuffer");
    }
    return target;
}

FrameTarget::~FrameTarget() {
    if (framebuffer_ != 0) glDeleteFramebuffers(1, &framebuffer_);
    if (colour_ != 0) glDeleteRenderbuffers(1, &colour_);
}

FrameTarget::FrameTarget(FrameTarget&& other) noexcept
    : framebuffer_(std::exchange(other.framebuffer_, 0)),
      colour_(std::exchange(other.colour_, 0)),
      width_(other.width_),
      height_(other.height_) {}

void FrameTarget::bind() const {
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    glViewport(0, 0, width_, height_);
}

void FrameTarget::blitTo(const FrameTarget& target, const Viewport& area) const {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, target.framebuffer_);
    glBlitFramebuffer(0, 0, width_, height_, area.x, area.y, area.x + area.width, area.y + area.height,
                      GL_COLOR_BUFFER_BIT, GL_NEAREST);
    target.bind();
}

void FrameTarget::resize(int width, int height) {
    if (framebuffer_ != 0) throw Error("OpenGL: an offscreen frame target has a fixed size");
    width_ = width;
    height_ = height;
}

std::vector<uint8_t> FrameTarget::readRgb() const {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_);
    if (framebuffer_ == 0) glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    std::vector<uint8_t> bottomUp(static_cast<size_t>(width_) * height_ * 3);
    glReadPixels(0, 0, width_, height_, GL_RGB, GL_UNSIGNED_BYTE, bottomUp.data());
    std::vector<uint8_t> topDown(bottomUp.size());
    const size_t row = static_cast<size_t>(width_) * 3;
    for (int y = 0; y < height_; ++y) {
        std::copy_n(bottomUp.begin() + static_cast<ptrdiff_t>((height_ - 1 - y) * row), row,
                    topDown.begin() + static_cast<ptrdiff_t>(y * row));
    }
    return topDown;
}

void FrameTarget::writePng(const std::filesystem::path& path) const {
    writeRgb8Png(path, width_, height_, readRgb());
}

}  // namespace strata::viewer
