#pragma once
// Reading `strata bench --vs-cycles`: the table of Strata's and Cycles' images against one
// reference (relMSE, seconds, relMSE x seconds and each against Cycles'), the error-against-time
// plot, and the spp at which a Strata run takes as long as a Cycles render.
#include <string>
#include <vector>
#include <glm/vec3.hpp>

#include "bench/bench_output.h"

namespace strata {

inline constexpr const char* kCyclesRenderer = "Cycles";

// One image: one renderer's settings at one budget.
struct CyclesRow {
    std::string renderer;  // kCyclesRenderer, or the Strata settings it ran with
    std::string match;     // how the budget was set against Cycles': "same spp", "equal time", ...
    int cyclesSpp = 0;     // the Cycles render it is set against (its own spp for Cycles)
    int spp = 0;
    double relMse = 0.0;   // against the reference (film/image_metrics.h)
    double seconds = 0.0;  // Strata: the whole process; Cycles: bpy.ops.render.render() alone
    glm::dvec3 meanOverReference{1.0};  // each channel's mean over the reference's
};

// Every row with relMSE x seconds and its ratios to the Cycles row of the same cyclesSpp (none
// for rows without one). Cells are formatted; the caller writes CSV or markdown.
Table cyclesComparisonTable(const std::vector<CyclesRow>& rows);

// A (spp, seconds) measurement of one renderer's settings.
struct TimedSpp {
    int spp = 0;
    double seconds = 0.0;
};
// The spp, a positive multiple of `step`, at which the line through two measurements (start-up
// plus a cost per sample) reaches `target` seconds; proportional to the larger measurement when
// the two do not give a rising line. At least `step`.
int equalTimeSpp(TimedSpp a, TimedSpp b, double target, int step);

// One curve of the plot: a CSV with columns "seconds" and "relmse", titled `title`.
struct PlotSeries {
    std::string title;
    std::string csv;
};
// The gnuplot script drawing relMSE against seconds, log-log, one line with points per series
// and the key below the axes, into `png` (file names relative to the folder gnuplot runs in).
std::string cyclesPlotScript(const std::vector<PlotSeries>& series, const std::string& png,
                             const std::string& title);
// The rows of each renderer, one point per spp in order of seconds: the plot's data, as CSV
// text beside each series' title (the file names are the caller's).
std::vector<std::pair<std::string, std::string>> cyclesPlotData(const std::vector<CyclesRow>& rows);

}  // namespace strata
