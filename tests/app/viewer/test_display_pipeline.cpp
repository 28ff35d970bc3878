// The display shader (shaders/display.frag through DisplayPipeline) against the CPU references it
// mirrors: renderer/io/tonemap.h for the colour view, app/viewer/false_colour.h for the error and
// sample-count views; and the split view's composition. Runs in an OSMesa context (no display).
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <vector>

#include "display_pipeline.h"
#include "false_colour.h"
#include "frame_target.h"
#include "offscreen_context.h"
#include "io/tonemap.h"

using namespace strata;
using namespace strata::viewer;

namespace {

DisplayImage makeImage(int width, int height) {
    DisplayImage image;
    image.width = width;
    image.height = height;
    image.meanAndCount.assign(4 * static_cast<size_t>(width) * height, 0.0f);
    image.errorAndDone.assign(2 * static_cast<size_t>(width) * height, 0.0f);
    return image;
}

void setPixel(DisplayImage& image, size_t pixel, glm::vec3 mean, float samples, float error = 0.0f,
              bool done = false) {
    image.meanAndCount[4 * pixel + 0] = mean.x;
    image.meanAndCount[4 * pixel + 1] = mean.y;
    image.meanAndCount[4 * pixel + 2] = mean.z;
    image.meanAndCount[4 * pixel + 3] = samples;
    image.errorAndDone[2 * pixel + 0] = error;
    image.errorAndDone[2 * pixel + 1] = done ? 1.0f : 0.0f;
}

// Draws `settings` over the whole target and returns its RGB bytes, top row first.
std::vector<uint8_t> display(DisplayPipeline& pipeline, const DisplaySettings& settings, int width, int height) {
    FrameTarget target = FrameTarget::offscreen(width, height);
    target.bind();
    pipeline.draw(settings, Viewport{0, 0, width, height});
    return target.readRgb();
}

uint8_t byteOf(float value) { return static_cast<uint8_t>(std::lround(std::clamp(value, 0.0f, 1.0f) * 255.0f)); }

}  // namespace

TEST_CASE("display shader matches the CPU tonemap within 1/255") {
    const auto context = OffscreenContext::create(OffscreenBackend::OsMesa);
    DisplayPipeline pipeline;
    constexpr int kWidth = 32, kHeight = 6;
    DisplayImage image = makeImage(kWidth, kHeight);
    std::vector<glm::vec3> expected(kWidth * kHeight);
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            const size_t p = static_cast<size_t>(y) * kWidth + x;
            const float t = static_cast<float>(x) / (kWidth - 1);
            glm::vec3 value;
            switch (y) {
                case 0: value = glm::vec3(t, 0.5f * t, 2.0f * t); break;                 // gradient over [0, 2]
                case 1: value = glm::vec3(std::pow(10.0f, 6.0f * t - 4.0f)); break;     // 1e-4 .. 1e2
                case 2: value = glm::vec3(0.18f, 0.5f, 0.9f); break;                    // a constant
                case 3: value = glm::vec3(1e6f, 3e9f, 1e15f); break;                    // huge values
                case 4: value = glm::vec3(-1.0f, 0.25f, -5.0f); break;                  // negatives clamp to 0
                default: value = glm::vec3(0.7f); break;                                 // no samples
            }
            setPixel(image, p, y == 5 ? glm::vec3(0.0f) : value, y == 5 ? 0.0f : 24.0f);
            expected[p] = y == 5 ? glm::vec3(0.0f) : value;
        }
    }
    pipeline.upload(0, image, DisplayView::Colour);
    for (Tonemap tonemap : {Tonemap::Clamp, Tonemap::Reinhard, Tonemap::Aces}) {
        for (float exposure : {0.0f, -1.5f, 2.0f}) {
            CAPTURE(tonemapName(tonemap));
            CAPTURE(exposure);
            DisplaySettings settings;
            settings.tonemap = tonemap;
            settings.exposure = exposure;
            const auto pixels = display(pipeline, settings, kWidth, kHeight);
            int worst = 0;
            for (size_t p = 0; p < expected.size(); ++p) {
                const glm::vec3 mapped = applyTonemap(expected[p], exposure, tonemap);
                for (int c = 0; c < 3; ++c) {
                    worst = std::max(worst, std::abs(int(pixels[3 * p + c]) - int(toByte(encodeSrgb(mapped[c])))));
                }
            }
            CHECK(worst <= 1);
        }
    }
}

