#pragma once
// What the display shader needs of one accumulation buffer, as float arrays ready for texture
// upload (no OpenGL here): per pixel the mean linear RGB and the sample count, the relative
// standard error of the mean luminance, and whether adaptive sampling has finished the pixel.
// Built on the render worker, shown on the UI thread.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "io/image_io.h"

namespace strata {
class AccumulationBuffer;
}

namespace strata::viewer {

struct DisplayImage {
    int width = 0;
    int height = 0;
    std::vector<float> meanAndCount;   // 4 floats per pixel, top row first: R, G, B, samples
    // 2 floats per pixel: standard error / mean luminance, and 1 if the pixel is done else 0.
    std::vector<float> errorAndDone;

    // `stratified`: estimate the error from per-pass means (strata24), else from per-sample
    // variance. `done`: adaptive sampling's mask (AdaptiveSampling::doneMask), if it is on.
    static DisplayImage fromBuffer(const AccumulationBuffer& buffer, bool stratified,
                                   const std::vector<uint8_t>* done = nullptr);
    // The mean radiance as an image (what the Files tab saves as EXR).
    Image radiance() const;
};

// The standard error of the mean luminance of one pixel with the estimator that fits the sampler:
// per-pass means for strata24 (its 24 paths in a pass are not independent), per-sample variance for
// i.i.d. sampling.
double pixelStandardError(const AccumulationBuffer& buffer, size_t pixel, bool stratified);

}  // namespace strata::viewer
