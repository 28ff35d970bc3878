#include "io/auto_exposure.h"

#include <algorithm>
#include <cmath>

#include "util/luminance.h"

namespace strata {

float autoExposure(const Image& image) {
    double logSum = 0.0;
    double weight = 0.0;
    for (int y0 = 0; y0 < image.height; y0 += kExposureBlock) {
        for (int x0 = 0; x0 < image.width; x0 += kExposureBlock) {
            double sum = 0.0;
            int pixels = 0;
            for (int y = y0; y < std::min(y0 + kExposureBlock, image.height); ++y) {
                for (int x = x0; x < std::min(x0 + kExposureBlock, image.width); ++x) {
                    sum += luminance(glm::dvec3(image.pixels[static_cast<size_t>(y) * image.width + x]));
                    ++pixels;
                }
            }
            const double mean = sum / pixels;
            if (!(mean > 0.0 && std::isfinite(mean))) continue;
            logSum += pixels * std::log(mean);
            weight += pixels;
        }
    }
    if (weight == 0.0) return 0.0f;
    const double stops = std::log2(kExposureKey) - logSum / weight / std::log(2.0);
    return std::clamp(static_cast<float>(stops), -kExposureLimit, kExposureLimit);
}

}  // namespace strata