TEST_CASE("split view shows each side on its side of the divider") {
    const auto context = OffscreenContext::create(OffscreenBackend::OsMesa);
    DisplayPipeline pipeline;
    constexpr int kWidth = 40, kHeight = 4;
    DisplayImage left = makeImage(kWidth, kHeight), right = makeImage(kWidth, kHeight);
    for (size_t p = 0; p < static_cast<size_t>(kWidth) * kHeight; ++p) {
        setPixel(left, p, glm::vec3(1.0f, 0.0f, 0.0f), 24.0f);
        setPixel(right, p, glm::vec3(0.0f, 0.0f, 1.0f), 24.0f);
    }
    pipeline.upload(0, left, DisplayView::Colour);
    pipeline.upload(1, right, DisplayView::Colour);
    for (float divider : {0.0f, 0.25f, 0.5f, 0.9f}) {
        CAPTURE(divider);
        DisplaySettings settings;
        settings.tonemap = Tonemap::Clamp;  // pure red and blue stay 255
        settings.split = true;
        settings.divider = divider;
        const auto pixels = display(pipeline, settings, kWidth, kHeight);
        for (int y = 0; y < kHeight; ++y) {
            for (int x = 0; x < kWidth; ++x) {
                CAPTURE(x);
                const size_t p = static_cast<size_t>(y) * kWidth + x;
                // A pixel belongs to the side its centre lies in.
                const bool onRight = (x + 0.5f) / kWidth >= divider;
                CHECK(int(pixels[3 * p + 0]) == (onRight ? 0 : 255));
                CHECK(int(pixels[3 * p + 2]) == (onRight ? 255 : 0));
            }
        }
    }
    // Without the split, side 0 fills the view.
    DisplaySettings single0;
    single0.tonemap = Tonemap::Clamp;
    const auto single = display(pipeline, single0, kWidth, kHeight);
    CHECK(int(single[3 * (kWidth - 1) + 0]) == 255);
}

TEST_CASE("error and sample-count views map known values to the false-colour ramp") {
    const auto context = OffscreenContext::create(OffscreenBackend::OsMesa);
    DisplayPipeline pipeline;
    constexpr int kWidth = 21, kHeight = 2;
    constexpr float kErrorScale = 0.2f, kSampleScale = 480.0f;
    DisplayImage image = makeImage(kWidth, kHeight);
    for (int x = 0; x < kWidth; ++x) {
        // t from -0.1 to 1.1: pixels with t <= 0 have no samples (grey in both views), those
        // above 1 clamp to the ramp's end.
        const float t = -0.1f + 1.2f * static_cast<float>(x) / (kWidth - 1);
        setPixel(image, static_cast<size_t>(x), glm::vec3(0.5f), std::max(0.0f, t) * kSampleScale, t * kErrorScale);
        setPixel(image, static_cast<size_t>(kWidth + x), glm::vec3(0.5f), x == 0 ? 0.0f : 24.0f, 0.1f);
    }
    // The known anchors of the ramp, independently of false_colour.cpp.
    CHECK(falseColour(0.0f).z == doctest::Approx(0.40f));
    CHECK(falseColour(0.5f).y == doctest::Approx(0.80f));
    CHECK(falseColour(1.0f).x == doctest::Approx(1.00f));
    CHECK(falseColour(0.125f).y == doctest::Approx(0.5f * (0.05f + 0.45f)));
    pipeline.upload(0, image, DisplayView::RelativeError);
    DisplaySettings settings;
    settings.errorScale = kErrorScale;
    settings.sampleScale = kSampleScale;
    for (DisplayView view : {DisplayView::RelativeError, DisplayView::SampleCount}) {
        CAPTURE(static_cast<int>(view));
        settings.view = view;
        const auto pixels = display(pipeline, settings, kWidth, kHeight);
        for (int x = 0; x < kWidth; ++x) {
            CAPTURE(x);
            const float t = -0.1f + 1.2f * static_cast<float>(x) / (kWidth - 1);
            const bool empty = t <= 0.0f;
            const glm::vec3 want = empty ? glm::vec3(kNoSamplesGrey) : falseColour(t);
            for (int c = 0; c < 3; ++c) CHECK(std::abs(int(pixels[3 * x + c]) - int(byteOf(want[c]))) <= 1);
        }
        // Second row: pixel 0 has no samples (grey), the others the ramp at 0.1 / scale.
        CHECK(int(pixels[3 * kWidth]) == int(byteOf(kNoSamplesGrey)));
    }
}

TEST_CASE("the adaptive-mask view washes done pixels green and leaves the others as displayed") {
    const auto context = OffscreenContext::create(OffscreenBackend::OsMesa);
    DisplayPipeline pipeline;
    constexpr int kWidth = 8, kHeight = 1;
    DisplayImage image = makeImage(kWidth, kHeight);
    for (int x = 0; x < kWidth; ++x) {
        setPixel(image, static_cast<size_t>(x), glm::vec3(0.1f * static_cast<float>(x)), 24.0f, 0.0f, x % 2 == 1);
    }
    pipeline.upload(0, image, DisplayView::AdaptiveMask);
    DisplaySettings settings;
    settings.view = DisplayView::AdaptiveMask;
    const auto pixels = display(pipeline, settings, kWidth, kHeight);
    for (int x = 0; x < kWidth; ++x) {
        CAPTURE(x);
        const glm::vec3 mapped = applyTonemap(glm::vec3(0.1f * static_cast<float>(x)), 0.0f, settings.tonemap);
        const glm::vec3 displayed(encodeSrgb(mapped.x), encodeSrgb(mapped.y), encodeSrgb(mapped.z));
        const glm::vec3 want = adaptiveMaskColour(displayed, x % 2 == 1);
        for (int c = 0; c < 3; ++c) CHECK(std::abs(int(pixels[3 * x + c]) - int(byteOf(want[c]))) <= 1);
    }
    // Done pixels are greener than their neighbours, whatever their colour.
    CHECK(int(pixels[3 * 1 + 1]) > int(pixels[3 * 1 + 0]));
    CHECK(adaptiveMaskColour(glm::vec3(1.0f), true).y > adaptiveMaskColour(glm::vec3(1.0f), true).x);
}
