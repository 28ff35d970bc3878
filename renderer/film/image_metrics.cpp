#include "film/image_metrics.h"

#include <cmath>
#include <limits>
#include <string>

#include "util/error.h"

namespace strata {
namespace {

// Sums in double over every channel; `referenceAt(i)` gives pixel i's reference.
template <typename Reference>
ImageError accumulateError(const Image& image, Reference referenceAt) {
    double squares = 0.0;
    double relative = 0.0;
    for (size_t i = 0; i < image.pixels.size(); ++i) {
        const glm::vec3 ref = referenceAt(i);
        for (int c = 0; c < 3; ++c) {
            const double r = ref[c];
            const double d = static_cast<double>(image.pixels[i][c]) - r;
            squares += d * d;
            relative += d * d / (r * r + kRelMseEpsilon);
        }
    }
    const double n = 3.0 * static_cast<double>(image.pixels.size());
    ImageError error;
    error.mse = squares / n;
    error.rmse = std::sqrt(error.mse);
    error.relMse = relative / n;
    return error;
}

}  // namespace

ImageError imageError(const Image& image, const Image& reference) {
    if (image.width != reference.width || image.height != reference.height) {
        throw Error("reference image is " + std::to_string(reference.width) + "x" +
                    std::to_string(reference.height) + " but the render is " +
                    std::to_string(image.width) + "x" + std::to_string(image.height));
    }
    if (image.pixels.empty()) throw Error("cannot compare empty images");
    return accumulateError(image, [&](size_t i) { return reference.pixels[i]; });
}

ImageError imageError(const Image& image, const glm::vec3& reference) {
    if (image.pixels.empty()) throw Error("cannot compare an empty image");
    return accumulateError(image, [&](size_t) { return reference; });
}

double efficiency(double relMse, double seconds) {
    if (!(relMse > 0.0) || !(seconds > 0.0)) return std::numeric_limits<double>::infinity();
    return 1.0 / (relMse * seconds);
}

}  // namespace strata
