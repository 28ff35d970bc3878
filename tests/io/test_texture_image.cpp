// Texture decoding (io/texture_image.h): 8-bit colour and data textures kept at 8 bits, and
// malformed bytes refused with the file's name.
#include <doctest/doctest.h>

#include <string>
#include <vector>
#include <stb_image_write.h>

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
}  // namespace

TEST_CASE("an 8-bit colour texture decodes its RGB as sRGB and its alpha linearly; data stays linear; both at 8 bits") {
    const std::string png = pngBytes(2, 1, 4, {10, 128, 255, 128, 0, 1, 2, 255});
    const Texture colour = decodeTexture(png, "a.png", TextureEncoding::Colour);
    CHECK(colour.width() == 2);
    CHECK(colour.channels() == 4);
    CHECK(colour.size().bytesPerChannel == 1);
    const auto& srgb = srgbDecodingTable();
    CHECK(colour.texel(0, 0) == glm::vec4(srgb[10], srgb[128], srgb[255], 128.0f / 255.0f));
    const Texture data = decodeTexture(png, "a.png", TextureEncoding::Data);
    CHECK(data.texel(0, 0) == glm::vec4(10.0f / 255.0f, 128.0f / 255.0f, 1.0f, 128.0f / 255.0f));
    CHECK(data.texel(1, 0) == glm::vec4(0.0f, 1.0f / 255.0f, 2.0f / 255.0f, 1.0f));
}

TEST_CASE("an EXR texture is read through OpenEXR as linear values") {
    const test::ScratchDir dir = test::scratchDir("texture_exr");
    Image image{2, 1, {glm::vec3(0.25f, 2.0f, 0.5f), glm::vec3(1.0f)}};
    writeImage(dir / "t.exr", image);
    const Texture t = decodeTexture(test::fileBytes(dir / "t.exr"), "t.exr", TextureEncoding::Colour);
    CHECK(t.texel(0, 0) == glm::vec4(0.25f, 2.0f, 0.5f, 1.0f));
}

TEST_CASE("bytes no decoder reads are refused with the file's name") {
    for (const std::string& bytes : {std::string(), std::string("not an image"), std::string("\x89PNG\r\n\x1a\n\0\0", 10)}) {
        try {
            decodeTexture(bytes, "bad.png", TextureEncoding::Colour);
            FAIL("decoded");
        } catch (const Error& e) {
            CHECK(std::string(e.what()).rfind("bad.png: cannot decode the texture", 0) == 0);
        }
    }
}

TEST_CASE("a header claiming more texels than its file can hold is refused before any allocation") {
    CHECK_THROWS_WITH_AS(decodeTexture(test::forgedTga(), "forged.tga", TextureEncoding::Colour),
                         "forged.tga: a 2608 x 29814 image cannot be stored in 26 bytes (truncated or corrupt)",
                         Error);
    // A genuine image compressed far below a byte a texel still loads.
    const std::string flat = pngBytes(2048, 2048, 1, std::vector<unsigned char>(2048 * 2048, 128));
    CHECK(flat.size() < 2048 * 2048 / 50);
    const Texture t = decodeTexture(flat, "flat.png", TextureEncoding::Data);
    CHECK(t.texel(1000, 1000).x == doctest::Approx(128.0 / 255.0));
}
