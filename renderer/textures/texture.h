#pragma once
// A texture image as shading reads it: linear float texels (1 to 4 channels), looked up by UV with
// bilinear filtering and repeat wrap.
//
// UV convention (every loader stores this one): u to the right, v up, origin at the image's
// lower-left corner, as OBJ's vt gives them; glTF's v runs down from the upper-left, so its loader
// stores 1 - v. Texel rows are kept top row first, as images are stored, so v = 1 is row 0's top
// edge. Texel (x, y) covers [x, x+1) x [y, y+1) of the image in texel units; its centre is the
// point where a lookup returns it unblended.
#include <cstdint>
#include <vector>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

namespace strata {

class Texture {
public:
    // `texels`: width * height * channels values, row-major, top row first. Missing channels of
    // a lookup read as image files mean them: one channel is grey (g, g, g, 1), two are grey and
    // alpha (g, g, g, a), three have alpha 1.
    Texture(int width, int height, int channels, std::vector<float> texels);

    // The bilinearly filtered value at `uv`, repeating outside [0, 1).
    glm::vec4 lookup(glm::vec2 uv) const;
    // The texel at integer coordinates (wrapped), top row y = 0.
    glm::vec4 texel(int x, int y) const;

    int width() const { return width_; }
    int height() const { return height_; }
    int channels() const { return channels_; }
    // Mean and largest value over all texels, per channel (as a lookup widens them).
    const glm::vec4& mean() const { return mean_; }
    const glm::vec4& max() const { return max_; }

private:
    int width_;
    int height_;
    int channels_;
    std::vector<float> texels_;
    glm::vec4 mean_{0.0f};
    glm::vec4 max_{0.0f};
};

}  // namespace strata
