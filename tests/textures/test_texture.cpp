// Bilinear lookups with repeat wrap (textures/texture.h): exact at texel centres, the linear blend
// between them, across the wrapped edge, and the v-up convention; 8-bit storage read as the floats
// of its decoded copy, bit for bit, in a quarter of the memory.
#include <doctest/doctest.h>

#include <cmath>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "test_support.h"
#include "textures/texture.h"
#include "util/error.h"

using namespace strata;

namespace {
// 2 x 2, one channel: top row 0, 1; bottom row 2, 3.
Texture twoByTwo() { return Texture(2, 2, 1, {0.0f, 1.0f, 2.0f, 3.0f}); }

double srgbCurve(int code) {
    const double c = code / 255.0;
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}
}  // namespace

TEST_CASE("the sRGB table is the exact curve") {
    const auto& table = srgbDecodingTable();
    for (int code : {0, 1, 10, 128, 255}) {
        CHECK(table[static_cast<size_t>(code)] == static_cast<float>(srgbCurve(code)));
    }
    CHECK(table[0] == 0.0f);
    CHECK(table[255] == 1.0f);
    CHECK(table[10] == static_cast<float>(10.0 / 255.0 / 12.92));  // the linear segment
}

TEST_CASE("an 8-bit texture reads, bit for bit, the floats its decoded copy holds, in a quarter of the memory") {
    // The copy as textures were decoded at load before they were kept at 8 bits: sRGB colour
    // channels through the table, alpha and data channels code / 255, then filtered.
    std::mt19937 random(3);
    for (const TextureEncoding encoding : {TextureEncoding::Colour, TextureEncoding::Data}) {
        for (int channels = 1; channels <= 4; ++channels) {
            CAPTURE(channels);
            const int width = 7, height = 5;
            std::vector<uint8_t> codes(static_cast<size_t>(width * height * channels));
            for (uint8_t& code : codes) code = static_cast<uint8_t>(random() & 0xff);
            const int colourChannels = channels == 1 || channels == 3 ? channels : channels - 1;
            std::vector<float> decoded(codes.size());
            for (size_t i = 0; i < codes.size(); ++i) {
                const auto channel = static_cast<int>(i % static_cast<size_t>(channels));
                const bool srgb = encoding == TextureEncoding::Colour && channel < colourChannels;
                decoded[i] = srgb ? srgbDecodingTable()[codes[i]] : static_cast<float>(codes[i]) / 255.0f;
            }
            const Texture floats(width, height, channels, decoded);
            const Texture bytes(width, height, channels, codes, encoding);
            CHECK(bytes.size().bytes() == codes.size());
            CHECK(floats.size().bytes() == 4 * codes.size());
            CHECK(bytes.mean() == floats.mean());
            CHECK(bytes.max() == floats.max());
            for (int y = 0; y < height; ++y) {
                for (int x = 0; x < width; ++x) CHECK(bytes.texel(x, y) == floats.texel(x, y));
            }
            std::uniform_real_distribution<float> uv(-2.0f, 3.0f);
            for (int i = 0; i < 200; ++i) {
                const glm::vec2 at(uv(random), uv(random));
                CHECK(bytes.lookup(at) == floats.lookup(at));
            }
        }
    }
    CHECK_THROWS_AS(Texture(2, 2, 1, std::vector<uint8_t>{1, 2, 3}, TextureEncoding::Data), Error);
}

TEST_CASE("texture lookups at texel centres return the texels, v up from the bottom row") {
    const Texture t = twoByTwo();
    CHECK(t.lookup({0.25f, 0.75f}).x == 0.0f);  // top left
    CHECK(t.lookup({0.75f, 0.75f}).x == 1.0f);  // top right
    CHECK(t.lookup({0.25f, 0.25f}).x == 2.0f);  // bottom left
    CHECK(t.lookup({0.75f, 0.25f}).x == 3.0f);  // bottom right
    // Grey reads as (g, g, g, 1).
    CHECK(t.lookup({0.75f, 0.25f}) == glm::vec4(3.0f, 3.0f, 3.0f, 1.0f));
}

TEST_CASE("texture lookups blend bilinearly and wrap across the edges") {
    const Texture t = twoByTwo();
    CHECK(t.lookup({0.5f, 0.75f}).x == doctest::Approx(0.5));   // halfway along the top row
    CHECK(t.lookup({0.5f, 0.5f}).x == doctest::Approx(1.5));    // the middle of all four
    // u = 0: halfway between the left column and, wrapped, the right one.
    CHECK(t.lookup({0.0f, 0.75f}).x == doctest::Approx(0.5));
    CHECK(t.lookup({1.0f, 0.75f}).x == doctest::Approx(0.5));
    // v = 1 (top edge) blends the top row with the bottom row wrapped over it.
    CHECK(t.lookup({0.25f, 1.0f}).x == doctest::Approx(1.0));
    // Whole periods away, the same values; negative coordinates too.
    CHECK(t.lookup({3.25f, -2.25f}).x == doctest::Approx(0.0));
    CHECK(t.lookup({-0.25f, 0.75f}).x == doctest::Approx(1.0));
    // A quarter of the way from the top-left centre to the top-right one.
    CHECK(t.lookup({0.375f, 0.75f}).x == doctest::Approx(0.25));
}

