#include "bench/convergence.h"

#include <cmath>

#include "util/error.h"

namespace strata {
namespace {

bool positiveFinite(double v) { return std::isfinite(v) && v > 0.0; }

double logLerp(double x0, double y0, double x1, double y1, double at) {
    const double t = (std::log(at) - std::log(x0)) / (std::log(x1) - std::log(x0));
    return std::exp(std::log(y0) + t * (std::log(y1) - std::log(y0)));
}

}  // namespace

PowerLawFit fitPowerLaw(const std::vector<double>& x, const std::vector<double>& y) {
    if (x.size() != y.size() || x.size() < 2) throw Error("a power-law fit needs >= 2 (x, y) pairs");
    const double n = static_cast<double>(x.size());
    double sx = 0.0, sy = 0.0;
    for (size_t i = 0; i < x.size(); ++i) {
        if (!positiveFinite(x[i]) || !positiveFinite(y[i])) {
            throw Error("a power-law fit needs positive finite values");
        }
        sx += std::log(x[i]);
        sy += std::log(y[i]);
    }
    const double mx = sx / n, my = sy / n;
    double sxx = 0.0, sxy = 0.0;
    for (size_t i = 0; i < x.size(); ++i) {
        const double dx = std::log(x[i]) - mx;
        sxx += dx * dx;
        sxy += dx * (std::log(y[i]) - my);
    }
    if (!(sxx > 0.0)) throw Error("a power-law fit needs two distinct x values");
    PowerLawFit fit;
    fit.slope = sxy / sxx;
    const double intercept = my - fit.slope * mx;
    fit.constant = std::exp(intercept);
    if (x.size() > 2) {
        double residuals = 0.0;
        for (size_t i = 0; i < x.size(); ++i) {
            const double r = std::log(y[i]) - (intercept + fit.slope * std::log(x[i]));
            residuals += r * r;
        }
        fit.slopeStandardError = std::sqrt(residuals / (n - 2.0) / sxx);
    }
    return fit;
}

std::optional<double> interpolateLogLog(const std::vector<double>& x, const std::vector<double>& y,
                                        double at) {
    if (x.empty() || x.size() != y.size() || !(at >= x.front()) || !(at <= x.back())) {
        return std::nullopt;
    }
    for (size_t i = 1; i < x.size(); ++i) {
        if (at <= x[i]) return logLerp(x[i - 1], y[i - 1], x[i], y[i], at);
    }
    return y.front();  // a single point equal to `at`
}

std::optional<double> firstReach(const std::vector<double>& x, const std::vector<double>& error,
                                 double target) {
    if (x.empty() || x.size() != error.size()) return std::nullopt;
    if (error.front() <= target) return x.front();
    for (size_t i = 1; i < x.size(); ++i) {
        if (error[i] <= target) {
            // log error is linear in log x between the checkpoints: solve for the target.
            const double t = (std::log(target) - std::log(error[i - 1])) /
                             (std::log(error[i]) - std::log(error[i - 1]));
            return std::exp(std::log(x[i - 1]) + t * (std::log(x[i]) - std::log(x[i - 1])));
        }
    }
    return std::nullopt;
}

double varianceRatio(const std::vector<double>& mseA, const std::vector<double>& mseB) {
    if (mseA.empty() || mseA.size() != mseB.size()) {
        throw Error("a variance ratio needs the same checkpoints for both estimators");
    }
    double logSum = 0.0;
    for (size_t i = 0; i < mseA.size(); ++i) {
        if (!positiveFinite(mseA[i]) || !positiveFinite(mseB[i])) {
            throw Error("a variance ratio needs positive finite errors");
        }
        logSum += std::log(mseA[i] / mseB[i]);
    }
    return std::exp(logSum / static_cast<double>(mseA.size()));
}

double paperSection4Ratio(double samples) { return (samples - 1.0) / (23.0 * samples); }

}  // namespace strata
