#include "film/accumulation_buffer.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <glm/gtc/type_ptr.hpp>

#include "io/image_io.h"
#include "util/error.h"
#include "util/prefault.h"

namespace strata {

AccumulationBuffer::AccumulationBuffer(int width, int height, PixelErrors errors) : width_(width), height_(height) {
    if (width < 1 || height < 1) throw Error("image size must be at least 1x1");
    const size_t n = static_cast<size_t>(width) * static_cast<size_t>(height);
    resizePrefaulted(sum_, n);
    resizePrefaulted(sampleCount_, n);
    resizePrefaulted(surfaceSamples_, n);
    resizePrefaulted(dropped_, n);
    if (errors == PixelErrors::NotKept) return;
    resizePrefaulted(luminanceSquares_, n);
    resizePrefaulted(openPassLuminance_, n);
    resizePrefaulted(openPassSamples_, n);
    resizePrefaulted(passMeanSum_, n);
    resizePrefaulted(passMeanSquares_, n);
    resizePrefaulted(passCount_, n);
}

void AccumulationBuffer::addSample(size_t pixel, const glm::vec3& value, bool onSurface) {
    if (!std::isfinite(value.x) || !std::isfinite(value.y) || !std::isfinite(value.z)) {
        ++dropped_[pixel];
        return;
    }
    const glm::dvec3 v(value);
    sum_[pixel] += v;
    ++sampleCount_[pixel];
    if (onSurface) ++surfaceSamples_[pixel];
    if (!keepsErrors()) return;
    const double y = luminance(v);
    luminanceSquares_[pixel] += y * y;
    openPassLuminance_[pixel] += y;
    ++openPassSamples_[pixel];
}

void AccumulationBuffer::completePass(size_t pixel) {
    if (!keepsErrors() || openPassSamples_[pixel] == 0) return;
    const double passMean = openPassLuminance_[pixel] / openPassSamples_[pixel];
    passMeanSum_[pixel] += passMean;
    passMeanSquares_[pixel] += passMean * passMean;
    ++passCount_[pixel];
    openPassLuminance_[pixel] = 0.0;
    openPassSamples_[pixel] = 0;
}

void AccumulationBuffer::clear() {
    std::fill(sum_.begin(), sum_.end(), glm::dvec3(0.0));
    std::fill(luminanceSquares_.begin(), luminanceSquares_.end(), 0.0);
    std::fill(sampleCount_.begin(), sampleCount_.end(), 0u);
    std::fill(surfaceSamples_.begin(), surfaceSamples_.end(), 0u);
    std::fill(dropped_.begin(), dropped_.end(), 0u);
    std::fill(openPassLuminance_.begin(), openPassLuminance_.end(), 0.0);
    std::fill(openPassSamples_.begin(), openPassSamples_.end(), 0u);
    std::fill(passMeanSum_.begin(), passMeanSum_.end(), 0.0);
    std::fill(passMeanSquares_.begin(), passMeanSquares_.end(), 0.0);
    std::fill(passCount_.begin(), passCount_.end(), 0u);
}

glm::dvec3 AccumulationBuffer::mean(size_t pixel) const {
    const uint32_t n = sampleCount_[pixel];
    return n ? sum_[pixel] / static_cast<double>(n) : glm::dvec3(0.0);
}

double AccumulationBuffer::coverage(size_t pixel) const {
    const uint32_t n = sampleCount_[pixel];
    return n ? static_cast<double>(surfaceSamples_[pixel]) / n : 0.0;
}

namespace {
// Standard error of a mean of n values from their sum and sum of squares (unbiased variance).
double standardErrorOfMean(double sum, double squares, uint32_t n) {
    if (n < 2) return 0.0;
    const double mean = sum / n;
    const double variance = std::max(0.0, (squares - sum * mean) / (n - 1));
    return std::sqrt(variance / n);
}
}  // namespace

void AccumulationBuffer::requireErrors() const {
    if (!keepsErrors()) throw Error("the accumulation buffer keeps no error estimates");
}

uint32_t AccumulationBuffer::completedPasses(size_t pixel) const {
    requireErrors();
    return passCount_[pixel];
}

double AccumulationBuffer::sampleStandardError(size_t pixel) const {
    requireErrors();
    return standardErrorOfMean(luminance(sum_[pixel]), luminanceSquares_[pixel], sampleCount_[pixel]);
}

double AccumulationBuffer::passStandardError(size_t pixel) const {
    requireErrors();
    return standardErrorOfMean(passMeanSum_[pixel], passMeanSquares_[pixel], passCount_[pixel]);
}

uint64_t AccumulationBuffer::droppedSamples() const {
    return std::accumulate(dropped_.begin(), dropped_.end(), uint64_t{0});
}

glm::dvec3 AccumulationBuffer::imageMean() const {
    glm::dvec3 total(0.0);
    for (size_t i = 0; i < pixelCount(); ++i) total += mean(i);
    return total / static_cast<double>(pixelCount());
}

Image AccumulationBuffer::meanImage() const {
    Image image{width_, height_, {}};
    resizePrefaulted(image.pixels, pixelCount());
    resizePrefaulted(image.alpha, pixelCount());
    for (size_t i = 0; i < pixelCount(); ++i) {
        image.pixels[i] = glm::vec3(mean(i));
        image.alpha[i] = static_cast<float>(coverage(i));
    }
    return image;
}

std::array<std::span<double>, 5> AccumulationBuffer::realArrays() {
    static_assert(sizeof(glm::dvec3) == 3 * sizeof(double), "the RGB sums must be packed doubles");
    return {std::span<double>(glm::value_ptr(sum_[0]), 3 * sum_.size()), luminanceSquares_,
            openPassLuminance_, passMeanSum_, passMeanSquares_};
}

std::array<std::span<uint32_t>, 5> AccumulationBuffer::countArrays() {
    return {sampleCount_, surfaceSamples_, dropped_, openPassSamples_, passCount_};
}

}  // namespace strata
