#pragma once
// The progressive estimate of every pixel: sums in double and counts, so that 10^7 samples of a
// constant still average to it within 1e-9 and nothing drifts over 10^4 passes.
//
// Besides the running mean it keeps two error estimates per pixel (on luminance):
//   - per-sample variance: right for i.i.d. samples (the uniform sampler);
//   - the spread of per-pass means: right for strata24, whose 24 paths in a pass are not
//     independent (per-sample variance overstates a stratified estimator's error).
// A non-finite sample (NaN or Inf) is dropped and counted, never added.
//
// It also counts the samples whose camera ray found a surface, so that a pixel's coverage (the
// share of its camera rays that hit the scene: the EXR's alpha) is known apart from its colour.
//
// The error estimates take 40 of the buffer's 76 bytes a pixel and three stores per sample; a
// buffer whose owner only reads its image can leave them out (PixelErrors::NotKept) and hold the
// sums and counts alone, 36 bytes a pixel.
#include <array>
#include <cstdint>
#include <span>
#include <vector>
#include <glm/vec3.hpp>

#include "util/luminance.h"

namespace strata {

struct Image;

// Whether a buffer keeps the per-sample and per-pass error estimates (above).
enum class PixelErrors { Kept, NotKept };

class AccumulationBuffer {
public:
    AccumulationBuffer(int width, int height, PixelErrors errors = PixelErrors::Kept);

    // Not thread-safe for one pixel; distinct pixels may be written concurrently. `onSurface`:
    // the sample's camera ray found a surface.
    void addSample(size_t pixel, const glm::vec3& value, bool onSurface = true);
    // Closes the pixel's current pass (its samples since the last call) for the pass statistics.
    void completePass(size_t pixel);
    void clear();

    int width() const { return width_; }
    int height() const { return height_; }
    size_t pixelCount() const { return sampleCount_.size(); }

    // Whether the error estimates are kept (PixelErrors::Kept).
    bool keepsErrors() const { return !passCount_.empty(); }

    glm::dvec3 mean(size_t pixel) const;
    uint32_t sampleCount(size_t pixel) const { return sampleCount_[pixel]; }
    // The next three need the error estimates kept; without them they throw strata::Error.
    uint32_t completedPasses(size_t pixel) const;
    // Standard error of the pixel's mean luminance from the per-sample variance (i.i.d. view).
    double sampleStandardError(size_t pixel) const;
    // Standard error of the mean luminance from the spread of completed pass means; 0 with
    // fewer than 2 passes.
    double passStandardError(size_t pixel) const;
    // The share of the pixel's samples whose camera ray found a surface; 0 without samples.
    double coverage(size_t pixel) const;
    uint64_t droppedSamples() const;
    // Mean of all pixel means (linear RGB).
    glm::dvec3 imageMean() const;
    // Every pixel's mean as an image (io/image_io.h), as files and image metrics take it: the
    // film hands its estimate to io, which knows nothing of films.
    Image meanImage() const;

    // The buffer's whole state as flat arrays in a fixed order (the RGB sums as 3 doubles a pixel).
    // Every entry is a sum over samples or passes, so buffers of one image that saw disjoint passes
    // combine by element-wise addition: that is how the MPI ranks' buffers are reduced
    // (app/render_job.cpp). Counts add exactly; the doubles' sum depends on the order of
    // additions, by at most a few ulps relative for non-negative radiance (see render_job.cpp).
    // Without the error estimates their arrays are empty.
    std::array<std::span<double>, 5> realArrays();
    std::array<std::span<uint32_t>, 5> countArrays();

private:
    void requireErrors() const;  // throws unless they are kept

    int width_;
    int height_;
    std::vector<glm::dvec3> sum_;
    std::vector<double> luminanceSquares_;
    std::vector<uint32_t> sampleCount_;
    std::vector<uint32_t> surfaceSamples_;  // of those, the ones whose camera ray found a surface
    std::vector<uint32_t> dropped_;
    std::vector<double> openPassLuminance_;  // sum over the current pass's samples
    std::vector<uint32_t> openPassSamples_;
    std::vector<double> passMeanSum_;
    std::vector<double> passMeanSquares_;
    std::vector<uint32_t> passCount_;
};

}  // namespace strata
