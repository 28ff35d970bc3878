#pragma once
// A live log-log plot of the split view's noise: each side's error against spp or against its
// render seconds, drawn with ImGui's draw list inside the panel.
#include <string>
#include <vector>

#include "render_worker.h"

namespace strata::viewer {

enum class ErrorAxis { Spp, Seconds };

struct ErrorSeries {
    std::string label;
    unsigned int colour;  // ImU32
    const std::vector<ErrorSample>* samples;
};

// Takes the panel's full width and `height` pixels; shows "waiting for 2 passes" when empty.
void drawErrorPlot(const char* id, ErrorAxis axis, const std::vector<ErrorSeries>& series, float height);

}  // namespace strata::viewer
