#pragma once
// A live log-log plot of the split view's noise: each side's error against spp or against its
// render seconds, drawn with ImGui's draw list inside the panel. A side's history grows by a
// point a pass up to a bound (render_worker.h); the plot spans all of it and draws a thinned copy.
#include <cstddef>
#include <string>
#include <vector>
#include <imgui.h>

#include "render_worker.h"

namespace strata::viewer {

enum class ErrorAxis { Spp, Seconds };

struct ErrorSeries {
    std::string label;
    unsigned int colour;  // ImU32
    const std::vector<ErrorSample>* samples;
};

// The indices of the points of `samples` that a plot `columns` pixels wide draws, in history
// order: of those it can place (x by `axis` and error both > 0), the first and the last, and in
// each of `columns` equal steps of log10 x the lowest and the highest error. At most
// 2 * columns + 2 of them however long the history, so that drawing costs the same after an
// hour as after a minute while the curve keeps its whole span and its extremes.
std::vector<size_t> thinForDrawing(const std::vector<ErrorSample>& samples, ErrorAxis axis, int columns);

// An axis of whole decades, 10^min to 10^max (max > min), labelled "1eK".
struct DecadeRange {
    int min = 0;
    int max = 1;
};

struct PlotLabel {
    std::string text;
    ImVec2 min, max;  // where it is drawn, screen pixels
};

// Where the plot in the rectangle at `origin` of `size` puts its frame and its decade labels,
// measured with the current ImGui font: the margins are the labels' own size, so that every label
// lies inside the rectangle, the y labels left of the frame and the x labels under it; a label
// that would overlap the one before it on its axis is left out.
struct ErrorPlotLayout {
    ImVec2 frameMin, frameMax;
    std::vector<PlotLabel> xLabels, yLabels;
};
ErrorPlotLayout layoutErrorPlot(ImVec2 origin, ImVec2 size, DecadeRange x, DecadeRange y);

// Takes the panel's full width and `height` pixels; shows "waiting for 2 passes" when empty.
void drawErrorPlot(const char* id, ErrorAxis axis, const std::vector<ErrorSeries>& series, float height);

}  // namespace strata::viewer
