#pragma once
// The display of the accumulation buffers: shaders/display.{vert,frag} drawn over a viewport from
// float textures of up to two images (the split view's sides). Needs a current OpenGL 3.3 context.
#include <array>

#include "display_image.h"
#include "frame_target.h"
#include "gl_loader.h"
#include "io/tonemap.h"

namespace strata::viewer {

enum class DisplayView { Colour, RelativeError, SampleCount, AdaptiveMask };

struct DisplaySettings {
    DisplayView view = DisplayView::Colour;
    Tonemap tonemap = kDefaultTonemap;
    float exposure = 0.0f;     // stops
    bool split = false;        // left of `divider` side 0, right of it side 1
    float divider = 0.5f;      // fraction of the viewport width
    float errorScale = 0.25f;  // relative error at the top of the false-colour ramp
    float sampleScale = 1.0f;  // sample count at the top of the ramp
    bool operator==(const DisplaySettings&) const = default;
};

class DisplayPipeline {
public:
    // Compiles the shaders; throws strata::Error with the compiler's log on failure.
    DisplayPipeline();
    ~DisplayPipeline();
    DisplayPipeline(const DisplayPipeline&) = delete;
    DisplayPipeline& operator=(const DisplayPipeline&) = delete;

    // Uploads side 0 or 1's image for `view` (resizing its textures when the size changed): its
    // error texture only if the view reads it. The colour view does not, and skipping it saves a
    // third of the upload.
    void upload(int side, const DisplayImage& image, DisplayView view);
    // Draws into the bound framebuffer's `viewport`. The images must have been uploaded for
    // `settings.view`.
    void draw(const DisplaySettings& settings, const Viewport& viewport) const;

    static bool readsError(DisplayView view);

private:
    static constexpr int kViews = 4;
    // One program per DisplayView (shaders/display.frag's STRATA_VIEW).
    std::array<GLuint, kViews> programs_{};
    GLuint vertexArray_ = 0;
    std::array<GLuint, 2> imageTextures_{};
    std::array<GLuint, 2> errorTextures_{};
};

}  // namespace strata::viewer
