#include <doctest/doctest.h>

#include <fstream>
#include <set>

#include "util/error.h"
#include "io/image_io.h"
#include "test_support.h"

using namespace strata;

namespace {
Image gradient() {
    Image image{5, 3, {}};
    for (int i = 0; i < 15; ++i) image.pixels.emplace_back(i * 0.25f, 1e-3f * i, 1000.0f + i);
    return image;
}
}  // namespace

TEST_CASE("image io: EXR round trip is exact in float") {
    const auto dir = test::scratchDir("exr");
    const Image image = gradient();
    writeImage(dir / "a.exr", image);
    const Image back = readExr(dir / "a.exr");
    REQUIRE(back.width == 5);
    REQUIRE(back.height == 3);
    CHECK(back.pixels == image.pixels);
    // Only the file itself is left: no temporary beside it.
    CHECK(std::distance(std::filesystem::directory_iterator(dir), {}) == 1);
}

TEST_CASE("image io: PFM holds little-endian floats, bottom row first") {
    const auto dir = test::scratchDir("pfm");
    writeImage(dir / "a.pfm", gradient());
    std::ifstream in(dir / "a.pfm", std::ios::binary);
    std::string magic, scale;
    int w, h;
    in >> magic >> w >> h >> scale;
    in.get();
    CHECK(magic == "PF");
    CHECK(scale == "-1.0");
    float first[3];
    in.read(reinterpret_cast<char*>(first), sizeof first);
    CHECK(first[0] == 10 * 0.25f);  // pixel (0, 2): index 10
}

TEST_CASE("image io: PNG is written, and bad formats and bad files are one-line errors") {
    const auto dir = test::scratchDir("png");
    writeImage(dir / "a.png", gradient(), {1.0f, Tonemap::Aces});
    CHECK(std::filesystem::file_size(dir / "a.png") > 0);
    CHECK_THROWS_WITH_AS(writeImage(dir / "a.bmp", gradient()), doctest::Contains("unknown image format"), Error);
    CHECK_THROWS_WITH_AS(writeImage(dir / "missing-dir" / "a.exr", gradient()),
                         doctest::Contains("cannot write"), Error);
    std::ofstream(dir / "fake.exr") << "not an exr";
    CHECK_THROWS_WITH_AS(readExr(dir / "fake.exr"), doctest::Contains("fake.exr: not a readable EXR"), Error);
    CHECK_THROWS_WITH_AS(readExr(dir / "absent.exr"), doctest::Contains("absent.exr: no such"), Error);
}

TEST_CASE("image io: a failed write leaves an existing file untouched") {
    const auto dir = test::scratchDir("atomic");
    std::ofstream(dir / "keep.png") << "previous contents";
    Image broken{4, 4, {}};  // no pixels: the encoder reads nothing valid
    broken.pixels.resize(16);
    // Make the write fail after the temporary is created: a directory where the target goes.
    std::filesystem::create_directory(dir / "target.exr");
    CHECK_THROWS_AS(writeImage(dir / "target.exr", broken), Error);
    CHECK(std::filesystem::is_directory(dir / "target.exr"));
    std::ifstream in(dir / "keep.png");
    std::string contents;
    std::getline(in, contents);
    CHECK(contents == "previous contents");
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        CHECK(entry.path().filename().string().find(".tmp-") == std::string::npos);
    }
}

TEST_CASE("image io: an image's size must fit 2^28 pixels and its file's bytes") {
    CHECK_NOTHROW(requirePlausibleImageSize(16384, 16384, 1 << 20, "big.exr"));
    CHECK_NOTHROW(requirePlausibleImageSize(8256, 1, 1, "dense.png"));
    CHECK_THROWS_WITH_AS(requirePlausibleImageSize(8257, 1, 1, "dense.png"),
                         "dense.png: a 8257 x 1 image cannot be stored in 1 bytes (truncated or corrupt)", Error);
    CHECK_THROWS_WITH_AS(requirePlausibleImageSize(16385, 16384, size_t{1} << 40, "huge.exr"),
                         "huge.exr: unreasonable image size 16385 x 16384", Error);
    CHECK_THROWS_WITH_AS(requirePlausibleImageSize(0, 5, 100, "empty.exr"), "empty.exr: unreasonable image size 0 x 5",
                         Error);
    CHECK_THROWS_AS(requirePlausibleImageSize(-4, -4, 100, "negative.exr"), Error);
}

TEST_CASE("image io: io knows files and images, not the film: its includes go to io, textures and util only") {
    // The film develops into an io Image (AccumulationBuffer::meanImage); io reads and writes
    // images for film, lights and textures alike, so it may include none of them but textures.
    CHECK(test::includedFolders("io") == std::set<std::string>{"io", "textures", "util"});
}

TEST_CASE("tonemap: sRGB encoding and curves at known points") {
    CHECK(encodeSrgb(0.0f) == 0.0f);
    CHECK(encodeSrgb(1.0f) == doctest::Approx(1.0f));
    CHECK(encodeSrgb(0.0031308f) == doctest::Approx(0.0404492f));
    CHECK(toByte(encodeSrgb(0.5f)) == 188);
    CHECK(applyTonemap(glm::vec3(1.0f), 0.0f, Tonemap::Reinhard).x == doctest::Approx(0.5f));
    CHECK(applyTonemap(glm::vec3(0.25f), 1.0f, Tonemap::Clamp).x == doctest::Approx(0.5f));
    CHECK(applyTonemap(glm::vec3(-1.0f), 0.0f, Tonemap::Aces).x == 0.0f);
    CHECK(parseTonemap("aces") == Tonemap::Aces);
    CHECK_FALSE(parseTonemap("filmic").has_value());
}
