// JPEG textures through libjpeg (io/jpeg_image.h): decoded at 8 bits, a header claiming more
// pixels than a Huffman-coded file can hold refused before decoding, and a truncated file
// decoded with one warning naming it, whether or not it still ends in an end-of-image marker.
#include <doctest/doctest.h>

#include <cstdlib>
#include <string>
#include <vector>

#include "image_support.h"
#include "io/jpeg_image.h"
#include "io/texture_image.h"
#include "util/error.h"

using namespace strata;

namespace {
// A smooth 64 x 64 RGB gradient, which JPEG codes closely.
std::vector<unsigned char> gradientPixels() {
    std::vector<unsigned char> pixels;
    for (int y = 0; y < 64; ++y) {
        for (int x = 0; x < 64; ++x) {
            pixels.insert(pixels.end(), {static_cast<unsigned char>(4 * x), static_cast<unsigned char>(4 * y), 128});
        }
    }
    return pixels;
}
}  // namespace

TEST_CASE("jpeg: colour and grey decode at 8 bits, close to what was coded") {
    const std::vector<unsigned char> source = gradientPixels();
    std::vector<std::string> warnings;
    const Texture colour =
        decodeTexture(test::jpegFile(64, 64, 3, source), "g.jpg", TextureEncoding::Data, warnings);
    CHECK(warnings.empty());
    CHECK(colour.size().bytes() == 64 * 64 * 3);
    for (const auto& [x, y] : {std::pair{5, 7}, {40, 20}, {63, 63}}) {
        const glm::vec4 t = colour.texel(x, y);
        CHECK(std::abs(t.x * 255.0f - 4.0f * x) < 6.0f);
        CHECK(std::abs(t.y * 255.0f - 4.0f * y) < 6.0f);
        CHECK(std::abs(t.z * 255.0f - 128.0f) < 6.0f);
    }
    const std::vector<unsigned char> grey(32 * 16, 200);
    const std::string greyJpeg = test::jpegFile(32, 16, 1, grey);
    CHECK(readJpegHeader(greyJpeg, "grey.jpg").channels == 1);
    const Texture g = decodeTexture(greyJpeg, "grey.jpg", TextureEncoding::Data, warnings);
    CHECK(std::abs(g.texel(10, 10).x * 255.0f - 200.0f) < 2.0f);
    CHECK(warnings.empty());
}

TEST_CASE("jpeg: a 40 KB file claiming 16384 x 16384 pixels is refused before decoding") {
    // A Huffman-coded JPEG spends a bit at least on each 8 x 8 block: 16384^2 pixels need 512 KB.
    // stb_image decoded the fuzzer's file into 3.9 GB of float texels in 98 s, silently.
    const std::string forged = test::forgedJpeg(16384, 16384, 40960);
    CHECK_THROWS_WITH_AS(readJpegHeader(forged, "big.jpg"),
                         "big.jpg: a 16384 x 16384 image cannot be stored in 40960 bytes (truncated or corrupt)", Error);
    CHECK(readJpegHeader(test::forgedJpeg(1024, 1024, 40960), "ok.jpg").bytes() == 1024 * 1024 * 3);
    CHECK_THROWS_WITH_AS(readJpegHeader(std::string("\xff\xd8\xff\xe0", 4), "cut.jpg"),
                         doctest::Contains("cut.jpg: cannot decode the texture ("), Error);
}

TEST_CASE("jpeg: a truncated file decodes, grey where its data is missing, with a warning naming it") {
    // Cut halfway into the coded data of its first scan: a baseline file's lower half is missing.
    const auto cutInScan = [](const std::string& jpeg) {
        const size_t scan = jpeg.find("\xff\xda");
        REQUIRE(scan != std::string::npos);
        return jpeg.substr(0, (scan + jpeg.size()) / 2);
    };
    const std::string cut = cutInScan(test::jpegFile(64, 64, 3, gradientPixels()));
    // Cut and closed with an end-of-image marker (which stb_image decoded without a word), and cut.
    for (const std::string& bytes : {cut + "\xff\xd9", cut}) {
        std::vector<std::string> warnings;
        const Texture t = decodeTexture(bytes, "cut.jpg", TextureEncoding::Data, warnings);
        REQUIRE(warnings.size() == 1);
        CHECK(warnings[0].rfind("cut.jpg: damaged or truncated JPEG (libjpeg: ", 0) == 0);
        CHECK(std::abs(t.texel(5, 2).x * 255.0f - 20.0f) < 6.0f);  // decoded before the cut
        const glm::vec4 missing = t.texel(60, 63);
        CHECK(std::abs(missing.x * 255.0f - 128.0f) < 2.0f);
        CHECK(std::abs(missing.y * 255.0f - 128.0f) < 2.0f);
    }
    // A progressive file cut in its first scan (of DC coefficients, some tens of bytes) likewise.
    const std::string progressive = test::jpegFile(64, 64, 3, gradientPixels(), true);
    std::vector<std::string> warnings;
    const std::string firstScan = progressive.substr(0, progressive.find("\xff\xda") + 30);
    decodeTexture(firstScan, "cut.jpg", TextureEncoding::Data, warnings);
    CHECK(warnings.size() == 1);
}
