// Bilinear lookups with repeat wrap (textures/texture.h): exact at texel centres, the linear blend
// between them, across the wrapped edge, and the v-up convention.
#include <doctest/doctest.h>

#include <vector>

#include "textures/texture.h"
#include "util/error.h"

using namespace strata;

namespace {
// 2 x 2, one channel: top row 0, 1; bottom row 2, 3.
Texture twoByTwo() { return Texture(2, 2, 1, {0.0f, 1.0f, 2.0f, 3.0f}); }
}  // namespace

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
