#pragma once
// The error of a rendered image against a reference: the one definition that the bench's curves
// and the viewer's against-reference curve both use, so the two give the same number for the
// same image. Over every colour channel c of every pixel i of N pixels (linear RGB, the image's
// float values, so a render is measured as it is written):
//   MSE    = 1/(3N) sum (x_ic - ref_ic)^2,               RMSE = sqrt(MSE);
//   relMSE = 1/(3N) sum (x_ic - ref_ic)^2 / (ref_ic^2 + 0.01)
//            (the usual relative MSE: the 0.01 keeps black reference pixels from dominating);
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
ImageError imageError(const Image& image, const Image& reference);
// Against a reference that is the same radiance in every pixel (an analytic scene).
ImageError imageError(const Image& image, const glm::vec3& reference);

double efficiency(double relMse, double seconds);

}  // namespace strata
