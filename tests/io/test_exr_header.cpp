// EXR headers checked against their files (io/exr_header.h): a data window whose chunks the file
// does not hold is refused before anything is allocated for it.
#include <doctest/doctest.h>

#include "image_support.h"
#include "io/exr_header.h"
#include "io/image_io.h"
#include "test_support.h"
#include "util/error.h"

using namespace strata;

TEST_CASE("exr header: the size of a written file, scanline and every chunk in place") {
    const auto dir = test::scratchDir("exr-header");
    writeImage(dir / "a.exr", Image{40, 3, std::vector<glm::vec3>(120, glm::vec3(0.5f))});
    const TextureSize size = readExrHeader(test::fileBytes(dir / "a.exr"), "a.exr");
    CHECK(size.width == 40);
    CHECK(size.height == 3);
    CHECK(size.bytes() == 40 * 3 * 12);
}

TEST_CASE("exr header: 23170 x 11585 pixels claimed by 93 KB without pixel data are refused unallocated") {
    const std::string forged = test::forgedExr(23170, 11585);
    CHECK(forged.size() == 92993);
    const std::string expected = "big.exr: not a readable EXR file (23170 x 11585 pixels, but chunk 1 of 11585 of "
                                 "their data lies outside the file's 92993 bytes: truncated or corrupt)";
    CHECK_THROWS_WITH_AS(readExrHeader(forged, "big.exr"), expected.c_str(), Error);
    // readExr allocated the 3 GB of floats before OpenEXR found the first chunk missing.
    const long before = test::peakRssKilobytes();
    CHECK_THROWS_WITH_AS(readExr(forged, "big.exr"), expected.c_str(), Error);
    if (!test::kSanitizedBuild) CHECK(test::peakRssKilobytes() - before < 64 * 1024);
    // A real file cut anywhere past its header is refused the same way.
    const auto dir = test::scratchDir("exr-cut");
    writeImage(dir / "a.exr", Image{64, 64, std::vector<glm::vec3>(64 * 64, glm::vec3(0.25f))});
    const std::string bytes = test::fileBytes(dir / "a.exr");
    CHECK_THROWS_WITH_AS(readExrHeader(bytes.substr(0, bytes.size() - 10), "cut.exr"),
                         doctest::Contains("cut.exr: not a readable EXR file (64 x 64 pixels, but chunk"), Error);
}

TEST_CASE("exr header: bytes that are no EXR are refused naming the file") {
    CHECK_THROWS_WITH_AS(readExrHeader("not an exr at all", "x.exr"),
                         doctest::Contains("x.exr: not a readable EXR file ("), Error);
    CHECK_THROWS_WITH_AS(readExrHeader("", "empty.exr"), doctest::Contains("empty.exr: not a readable EXR file ("),
                         Error);
}
