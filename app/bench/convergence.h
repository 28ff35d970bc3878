#pragma once
// Reading convergence curves (error against samples or seconds), as `strata bench` does:
// power-law fits in log-log space, interpolation between checkpoints, and the variance ratio of
// two estimators at equal sample count, beside the paper's claims for it.
#include <optional>
#include <vector>

namespace strata {

// y ~= constant * x^slope, fitted by least squares on (log x, log y). slopeStandardError is the
// usual OLS standard error of the slope (0 for two points or an exact power law).
struct PowerLawFit {
    double slope = 0.0;
    double constant = 0.0;
    double slopeStandardError = 0.0;
};
// Throws strata::Error unless there are >= 2 points, all x and y positive and finite, and two
// distinct x.
PowerLawFit fitPowerLaw(const std::vector<double>& x, const std::vector<double>& y);

// y at `x` on the polyline through (x_i, y_i) drawn in log-log space (x strictly increasing);
// nullopt outside [x_0, x_last].
std::optional<double> interpolateLogLog(const std::vector<double>& x, const std::vector<double>& y,
                                        double at);

// The first time a falling error curve reaches `target`: the log-log interpolated x between the
// last checkpoint above the target and the first at or below it; x_0 if it starts below; nullopt
// if it never gets there.
std::optional<double> firstReach(const std::vector<double>& x, const std::vector<double>& error,
                                 double target);

// Geometric mean of mseA_i / mseB_i over checkpoints taken at equal sample counts: for unbiased
// estimators MSE is variance, so this is Var(A) / Var(B) (the geometric mean keeps one noisy
// checkpoint from dominating). Throws strata::Error for empty or unequal inputs.
double varianceRatio(const std::vector<double>& mseA, const std::vector<double>& mseB);

// The paper's claims for Var(strata24) / Var(uniform) at N samples:
//   section 3: Var xi*_N = Var xi_N / 24, and section 4: (N - 1) / (23 N) (notes section 4).
inline constexpr double kPaperSection3Ratio = 1.0 / 24.0;
double paperSection4Ratio(double samples);

}  // namespace strata
