#pragma once
// Error of a rendered image against a reference, per colour channel of every pixel:
//   MSE    = mean (x - ref)^2,                RMSE = sqrt(MSE);
//   relMSE = mean (x - ref)^2 / (ref^2 + 0.01)   (the usual relative MSE: the 0.01 keeps black
//            reference pixels from dominating; issue 5);
//   efficiency = 1 / (relMSE * seconds): higher is better, independent of the budget for an
//            estimator whose relMSE falls as 1/time.
// Non-finite rendered values make the result non-finite (they are an error to report, not skip).
#include <glm/vec3.hpp>

#include "io/image_io.h"

namespace strata {

inline constexpr double kRelMseEpsilon = 0.01;

struct ImageError {
    double mse = 0.0;
    double rmse = 0.0;
    double relMse = 0.0;
};

// Throws strata::Error when the sizes differ.
ImageError compareImages(const Image& image, const Image& reference);
// Against a reference that is the same radiance in every pixel (an analytic scene).
ImageError compareToConstant(const Image& image, const glm::vec3& reference);

double efficiency(double relMse, double seconds);

}  // namespace strata
