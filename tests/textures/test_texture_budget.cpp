// The scene's texture budget (textures/texture_budget.h): textures add up until one would cross
// the limit, which is refused in one line with its figures and the option that raises it.
#include <doctest/doctest.h>

#include "textures/texture_budget.h"
#include "util/error.h"

using namespace strata;

TEST_CASE("texture budget: sizes add up to the limit, and the one past it is refused with its figures") {
    constexpr uint64_t kGiB = uint64_t{1} << 30;
    TextureBudget budget(kDefaultTextureBudget);
    CHECK(budget.limit() == 4 * kGiB);
    const TextureSize huge{16384, 16384, 4, 1};
    CHECK(huge.bytes() == kGiB);
    for (int i = 0; i < 3; ++i) budget.reserve(huge, "texture");
    budget.reserve({8192, 4096, 3, 4}, "the map");  // 0.375 GiB of floats
    CHECK(budget.used() == 3 * kGiB + 3 * kGiB / 8);
    CHECK_THROWS_WITH_AS(budget.reserve(huge, "spider.mtl:12: map_Kd: texture 'huge.png'"),
                         "spider.mtl:12: map_Kd: texture 'huge.png' is 16384 x 16384, 4 channels of 8 bits (1.0 GiB); "
                         "with it the scene's textures would take 4.4 GiB, over the --texture-budget of 4.0 GiB",
                         Error);
    // Refused, it is not counted: a smaller one still fits.
    CHECK(budget.used() == 3 * kGiB + 3 * kGiB / 8);
    budget.reserve({8192, 8192, 4, 1}, "texture");
    CHECK(budget.used() == 3 * kGiB + 5 * kGiB / 8);
    // Exactly the limit fits.
    TextureBudget exact(48, 0);
    exact.reserve({4, 4, 3, 1}, "texture");
    CHECK(exact.used() == 48);
    CHECK_THROWS_WITH_AS(TextureBudget(kGiB / 2, kGiB / 2).reserve({1, 1, 1, 4}, "sky.exr: the environment map"),
                         "sky.exr: the environment map is 1 x 1, 1 channel of 32 bits (4 bytes); with it the scene's "
                         "textures would take 512.0 MiB, over the --texture-budget of 512.0 MiB",
                         Error);
}

TEST_CASE("texture budget: byte counts in the largest binary unit they fill") {
    CHECK(describeBytes(0) == "0 bytes");
    CHECK(describeBytes(1023) == "1023 bytes");
    CHECK(describeBytes(1024) == "1.0 KiB");
    CHECK(describeBytes(3 << 19) == "1.5 MiB");
    CHECK(describeBytes(uint64_t{4} << 30) == "4.0 GiB");
    CHECK(describeBytes(uint64_t{5} << 40) == "5.0 TiB");
}
