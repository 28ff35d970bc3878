#include "sampling/piecewise_constant_2d.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace strata {
namespace {

std::vector<float> rowIntegrals(const std::vector<PiecewiseConstant1D>& rows) {
    std::vector<float> integrals;
    integrals.reserve(rows.size());
    for (const auto& row : rows) integrals.push_back(static_cast<float>(row.integral()));
    return integrals;
}

std::vector<PiecewiseConstant1D> conditionals(const std::vector<float>& values, int width, int height) {
    assert(width > 0 && height > 0 && values.size() == static_cast<size_t>(width) * height);
    std::vector<PiecewiseConstant1D> rows;
    rows.reserve(height);
    for (int y = 0; y < height; ++y) {
        const auto begin = values.begin() + static_cast<std::ptrdiff_t>(y) * width;
        rows.emplace_back(std::vector<float>(begin, begin + width));
    }
    return rows;
}

// The interval a point of [0,1] lies in, the far edge belonging to the last one.
int intervalOf(float x, size_t count) {
    const int i = static_cast<int>(x * static_cast<float>(count));
    return std::clamp(i, 0, static_cast<int>(count) - 1);
}

}  // namespace

PiecewiseConstant1D::PiecewiseConstant1D(const std::vector<float>& values)
    : cdf_(values.size() + 1, 0.0), pdf_(values.size()) {
    assert(!values.empty());
    const double n = static_cast<double>(values.size());
    for (size_t i = 0; i < values.size(); ++i) cdf_[i + 1] = cdf_[i] + values[i] / n;
    integral_ = cdf_.back();
    for (size_t i = 0; i < values.size(); ++i) {
        if (integral_ > 0.0) {
            cdf_[i + 1] /= integral_;
            pdf_[i] = static_cast<float>(values[i] / integral_);
        } else {
            cdf_[i + 1] = (i + 1) / n;
            pdf_[i] = 1.0f;
        }
    }
    cdf_.back() = 1.0;
}

PiecewiseConstant1D::Sample PiecewiseConstant1D::sample(float u) const {
    // The last interval whose cdf is <= u: intervals of zero mass are never chosen.
    const auto above = std::upper_bound(cdf_.begin(), cdf_.end(), static_cast<double>(u));
    const int i = std::clamp(static_cast<int>(above - cdf_.begin()) - 1, 0,
                             static_cast<int>(pdf_.size()) - 1);
    const double width = cdf_[i + 1] - cdf_[i];
    const double offset = width > 0.0 ? (u - cdf_[i]) / width : 0.0;
    // Rounding may carry x to the cell's far edge, and thus into the next cell: keep it inside.
    const double n = static_cast<double>(pdf_.size());
    const float x = std::min(static_cast<float>((i + offset) / n),
                             std::nextafter(static_cast<float>((i + 1) / n), 0.0f));
    return {x, pdf_[i], i};
}

PiecewiseConstant2D::PiecewiseConstant2D(const std::vector<float>& values, int width, int height)
    : rows_(conditionals(values, width, height)), marginal_(rowIntegrals(rows_)) {}

PiecewiseConstant2D::Sample PiecewiseConstant2D::sample(glm::vec2 u) const {
    const PiecewiseConstant1D::Sample y = marginal_.sample(u.y);
    const PiecewiseConstant1D::Sample x = rows_[y.interval].sample(u.x);
    return {{x.x, y.x}, x.pdf * y.pdf};
}

glm::ivec2 PiecewiseConstant2D::cellOf(glm::vec2 point) const {
    const int y = intervalOf(point.y, rows_.size());
    return {intervalOf(point.x, rows_[y].size()), y};
}

}  // namespace strata
