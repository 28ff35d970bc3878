// WebP textures through libwebp (io/webp_image.h): lossless files decode to their exact bytes,
// with an alpha channel only where the file has one; a header claiming more texels than any
// WebP coding packs into the file is refused before decoding, and damaged data with its name.
#include <doctest/doctest.h>

#include <string>
#include <vector>
#include <webp/encode.h>

#include "io/texture_image.h"
#include "io/webp_image.h"
#include "util/error.h"

using namespace strata;

namespace {

// A lossless WebP of `pixels` (RGB or RGBA, top row first).
std::string losslessWebp(int width, int height, int channels, const std::vector<uint8_t>& pixels) {
    uint8_t* out = nullptr;
    const size_t size = channels == 4 ? WebPEncodeLosslessRGBA(pixels.data(), width, height, width * 4, &out)
                                      : WebPEncodeLosslessRGB(pixels.data(), width, height, width * 3, &out);
    REQUIRE(size > 0);
    std::string bytes(reinterpret_cast<const char*>(out), size);
    WebPFree(out);
    return bytes;
}

std::vector<uint8_t> ramp(int width, int height, int channels) {
    std::vector<uint8_t> pixels;
    for (int i = 0; i < width * height * channels; ++i) pixels.push_back(static_cast<uint8_t>(37 * i + 11));
    return pixels;
}

std::string errorOf(const std::string& bytes) {
    std::vector<std::string> warnings;
    try {
        decodeTexture(bytes, "t.webp", TextureEncoding::Data, warnings);
    } catch (const Error& e) {
        return e.what();
    }
    return "decoded";
}

}  // namespace

TEST_CASE("webp: a lossless file decodes to its bytes, RGBA with alpha and RGB without") {
    for (int channels : {3, 4}) {
        const std::vector<uint8_t> pixels = ramp(5, 3, channels);
        const std::string file = losslessWebp(5, 3, channels, pixels);
        REQUIRE(isWebp(file));
        const TextureSize size = readWebpHeader(file, "t.webp");
        CHECK(size.width == 5);
        CHECK(size.height == 3);
        CHECK(size.channels == channels);
        CHECK(decodeWebp(file, "t.webp") == pixels);
        // Through the texture decoder, as a data texture: code / 255 per channel.
        std::vector<std::string> warnings;
        const Texture texture = decodeTexture(file, "t.webp", TextureEncoding::Data, warnings);
        CHECK(warnings.empty());
        CHECK(texture.texel(4, 2).x == doctest::Approx(pixels[(2 * 5 + 4) * channels] / 255.0));
    }
    // An opaque RGBA image is stored without alpha: three channels.
    const std::vector<uint8_t> opaque(4 * 4 * 4, 255);
    CHECK(readWebpHeader(losslessWebp(4, 4, 4, opaque), "t.webp").channels == 3);
}

TEST_CASE("webp: a forged size, a damaged body and a file that is not WebP are refused with the name") {
    std::string file = losslessWebp(8, 8, 3, ramp(8, 8, 3));
    // VP8L: the signature byte 0x2f at offset 20, then width - 1 and height - 1 in 14 bits each.
    REQUIRE(file.substr(12, 4) == "VP8L");
    std::string forged = file;
    forged[21] = '\xff';
    forged[22] = '\xff';
    forged[23] = '\xff';
    forged[24] = static_cast<char>((forged[24] & 0xf0) | 0x0f);
    CHECK(errorOf(forged) == "t.webp: a 16384 x 16384 image cannot be stored in " + std::to_string(file.size()) +
                                 " bytes (truncated or corrupt)");
    // The header intact, the image data cut short.
    CHECK(errorOf(file.substr(0, file.size() - 6)).rfind("t.webp: cannot decode the texture", 0) == 0);
    CHECK(errorOf(std::string("RIFF\x10\0\0\0WEBPVP8X", 16)) ==
          "t.webp: cannot decode the texture (a WebP file that ends inside its header)");
    CHECK(errorOf(file.substr(0, 24)) == "t.webp: cannot decode the texture (a WebP file that ends inside its header)");
}
