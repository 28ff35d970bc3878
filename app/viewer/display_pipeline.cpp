#include "display_pipeline.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "util/error.h"
#include "shader_sources.h"

namespace strata::viewer {
namespace {

GLuint compileShader(GLenum stage, const std::string& source, const char* name) {
    const GLuint shader = glCreateShader(stage);
    const char* text = source.c_str();
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    GLint ok = GL_FALSE;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        std::string log(4096, '\0');
        glGetShaderInfoLog(shader, static_cast<GLsizei>(log.size()), nullptr, log.data());
        glDeleteShader(shader);
        throw Error(std::string("shaders/") + name + ": does not compile: " + log.c_str());
    }
    return shader;
}

// display.frag with STRATA_VIEW defined: the definition goes after the #version line, which must
// come first.
std::string fragmentSourceFor(DisplayView view) {
    const std::string source = kDisplayFragmentShader;
    const size_t afterVersion = source.find('\n') + 1;
    return source.substr(0, afterVersion) + "#define STRATA_VIEW " + std::to_string(static_cast<int>(view)) +
           "\n" + source.substr(afterVersion);
}

GLuint linkProgram(DisplayView view) {
    const GLuint vertex = compileShader(GL_VERTEX_SHADER, kDisplayVertexShader, "display.vert");
    const GLuint fragment = compileShader(GL_FRAGMENT_SHADER, fragmentSourceFor(view), "display.frag");
    const GLuint program = glCreateProgram();
    glAttachShader(program, vertex);
    glAttachShader(program, fragment);
    glLinkProgram(program);
    glDeleteShader(vertex);
    glDeleteShader(fragment);
    GLint ok = GL_FALSE;
    glGetProgramiv(program, GL_LINK_STATUS, &ok);
    if (!ok) {
        std::string log(4096, '\0');
        glGetProgramInfoLog(program, static_cast<GLsizei>(log.size()), nullptr, log.data());
        glDeleteProgram(program);
        throw Error(std::string("shaders/display: does not link: ") + log.c_str());
    }
    return program;
}

GLuint makeTexture() {
    GLuint texture = 0;
    glGenTextures(1, &texture);
    glBindTexture(GL_TEXTURE_2D, texture);
    // Nearest: a texel is a pixel's estimate; blending neighbours would blend sample counts too.
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    const float empty[4] = {0.0f, 0.0f, 0.0f, 0.0f};
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, 1, 1, 0, GL_RGBA, GL_FLOAT, empty);
    return texture;
}

}  // namespace

DisplayPipeline::DisplayPipeline() {
    try {
        for (int view = 0; view < kViews; ++view) programs_[view] = linkProgram(static_cast<DisplayView>(view));
    } catch (...) {
        for (GLuint program : programs_) glDeleteProgram(program);  // the unlinked ones are 0: a no-op
        throw;
    }
    glGenVertexArrays(1, &vertexArray_);  // core profile draws need one, even without attributes
    for (int side = 0; side < 2; ++side) {
        imageTextures_[side] = makeTexture();
        errorTextures_[side] = makeTexture();
    }
}

DisplayPipeline::~DisplayPipeline() {
    glDeleteTextures(2, imageTextures_.data());
    glDeleteTextures(2, errorTextures_.data());
    glDeleteVertexArrays(1, &vertexArray_);
    for (GLuint program : programs_) glDeleteProgram(program);
}

bool DisplayPipeline::readsError(DisplayView view) {
    return view == DisplayView::RelativeError || view == DisplayView::AdaptiveMask;
}

void DisplayPipeline::upload(int side, const DisplayImage& image, DisplayView view) {
    if (image.width < 1 || image.height < 1) return;
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glBindTexture(GL_TEXTURE_2D, imageTextures_.at(side));
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, image.width, image.height, 0, GL_RGBA, GL_FLOAT,
                 image.meanAndCount.data());
    if (!readsError(view)) return;
    glBindTexture(GL_TEXTURE_2D, errorTextures_.at(side));
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RG32F, image.width, image.height, 0, GL_RG, GL_FLOAT,
                 image.errorAndDone.data());
}

void DisplayPipeline::draw(const DisplaySettings& settings, const Viewport& viewport) const {
    glViewport(viewport.x, viewport.y, viewport.width, viewport.height);
    glDisable(GL_BLEND);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_FRAMEBUFFER_SRGB);  // the shader encodes sRGB itself, like renderer/io/tonemap.cpp
    const GLuint program = programs_.at(static_cast<size_t>(settings.view));
    glUseProgram(program);
    glUniform1i(glGetUniformLocation(program, "uImage"), 0);
    glUniform1i(glGetUniformLocation(program, "uError"), 1);
    glUniform2f(glGetUniformLocation(program, "uViewportOrigin"), static_cast<float>(viewport.x),
                static_cast<float>(viewport.y));
    glUniform2f(glGetUniformLocation(program, "uViewportSize"), static_cast<float>(viewport.width),
                static_cast<float>(viewport.height));
    glUniform1i(glGetUniformLocation(program, "uTonemap"), static_cast<int>(settings.tonemap));
    glUniform1f(glGetUniformLocation(program, "uExposure"), settings.exposure);
    glUniform1f(glGetUniformLocation(program, "uErrorScale"), settings.errorScale);
    glUniform1f(glGetUniformLocation(program, "uSampleScale"), settings.sampleScale);
    glBindVertexArray(vertexArray_);
    // Split: side 1 from the first column whose centre lies at or right of the divider.
    const int firstRight = settings.split
        ? std::clamp(static_cast<int>(std::ceil(settings.divider * static_cast<float>(viewport.width) - 0.5f)), 0,
                     viewport.width)
        : viewport.width;
    const int columns[3] = {0, firstRight, viewport.width};
    for (int side = 0; side < 2; ++side) {
        if (columns[side + 1] <= columns[side]) continue;
        glEnable(GL_SCISSOR_TEST);
        glScissor(viewport.x + columns[side], viewport.y, columns[side + 1] - columns[side], viewport.height);
        glActiveTexture(GL_TEXTURE0);
        glBindTexture(GL_TEXTURE_2D, imageTextures_[side]);
        glActiveTexture(GL_TEXTURE1);
        glBindTexture(GL_TEXTURE_2D, errorTextures_[side]);
        glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    glDisable(GL_SCISSOR_TEST);
    glBindVertexArray(0);
    glUseProgram(0);
    glActiveTexture(GL_TEXTURE0);
}

}  // namespace strata::viewer
