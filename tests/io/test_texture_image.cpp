// Texture decoding (io/texture_image.h): 8-bit colour and data textures kept at 8 bits, malformed
// bytes refused with the file's name, and headers that claim more texels than their file holds
// refused before anything is allocated, format by format.
#include <doctest/doctest.h>

#include <string>
#include <vector>
#include <stb_image_write.h>

#include "image_support.h"
#include "io/image_io.h"
#include "io/texture_image.h"
#include "test_support.h"
#include "util/error.h"

using namespace strata;

namespace {
// A PNG of `channels` 8-bit channels in memory.
std::string pngBytes(int width, int height, int channels, const std::vector<unsigned char>& pixels) {
    std::string out;
    stbi_write_png_to_func(
        [](void* context, void* data, int size) {
            static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<size_t>(size));
        },
        &out, width, height, channels, pixels.data(), width * channels);
    return out;
}

Texture decode(const std::string& bytes, const std::string& name, TextureEncoding encoding = TextureEncoding::Data) {
    std::vector<std::string> warnings;
    Texture texture = decodeTexture(bytes, name, encoding, warnings);
    CHECK(warnings.empty());
    return texture;
}

std::string errorOf(const std::string& bytes, const std::string& name) {
    try {
        readTextureHeader(bytes, name);
    } catch (const Error& e) {
        return e.what();
    }
    return "no error";
}
}  // namespace

TEST_CASE("an 8-bit colour texture decodes its RGB as sRGB and its alpha linearly, and data stays linear, all at 8 bits") {
    const std::string png = pngBytes(2, 1, 4, {10, 128, 255, 128, 0, 1, 2, 255});
    const Texture colour = decode(png, "a.png", TextureEncoding::Colour);
    CHECK(colour.width() == 2);
    CHECK(colour.channels() == 4);
    CHECK(colour.size().bytesPerChannel == 1);
    const auto& srgb = srgbDecodingTable();
    CHECK(colour.texel(0, 0) == glm::vec4(srgb[10], srgb[128], srgb[255], 128.0f / 255.0f));
    const Texture data = decode(png, "a.png", TextureEncoding::Data);
    CHECK(data.texel(0, 0) == glm::vec4(10.0f / 255.0f, 128.0f / 255.0f, 1.0f, 128.0f / 255.0f));
    CHECK(data.texel(1, 0) == glm::vec4(0.0f, 1.0f / 255.0f, 2.0f / 255.0f, 1.0f));
}

TEST_CASE("an EXR texture is read through OpenEXR as linear floats") {
    const test::ScratchDir dir = test::scratchDir("texture_exr");
    Image image{2, 1, {glm::vec3(0.25f, 2.0f, 0.5f), glm::vec3(1.0f)}};
    writeImage(dir / "t.exr", image);
    const Texture t = decode(test::fileBytes(dir / "t.exr"), "t.exr", TextureEncoding::Colour);
    CHECK(t.texel(0, 0) == glm::vec4(0.25f, 2.0f, 0.5f, 1.0f));
    CHECK(t.size().bytesPerChannel == 4);
    CHECK(readTextureHeader(test::fileBytes(dir / "t.exr"), "t.exr").bytes() == 2 * 3 * 4);
}

TEST_CASE("bytes no decoder reads are refused with the file's name") {
    for (const std::string& bytes : {std::string(), std::string("not an image"), std::string("\x89PNG\r\n\x1a\n\0\0", 10)}) {
        std::vector<std::string> warnings;
        try {
            decodeTexture(bytes, "bad.png", TextureEncoding::Colour, warnings);
            FAIL("decoded");
        } catch (const Error& e) {
            CHECK(std::string(e.what()).rfind("bad.png: cannot decode the texture", 0) == 0);
        }
    }
}

TEST_CASE("a header claiming more texels than its file can hold is refused before any allocation") {
    CHECK(errorOf(test::forgedTga(), "forged.tga") ==
          "forged.tga: a 2608 x 29814 image cannot be stored in 26 bytes (truncated or corrupt)");
    // A genuine image compressed far below a byte a texel still loads.
    const std::string flat = pngBytes(2048, 2048, 1, std::vector<unsigned char>(2048 * 2048, 128));
    CHECK(flat.size() < 2048 * 2048 / 50);
    const Texture t = decode(flat, "flat.png");
    CHECK(t.texel(1000, 1000).x == doctest::Approx(128.0 / 255.0));
}

