#include <doctest/doctest.h>

#include <fstream>
#include <set>
#include <unistd.h>
#include <tbb/info.h>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfThreading.h>

#include "film/accumulation_buffer.h"
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

TEST_CASE("image io: an EXR whose data window lies anywhere, negative or far out, reads as its pixels") {
    // OpenEXR addresses pixels by absolute coordinates; a window away from (0, 0) must still land
    // every pixel in place, with no pointer taken outside the image (the sanitized build checks).
    const auto dir = test::scratchDir("exr-window");
    const Image image = gradient();
    for (const Imath::V2i& origin : {Imath::V2i(-7, -1000000000), Imath::V2i(1 << 29, 3)}) {
        const Imath::Box2i window(origin, origin + Imath::V2i(image.width - 1, image.height - 1));
        Imf::Header header(window, window);
        for (const char* channel : {"R", "G", "B"}) header.channels().insert(channel, Imf::Channel(Imf::FLOAT));
        {
            std::vector<float> planes[3];
            for (const glm::vec3& pixel : image.pixels) {
                for (int c = 0; c < 3; ++c) planes[c].push_back(pixel[c]);
            }
            Imf::FrameBuffer frame;
            const char* names[3] = {"R", "G", "B"};
            for (int c = 0; c < 3; ++c) {
                frame.insert(names[c], Imf::Slice::Make(Imf::FLOAT, planes[c].data(), window, sizeof(float),
                                                        sizeof(float) * image.width));
            }
            Imf::OutputFile out((dir / "window.exr").c_str(), header);
            out.setFrameBuffer(frame);
            out.writePixels(image.height);
        }
        const Image back = readExr(dir / "window.exr");
        CHECK(back.width == image.width);
        CHECK(back.height == image.height);
        CHECK(back.pixels == image.pixels);
    }
}

TEST_CASE("image io: an image's alpha goes to the EXR's A channel and back, a render's is its coverage") {
    const auto dir = test::scratchDir("exr-alpha");
    Image image = gradient();
    for (int i = 0; i < 15; ++i) image.alpha.push_back(static_cast<float>(i) / 14.0f);
    writeImage(dir / "a.exr", image);
    const Image back = readExr(dir / "a.exr");
    CHECK(back.pixels == image.pixels);
    CHECK(back.alpha == image.alpha);
    CHECK(readExr(dir / "a.exr").alpha.size() == 15);
    writeImage(dir / "opaque.exr", gradient());
    CHECK(readExr(dir / "opaque.exr").alpha.empty());
    AccumulationBuffer buffer(2, 1);
    buffer.addSample(0, glm::vec3(1.0f), true);
    buffer.addSample(0, glm::vec3(0.5f), false);
    buffer.addSample(1, glm::vec3(0.5f), false);
    const Image means = buffer.meanImage();
    CHECK(means.alpha == std::vector<float>{0.5f, 0.0f});
    CHECK(means.pixels[0] == glm::vec3(0.75f));
}

TEST_CASE("image io: an EXR written and read on several threads is the same, byte for byte") {
    const auto dir = test::scratchDir("exr-threads");
    // 100 rows: seven of the 16-row blocks that ZIP compresses apart, the last one short.
    Image image{64, 100, {}};
    for (int i = 0; i < image.width * image.height; ++i) {
        const auto u = static_cast<float>((i * 2654435761u) >> 8) * 0x1p-24f;
        image.pixels.emplace_back(u, 1.0f - u, 100.0f * u * u);
        image.alpha.push_back(static_cast<float>(i % 7) / 6.0f);
    }
    const auto bytesOf = [](const std::filesystem::path& path) {
        std::ifstream in(path, std::ios::binary);
        return std::string(std::istreambuf_iterator<char>(in), {});
    };
    setExrThreads(1);
    CHECK(Imf::globalThreadCount() == 0);  // the caller's thread alone
    writeImage(dir / "one.exr", image);
    setExrThreads(4);
    CHECK(Imf::globalThreadCount() == 4);
    writeImage(dir / "four.exr", image);
    const Image back = readExr(dir / "one.exr");
    const int cores = tbb::info::default_concurrency();
    setExrThreads(0);
    CHECK(Imf::globalThreadCount() == (cores > 1 ? cores : 0));
    setExrThreads(1);
    CHECK(bytesOf(dir / "one.exr") == bytesOf(dir / "four.exr"));
    CHECK(back.pixels == image.pixels);
    CHECK(back.alpha == image.alpha);
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

TEST_CASE("image io: images and screenshots never write through a symlink planted at a temporary name") {
    const auto dir = test::scratchDir("image-symlinks");
    std::ofstream(dir / "victim") << "precious";
    const std::string pid = std::to_string(getpid());
    for (const char* name : {"a.exr", "a.pfm", "a.png", "shot.png"}) {
        // The names a writer in this process would try first, then the first free one.
        for (const std::string& suffix : {".tmp-" + pid, ".tmp" + pid, ".tmp-" + pid + "-0", ".tmp-" + pid + "-1"}) {
            std::filesystem::create_symlink(dir / "victim", dir / (name + suffix));
        }
    }
    writeImage(dir / "a.exr", gradient());
    writeImage(dir / "a.pfm", gradient());
    writeImage(dir / "a.png", gradient());
    writeRgb8Png(dir / "shot.png", 2, 1, {255, 0, 0, 0, 255, 0});
    CHECK(test::fileBytes(dir / "victim") == "precious");
    CHECK(readExr(dir / "a.exr").pixels == gradient().pixels);
    for (const char* name : {"a.pfm", "a.png", "shot.png"}) CHECK(std::filesystem::file_size(dir / name) > 8);
}

TEST_CASE("image io: the format comes from the extension in any letter case") {
    CHECK(imageFormatOf("a.EXR") == ImageFormat::Exr);
    CHECK(imageFormatOf("a.Pfm") == ImageFormat::Pfm);
    CHECK(imageFormatOf("dir.png/a.PNG") == ImageFormat::Png);
    CHECK_THROWS_WITH_AS(imageFormatOf("a.png.bmp"), "a.png.bmp: unknown image format (use .exr, .pfm or .png)", Error);
    CHECK_THROWS_WITH_AS(imageFormatOf("png"), "png: unknown image format (use .exr, .pfm or .png)", Error);
    const auto dir = test::scratchDir("image-case");
    writeImage(dir / "a.EXR", gradient());
    CHECK(readExr(dir / "a.EXR").pixels == gradient().pixels);
    writeRgb8Png(dir / "shot.PNG", 1, 1, {1, 2, 3});
    CHECK(test::fileBytes(dir / "shot.PNG").substr(1, 3) == "PNG");
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
    // The default display is the filmic curve: it rolls off the highlights the clamp cuts, and
    // reaches 1 only near x = 7.24.
    CHECK(kDefaultTonemap == Tonemap::Aces);
    CHECK(applyTonemap(glm::vec3(2.0f), 0.0f, Tonemap::Aces).x < applyTonemap(glm::vec3(4.0f), 0.0f, Tonemap::Aces).x);
    CHECK(applyTonemap(glm::vec3(4.0f), 0.0f, Tonemap::Aces).x < 1.0f);
    CHECK(applyTonemap(glm::vec3(7.3f), 0.0f, Tonemap::Aces).x == 1.0f);
    CHECK(applyTonemap(glm::vec3(0.18f), 0.0f, Tonemap::Aces).x == doctest::Approx(0.2669f).epsilon(1e-3));
    CHECK_FALSE(parseTonemap("filmic").has_value());
}
