#include "textures/texture.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>

#include "util/error.h"

namespace strata {
namespace {

int wrap(int i, int n) {
    const int r = i % n;
    return r < 0 ? r + n : r;
}

// The texel index in [0, n) that index i reads under `mode`.
int wrapIndex(int i, int n, TextureWrap mode) {
    switch (mode) {
        case TextureWrap::Repeat: break;
        case TextureWrap::ClampToEdge: return i < 0 ? 0 : i >= n ? n - 1 : i;
        case TextureWrap::MirroredRepeat: {
            const int m = wrap(i, 2 * n);
            return m < n ? m : 2 * n - 1 - m;
        }
    }
    return wrap(i, n);
}

// A texel coordinate (its floor) brought near [0, n) as `mode` reads it, so that int arithmetic
// on it cannot overflow: whole periods taken off (n, or 2n mirrored), or clamped just outside.
int reducedIndex(float coordinate, int n, TextureWrap mode) {
    const auto size = static_cast<float>(n);
    switch (mode) {
        case TextureWrap::Repeat: break;
        case TextureWrap::ClampToEdge: return static_cast<int>(std::clamp(coordinate, -1.0f, size));
        case TextureWrap::MirroredRepeat: return static_cast<int>(std::fmod(coordinate, 2.0f * size));
    }
    return static_cast<int>(std::fmod(coordinate, size));
}

// code / 255 in float, as the division gives it.
const std::array<float, 256>& linearDecodingTable() {
    static const std::array<float, 256> table = [] {
        std::array<float, 256> t{};
        for (int code = 0; code < 256; ++code) {
            t[static_cast<size_t>(code)] = static_cast<float>(code) / 255.0f;
        }
        return t;
    }();
    return table;
}

void requireMatchingSize(int width, int height, int channels, size_t values) {
    if (width < 1 || height < 1 || channels < 1 || channels > 4 ||
        values != static_cast<size_t>(width) * static_cast<size_t>(height) * static_cast<size_t>(channels)) {
        throw Error("a texture's size does not match its texels");
    }
}

}  // namespace

const std::array<float, 256>& srgbDecodingTable() {
    static const std::array<float, 256> table = [] {
        std::array<float, 256> t{};
        for (int code = 0; code < 256; ++code) {
            const double c = code / 255.0;
            t[static_cast<size_t>(code)] =
                static_cast<float>(c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4));
        }
        return t;
    }();
    return table;
}

Texture::Texture(int width, int height, int channels, std::vector<float> texels)
    : width_(width),
      height_(height),
      channels_(channels),
      floats_(std::make_shared<const std::vector<float>>(std::move(texels))),
      floatTexels_(floats_->data()) {
    requireMatchingSize(width, height, channels, floats_->size());
    computeStatistics();
}

Texture::Texture(int width, int height, int channels, std::vector<uint8_t> codes, TextureEncoding encoding)
    : width_(width),
      height_(height),
      channels_(channels),
      codes_(std::make_shared<const std::vector<uint8_t>>(std::move(codes))),
      codeTexels_(codes_->data()) {
    requireMatchingSize(width, height, channels, codes_->size());
    // Grey and grey-alpha images have their colour in channel 0 only; the last of 2 or 4 is alpha.
    const int colourChannels = channels == 1 || channels == 3 ? channels : channels - 1;
    for (int c = 0; c < channels; ++c) {
        const bool srgb = encoding == TextureEncoding::Colour && c < colourChannels;
        decoding_[static_cast<size_t>(c)] = (srgb ? srgbDecodingTable() : linearDecodingTable()).data();
    }
    computeStatistics();
}

void Texture::computeStatistics() {
    glm::dvec4 sum(0.0);
    max_ = glm::vec4(-INFINITY);
    const size_t texels = static_cast<size_t>(width_) * static_cast<size_t>(height_);
    for (size_t i = 0; i < texels; ++i) {
        const glm::vec4 t = texelAt(i);
        sum += glm::dvec4(t);
        max_ = glm::max(max_, t);
    }
    mean_ = glm::vec4(sum / static_cast<double>(texels));
}

glm::vec4 Texture::texelAt(size_t texel) const {
    const size_t first = texel * static_cast<size_t>(channels_);
    float t[4];
    if (codeTexels_ == nullptr) {
        for (size_t c = 0; c < static_cast<size_t>(channels_); ++c) t[c] = floatTexels_[first + c];
    } else {
        for (size_t c = 0; c < static_cast<size_t>(channels_); ++c) t[c] = decoding_[c][codeTexels_[first + c]];
    }
    switch (channels_) {
        case 1: return {t[0], t[0], t[0], 1.0f};
        case 2: return {t[0], t[0], t[0], t[1]};
        case 3: return {t[0], t[1], t[2], 1.0f};
        default: return {t[0], t[1], t[2], t[3]};
    }
}

Texture Texture::sampled(const TextureSampling& sampling) const {
    Texture copy = *this;
    copy.sampling_ = sampling;
    return copy;
}

glm::vec4 Texture::texel(int x, int y) const {
    const auto row = static_cast<size_t>(wrapIndex(y, height_, sampling_.v));
    return texelAt(row * static_cast<size_t>(width_) + static_cast<size_t>(wrapIndex(x, width_, sampling_.u)));
}

glm::vec4 Texture::lookup(glm::vec2 uv) const {
    // Texel centres sit at half-integers: x = u W - 1/2 in centre coordinates, y likewise from the
    // top (v up, rows down). floor() of a huge or non-finite coordinate is no valid int: such a
    // UV reads texel (0, 0).
    const float fx = uv.x * static_cast<float>(width_) - 0.5f;
    const float fy = (1.0f - uv.y) * static_cast<float>(height_) - 0.5f;
    if (!(std::abs(fx) < 1e9f && std::abs(fy) < 1e9f)) return texel(0, 0);
    if (sampling_.nearest) {
        // The texel whose square holds uv: the one whose centre is nearest.
        return texel(reducedIndex(std::floor(fx + 0.5f), width_, sampling_.u),
                     reducedIndex(std::floor(fy + 0.5f), height_, sampling_.v));
    }
    const float x0 = std::floor(fx);
    const float y0 = std::floor(fy);
    const float tx = fx - x0;
    const float ty = fy - y0;
    // Reduced once here, so that the int arithmetic below cannot overflow; then the two columns
    // and the two rows wrapped, each once.
    const int x = reducedIndex(x0, width_, sampling_.u);
    const int y = reducedIndex(y0, height_, sampling_.v);
    const auto width = static_cast<size_t>(width_);
    const auto left = static_cast<size_t>(wrapIndex(x, width_, sampling_.u));
    const auto right = static_cast<size_t>(wrapIndex(x + 1, width_, sampling_.u));
    const size_t top = static_cast<size_t>(wrapIndex(y, height_, sampling_.v)) * width;
    const size_t bottom = static_cast<size_t>(wrapIndex(y + 1, height_, sampling_.v)) * width;
    return (1.0f - ty) * ((1.0f - tx) * texelAt(top + left) + tx * texelAt(top + right)) +
           ty * ((1.0f - tx) * texelAt(bottom + left) + tx * texelAt(bottom + right));
}

}  // namespace strata