TEST_CASE("a 1-bit PNG is kept at a byte a texel, its 16384 x 16384 at 256 MiB where floats took 1 GiB") {
    // 16 x 2 pixels, 1 bit each: rows 0xf0 0x0f and 0xaa 0x55, each after its filter byte 0.
    const std::string rows("\0\xf0\x0f\0\xaa\x55", 6);
    const Texture t = decode(test::pngFile(16, 2, 1, 0, rows), "bits.png");
    CHECK(t.size().bytes() == 32);
    CHECK(t.texel(0, 0).x == 1.0f);
    CHECK(t.texel(4, 0).x == 0.0f);
    CHECK(t.texel(12, 0).x == 1.0f);
    CHECK(t.texel(0, 1).x == 1.0f);
    CHECK(t.texel(1, 1).x == 0.0f);
    // A flat 16384^2 1-bit PNG needs at least 33 KB: this one is plausible, and 1 channel of 8 bits.
    const TextureSize huge = readTextureHeader(test::forgedPng(16384, 16384, 1, 0, 72 << 10), "huge.png");
    CHECK(huge.bytes() == uint64_t{256} << 20);
}

TEST_CASE("an RGBA PNG is kept at 4 bytes a texel: 1 GiB for 16384 x 16384, where floats took 4 GiB") {
    const TextureSize size = readTextureHeader(test::forgedPng(16384, 16384, 8, 6, 1 << 20), "rgba.png");
    CHECK(size.channels == 4);
    CHECK(size.bytes() == uint64_t{1} << 30);
}

TEST_CASE("a grey PNG with a transparent colour decodes with its alpha channel") {
    // tRNS: grey level 255 (as a 16-bit sample) is transparent.
    const std::string transparent = test::pngChunk("tRNS", std::string("\0\xff", 2));
    const std::string png = test::pngFile(2, 1, 8, 0, std::string("\0\x40\xff", 3), transparent);
    CHECK(readTextureHeader(png, "grey.png").channels == 2);
    const Texture t = decode(png, "grey.png");
    CHECK(t.channels() == 2);
    CHECK(t.texel(0, 0) == glm::vec4(64.0f / 255.0f, 64.0f / 255.0f, 64.0f / 255.0f, 1.0f));
    CHECK(t.texel(1, 0).w == 0.0f);
}

TEST_CASE("a GIF decodes its first image at 8 bits, and one whose data is too short for its size is refused") {
    // The palette: black, white, red, green.
    const Texture t = decode(test::gifFile(3, 2, {0, 1, 2, 3, 2, 1}), "small.gif", TextureEncoding::Data);
    CHECK(t.channels() == 4);
    CHECK(t.size().bytes() == 3 * 2 * 4);
    CHECK(t.texel(0, 0) == glm::vec4(0, 0, 0, 1));
    CHECK(t.texel(1, 0) == glm::vec4(1, 1, 1, 1));
    CHECK(t.texel(2, 0) == glm::vec4(1, 0, 0, 1));
    CHECK(t.texel(0, 1) == glm::vec4(0, 1, 0, 1));
    // 16384^2 pixels need at least 98 KB of LZW codes (4096 pixels per 12 bits at best); stb_image
    // would decode the 40 KB of a fuzzer's finding into 2.3 GB of canvas (RGBA and its animation
    // buffers), padding what is missing.
    CHECK(errorOf(test::forgedGif(16384, 16384, 40000), "big.gif") ==
          "big.gif: a 16384 x 16384 image cannot be stored in 40000 bytes (truncated or corrupt)");
    CHECK(readTextureHeader(test::forgedGif(16384, 16384, 100000), "big.gif").bytes() == uint64_t{1} << 30);
}

TEST_CASE("a GIF cut inside its image decodes with a warning naming the file") {
    std::vector<unsigned char> indices(64 * 64);
    for (size_t i = 0; i < indices.size(); ++i) indices[i] = static_cast<unsigned char>(i % 4);
    const std::string gif = test::gifFile(64, 64, indices);
    std::vector<std::string> warnings;
    const Texture t = decodeTexture(gif.substr(0, gif.size() / 2), "cut.gif", TextureEncoding::Data, warnings);
    CHECK(t.width() == 64);
    CHECK(t.texel(1, 0) == glm::vec4(1, 1, 1, 1));
    CHECK(warnings == std::vector<std::string>{
                          "cut.gif: truncated GIF (the file ends inside its image); the rest decodes blank"});
}
