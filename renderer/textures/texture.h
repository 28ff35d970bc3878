#pragma once
// A texture image as shading reads it: 1 to 4 channels, looked up by UV with bilinear filtering
// (or the nearest texel, where a glTF sampler asks for it), each texel read as linear float, and
// wrapped outside [0, 1) along each axis as its wrap mode says (repeat unless a glTF sampler or
// MTL's -clamp says otherwise).
//
// Texels are stored as they came: 8-bit codes for images that hold 8 bits a channel (PNG, JPEG,
// ...), decoded to linear values only when read, through a 256-entry table per channel; floats
// for images that hold floats (EXR). An 8-bit texture so takes a quarter of the memory of its
// float copy, and reads exactly the floats that copy would hold.
//
// UV convention (every loader stores this one): u to the right, v up, origin at the image's
// lower-left corner, as OBJ's vt gives them; glTF's v runs down from the upper-left, so its loader
// stores 1 - v. Texel rows are kept top row first, as images are stored, so v = 1 is row 0's top
// edge. Texel (x, y) covers [x, x+1) x [y, y+1) of the image in texel units; its centre is the
// point where a lookup returns it unblended.
#include <array>
#include <cstdint>
#include <memory>
#include <vector>
#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

namespace strata {

// What the 8-bit codes of a texture's channels mean.
enum class TextureEncoding {
    Colour,  // RGB is sRGB-encoded (base colour, diffuse, emission); alpha is linear
    Data,    // every channel linear, code / 255 (coverage, normals, roughness/metallic)
};

// What a lookup outside [0, 1) reads along one axis (glTF's sampler wrap modes).
enum class TextureWrap {
    Repeat,          // the image tiles the plane
    ClampToEdge,     // the edge texels stretch out (MTL's -clamp on)
    MirroredRepeat,  // every other tile is the image mirrored
};

// How a texture is looked up: its wrap modes along u and v, and whether it reads the nearest
// texel instead of blending the four nearest (glTF's magFilter NEAREST: pixel art).
struct TextureSampling {
    TextureWrap u = TextureWrap::Repeat;
    TextureWrap v = TextureWrap::Repeat;
    bool nearest = false;

    bool operator==(const TextureSampling&) const = default;
};

// The sRGB decoding of each 8-bit code (IEC 61966-2-1):
// c / 12.92 for c = code / 255 <= 0.04045, else ((c + 0.055) / 1.055)^2.4.
const std::array<float, 256>& srgbDecodingTable();

// The shape of a texture's storage: width x height texels of `channels` channels,
// `bytesPerChannel` bytes each (1: 8-bit codes, 4: floats).
struct TextureSize {
    int width = 0;
    int height = 0;
    int channels = 0;
    int bytesPerChannel = 1;

    uint64_t bytes() const {
        return static_cast<uint64_t>(width) * static_cast<uint64_t>(height) *
               static_cast<uint64_t>(channels * bytesPerChannel);
    }
};

class Texture {
public:
    // `texels`: width * height * channels linear values, row-major, top row first. Missing
    // channels of a lookup read as image files mean them: one channel is grey (g, g, g, 1), two
    // are grey and alpha (g, g, g, a), three have alpha 1.
    Texture(int width, int height, int channels, std::vector<float> texels);
    // The same as 8-bit codes, kept as they are and read as `encoding` says: under Colour the
    // colour channels (the first of 1 or 2, the first three of 3 or 4) through
    // srgbDecodingTable(), every other channel as code / 255.
    Texture(int width, int height, int channels, std::vector<uint8_t> codes, TextureEncoding encoding);

    // The same texels, shared, looked up as `sampling` says.
    Texture sampled(const TextureSampling& sampling) const;

    // The value at `uv`: the bilinear blend of the four nearest texels, each read as linear float
    // first (or the nearest texel alone), wrapped outside [0, 1).
    glm::vec4 lookup(glm::vec2 uv) const;
    // The texel at integer coordinates (wrapped), top row y = 0.
    glm::vec4 texel(int x, int y) const;
    const TextureSampling& sampling() const { return sampling_; }

    int width() const { return width_; }
    int height() const { return height_; }
    int channels() const { return channels_; }
    TextureSize size() const { return {width_, height_, channels_, codes_ ? 1 : 4}; }
    // Mean and largest value over all texels, per channel (as a lookup widens them).
    const glm::vec4& mean() const { return mean_; }
    const glm::vec4& max() const { return max_; }

private:
    // The texel at row-major index `texel` (not wrapped), widened to four channels.
    glm::vec4 texelAt(size_t texel) const;
    void computeStatistics();

    int width_;
    int height_;
    int channels_;
    // One of the two holds the texels, which sampled() copies share; read through the pointer
    // beside it.
    std::shared_ptr<const std::vector<float>> floats_;
    std::shared_ptr<const std::vector<uint8_t>> codes_;
    const float* floatTexels_ = nullptr;
    const uint8_t* codeTexels_ = nullptr;
    TextureSampling sampling_;
    // For codes_: each channel's code -> linear value table.
    std::array<const float*, 4> decoding_{};
    glm::vec4 mean_{0.0f};
    glm::vec4 max_{0.0f};
};

}  // namespace strata
