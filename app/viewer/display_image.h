#pragma once
// What the display shader needs of one accumulation buffer, as float arrays ready for texture
// upload (no OpenGL here): per pixel the mean linear RGB and the sample count, and the relative
// standard error of the mean luminance. Built on the render worker, shown on the UI thread.
#include <cstddef>
#include <cstdint>
#include <vector>

namespace strata {
class AccumulationBuffer;
}

namespace strata::viewer {

struct DisplayImage {
    int width = 0;
    int height = 0;
    std::vector<float> meanAndCount;   // 4 floats per pixel, top row first: R, G, B, samples
    std::vector<float> relativeError;  // 1 float per pixel: standard error / mean luminance

    // `stratified`: estimate the error from per-pass means (strata24), else from per-sample variance.
    static DisplayImage fromBuffer(const AccumulationBuffer& buffer, bool stratified);
};

// The standard error of the mean luminance of one pixel with the estimator that fits the sampler:
// per-pass means for strata24 (its 24 paths in a pass are not independent), per-sample variance for
// i.i.d. sampling.
double pixelStandardError(const AccumulationBuffer& buffer, size_t pixel, bool stratified);

}  // namespace strata::viewer
