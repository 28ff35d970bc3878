#pragma once
// A piecewise-constant density on [0,1)^2 proportional to a grid of non-negative values, sampled
// by inversion: the marginal over rows picks a row, that row's conditional picks a column, and
// the point is uniform inside its cell (pbrt-v4's PiecewiseConstant2D). An environment map
// weights its texels by luminance times sin(theta) this way (lights/environment_map_light.h).
#include <vector>
#include <glm/vec2.hpp>
#include <glm/ext/vector_int2.hpp>

namespace strata {

// A piecewise-constant density on [0,1) over `values.size()` equal intervals.
class PiecewiseConstant1D {
public:
    // `values` >= 0 and not empty; all zero gives the uniform density.
    explicit PiecewiseConstant1D(const std::vector<float>& values);

    struct Sample {
        float x;         // in [0,1)
        float pdf;       // density of x
        int interval;    // which of the intervals x lies in
    };
    // `u` uniform in [0,1).
    Sample sample(float u) const;
    float pdf(int interval) const { return pdf_[interval]; }
    size_t size() const { return pdf_.size(); }
    // The mean of the values (the integral of the step function over [0,1)).
    double integral() const { return integral_; }

private:
    std::vector<double> cdf_;  // cdf_[i] = mass of intervals before i; size() + 1 entries, last 1
    std::vector<float> pdf_;
    double integral_;
};

class PiecewiseConstant2D {
public:
    // `values` row-major, `width` x `height` of them (row 0 at y in [0, 1/height)); each >= 0.
    PiecewiseConstant2D(const std::vector<float>& values, int width, int height);

    struct Sample {
        glm::vec2 point;  // (x, y) in [0,1)^2
        float pdf;        // density of the point on the unit square
    };
    // `u` uniform in [0,1)^2: u.y picks the row, u.x the column.
    Sample sample(glm::vec2 u) const;
    // The cell (column, row) that `point` in [0,1]^2 lies in; points on the far edges belong to
    // the last column or row.
    glm::ivec2 cellOf(glm::vec2 point) const;
    // The density in a cell, and at a point.
    float pdf(glm::ivec2 cell) const { return marginal_.pdf(cell.y) * rows_[cell.y].pdf(cell.x); }
    float pdf(glm::vec2 point) const { return pdf(cellOf(point)); }

private:
    std::vector<PiecewiseConstant1D> rows_;  // the conditional density of x in each row
    PiecewiseConstant1D marginal_;           // of y: each row's integral
};

}  // namespace strata
