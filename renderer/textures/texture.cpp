#include "textures/texture.h"

#include <cmath>
#include <glm/common.hpp>

#include "util/error.h"

namespace strata {
namespace {
int wrap(int i, int n) {
    const int r = i % n;
    return r < 0 ? r + n : r;
}
}  // namespace

Texture::Texture(int width, int height, int channels, std::vector<float> texels)
    : width_(width), height_(height), channels_(channels), texels_(std::move(texels)) {
    if (width < 1 || height < 1 || channels < 1 || channels > 4 ||
        texels_.size() != static_cast<size_t>(width) * height * channels) {
        throw Error("a texture's size does not match its texels");
    }
    glm::dvec4 sum(0.0);
    max_ = glm::vec4(-INFINITY);
    for (int y = 0; y < height_; ++y) {
        for (int x = 0; x < width_; ++x) {
            const glm::vec4 t = texel(x, y);
            sum += glm::dvec4(t);
            max_ = glm::max(max_, t);
        }
    }
    mean_ = glm::vec4(sum / (static_cast<double>(width_) * height_));
}

glm::vec4 Texture::texel(int x, int y) const {
    const float* t = texels_.data() + (static_cast<size_t>(wrap(y, height_)) * width_ + wrap(x, width_)) * channels_;
    switch (channels_) {
        case 1: return {t[0], t[0], t[0], 1.0f};
        case 2: return {t[0], t[0], t[0], t[1]};
        case 3: return {t[0], t[1], t[2], 1.0f};
        default: return {t[0], t[1], t[2], t[3]};
    }
}

glm::vec4 Texture::lookup(glm::vec2 uv) const {
    // Texel centres sit at half-integers: x = u W - 1/2 in centre coordinates, y likewise from the
    // top (v up, rows down). floor() of a huge or non-finite coordinate is no valid int: such a
    // UV reads texel (0, 0).
    const float fx = uv.x * static_cast<float>(width_) - 0.5f;
    const float fy = (1.0f - uv.y) * static_cast<float>(height_) - 0.5f;
    if (!(std::abs(fx) < 1e9f && std::abs(fy) < 1e9f)) return texel(0, 0);
    const float x0 = std::floor(fx);
    const float y0 = std::floor(fy);
    const float tx = fx - x0;
    const float ty = fy - y0;
    // Wrapped once here, so that the int arithmetic below cannot overflow.
    const int x = wrap(static_cast<int>(std::fmod(x0, static_cast<float>(width_))), width_);
    const int y = wrap(static_cast<int>(std::fmod(y0, static_cast<float>(height_))), height_);
    return (1.0f - ty) * ((1.0f - tx) * texel(x, y) + tx * texel(x + 1, y)) +
           ty * ((1.0f - tx) * texel(x, y + 1) + tx * texel(x + 1, y + 1));
}

}  // namespace strata