TEST_CASE("texture wrap modes: repeat tiles, clamp stretches the edge texels, mirror reflects every other tile") {
    // One row of two texels, 0 and 1, centres at u = 0.25 and 0.75.
    const Texture repeat(2, 1, 1, {0.0f, 1.0f});
    const Texture clamp = repeat.sampled({TextureWrap::ClampToEdge, TextureWrap::ClampToEdge, false});
    const Texture mirror = repeat.sampled({TextureWrap::MirroredRepeat, TextureWrap::MirroredRepeat, false});
    CHECK(clamp.sampling().u == TextureWrap::ClampToEdge);
    CHECK(repeat.sampling().u == TextureWrap::Repeat);  // the original keeps its own
    const auto at = [](const Texture& t, float u) { return t.lookup({u, 0.5f}).x; };
    // Inside, between the centres, all three blend alike.
    for (const Texture* t : {&repeat, &clamp, &mirror}) CHECK(at(*t, 0.5f) == doctest::Approx(0.5));
    // At u = 0 repeat blends with the far edge, clamp and mirror read the edge texel.
    CHECK(at(repeat, 0.0f) == doctest::Approx(0.5));
    CHECK(at(clamp, 0.0f) == 0.0f);
    CHECK(at(mirror, 0.0f) == 0.0f);
    // Past the image: repeat reads the next tile, clamp the edge, mirror the tile reflected.
    CHECK(at(repeat, 1.25f) == doctest::Approx(0.0));
    CHECK(at(clamp, 1.25f) == 1.0f);
    CHECK(at(clamp, -3.0f) == 0.0f);
    CHECK(at(clamp, 1e8f) == 1.0f);
    CHECK(at(mirror, 1.25f) == doctest::Approx(1.0));   // as u = 0.75
    CHECK(at(mirror, 1.625f) == doctest::Approx(0.25));  // as u = 0.375
    CHECK(at(mirror, -0.25f) == doctest::Approx(0.0));  // as u = 0.25
    CHECK(at(mirror, 2.25f) == doctest::Approx(0.0));   // a whole mirrored period on
    // v likewise, each axis its own: two rows, 0 at the top, 2 at the bottom.
    const Texture rows = Texture(1, 2, 1, {0.0f, 2.0f}).sampled({TextureWrap::Repeat, TextureWrap::ClampToEdge, false});
    CHECK(rows.lookup({5.3f, 1.5f}).x == 0.0f);
    CHECK(rows.lookup({-0.7f, -2.0f}).x == 2.0f);
    // The copies share the texels: statistics and sizes are the original's.
    CHECK(clamp.mean() == repeat.mean());
    CHECK(clamp.size().bytes() == repeat.size().bytes());
}

TEST_CASE("a nearest-texel texture reads the texel whose square holds uv, wrapped as its modes say") {
    const Texture t = twoByTwo().sampled({TextureWrap::Repeat, TextureWrap::ClampToEdge, true});
    // Top row 0, 1; bottom row 2, 3 (v up from the bottom row).
    CHECK(t.lookup({0.1f, 0.9f}).x == 0.0f);
    CHECK(t.lookup({0.49f, 0.51f}).x == 0.0f);
    CHECK(t.lookup({0.51f, 0.51f}).x == 1.0f);
    CHECK(t.lookup({0.5f, 0.5f}).x == 3.0f);  // a square's lower-left corner belongs to it
    CHECK(t.lookup({0.9f, 0.1f}).x == 3.0f);
    // u repeats, v clamps.
    CHECK(t.lookup({1.1f, 0.9f}).x == 0.0f);
    CHECK(t.lookup({-0.4f, 0.9f}).x == 1.0f);
    CHECK(t.lookup({0.1f, 7.0f}).x == 0.0f);
    CHECK(t.lookup({0.1f, -7.0f}).x == 2.0f);
}

TEST_CASE("texture statistics and channel layouts") {
    const Texture t = twoByTwo();
    CHECK(t.mean().x == doctest::Approx(1.5));
    CHECK(t.max().x == 3.0f);
    const Texture greyAlpha(1, 1, 2, {0.25f, 0.5f});
    CHECK(greyAlpha.lookup({0.5f, 0.5f}) == glm::vec4(0.25f, 0.25f, 0.25f, 0.5f));
    const Texture rgb(1, 1, 3, {0.1f, 0.2f, 0.3f});
    CHECK(rgb.lookup({0.5f, 0.5f}).w == 1.0f);
    // A non-finite UV reads a texel rather than an out-of-range index.
    CHECK(t.lookup({std::numeric_limits<float>::quiet_NaN(), 0.5f}).x == 0.0f);
    CHECK_THROWS_AS(Texture(2, 2, 1, {1.0f}), Error);
}

TEST_CASE("textures know texels, not files: their includes go to textures and util only") {
    // The decoders (io/texture_image.h) make textures and the budget counts them; a texture
    // knows neither, so io and scene build on textures and never the other way round.
    CHECK(test::includedFolders("textures") == std::set<std::string>{"textures", "util"});
}
