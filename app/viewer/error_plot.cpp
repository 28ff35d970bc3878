#include "error_plot.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace strata::viewer {
namespace {

// Space between a label and what it labels, and around the plot's rectangle.
constexpr float kPad = 3.0f;
// Up to this many points, each is marked with a dot: a young history shows its passes.
constexpr size_t kMarkedPoints = 32;

double xOf(const ErrorSample& s, ErrorAxis axis) { return axis == ErrorAxis::Spp ? s.spp : s.seconds; }

bool placeable(const ErrorSample& s, ErrorAxis axis) { return xOf(s, axis) > 0.0 && s.error > 0.0; }

std::string decadeLabel(int exponent) { return "1e" + std::to_string(exponent); }

struct Range {
    double min = std::numeric_limits<double>::infinity();
    double max = -std::numeric_limits<double>::infinity();
    void add(double v) {
        min = std::min(min, v);
        max = std::max(max, v);
    }
    // Whole decades around the data, at least one decade wide.
    DecadeRange decades() const {
        const int low = static_cast<int>(std::floor(min));
        return {low, std::max(static_cast<int>(std::ceil(max)), low + 1)};
    }
};

}  // namespace

std::vector<size_t> thinForDrawing(const std::vector<ErrorSample>& samples, ErrorAxis axis, int columns) {
    std::vector<size_t> placed;
    Range logX;
    for (size_t i = 0; i < samples.size(); ++i) {
        if (!placeable(samples[i], axis)) continue;
        placed.push_back(i);
        logX.add(std::log10(xOf(samples[i], axis)));
    }
    columns = std::max(columns, 1);
    if (placed.size() <= 2 * static_cast<size_t>(columns) + 2) return placed;
    // x never decreases along a history (spp, render seconds), so each column is one run of it.
    std::vector<size_t> kept{placed.front()};
    int column = -1;
    size_t lowest = 0, highest = 0;
    const auto flush = [&] {
        if (column < 0) return;
        kept.push_back(std::min(lowest, highest));
        if (lowest != highest) kept.push_back(std::max(lowest, highest));
    };
    const double span = std::max(logX.max - logX.min, 1e-300);
    for (size_t k = 1; k + 1 < placed.size(); ++k) {
        const size_t i = placed[k];
        const double t = (std::log10(xOf(samples[i], axis)) - logX.min) / span;
        const int c = std::clamp(static_cast<int>(t * columns), 0, columns - 1);
        if (c != column) {
            flush();
            column = c;
            lowest = highest = i;
        } else {
            if (samples[i].error < samples[lowest].error) lowest = i;
            if (samples[i].error > samples[highest].error) highest = i;
        }
    }
    flush();
    kept.push_back(placed.back());
    return kept;
}

ErrorPlotLayout layoutErrorPlot(ImVec2 origin, ImVec2 size, DecadeRange x, DecadeRange y) {
    const float lineHeight = ImGui::GetTextLineHeight();
    float yLabelWidth = 0.0f;
    for (int k = y.min; k <= y.max; ++k) {
        yLabelWidth = std::max(yLabelWidth, ImGui::CalcTextSize(decadeLabel(k).c_str()).x);
    }
    ErrorPlotLayout layout;
    // Room for the widest y label on the left, half a line above the top one (centred on its
    // tick) and a line under the frame for the x labels.
    layout.frameMin = ImVec2(origin.x + yLabelWidth + 2.0f * kPad, origin.y + 0.5f * lineHeight + kPad);
    layout.frameMax = ImVec2(origin.x + size.x - kPad, origin.y + size.y - lineHeight - 2.0f * kPad);
    const float right = origin.x + size.x, bottom = origin.y + size.y;

    // Under its tick, centred where the rectangle allows: the first starts at the frame's left
    // edge (left of it are the y labels), the last ends at the rectangle's right edge.
    float lastRight = -std::numeric_limits<float>::infinity();
    for (int k = x.min; k <= x.max; ++k) {
        const std::string text = decadeLabel(k);
        const float width = ImGui::CalcTextSize(text.c_str()).x;
        const float along = static_cast<float>(k - x.min) / static_cast<float>(x.max - x.min);
        const float tick = layout.frameMin.x + along * (layout.frameMax.x - layout.frameMin.x);
        const float left =
            std::clamp(tick - 0.5f * width, layout.frameMin.x, std::max(layout.frameMin.x, right - width));
        if (left < lastRight + kPad) continue;
        const float top = layout.frameMax.y + kPad;
        layout.xLabels.push_back({text, ImVec2(left, top), ImVec2(left + width, top + lineHeight)});
        lastRight = left + width;
    }
    // Left of the frame, right-aligned, centred on its tick where the rectangle allows; from the
    // bottom up.
    float lastTop = std::numeric_limits<float>::infinity();
    for (int k = y.min; k <= y.max; ++k) {
        const std::string text = decadeLabel(k);
        const float width = ImGui::CalcTextSize(text.c_str()).x;
        const float along = static_cast<float>(k - y.min) / static_cast<float>(y.max - y.min);
        const float tick = layout.frameMax.y - along * (layout.frameMax.y - layout.frameMin.y);
        const float top =
            std::clamp(tick - 0.5f * lineHeight, origin.y, std::max(origin.y, bottom - lineHeight));
        if (top + lineHeight > lastTop) continue;
        const float labelRight = layout.frameMin.x - kPad;
        layout.yLabels.push_back(
            {text, ImVec2(labelRight - width, top), ImVec2(labelRight, top + lineHeight)});
        lastTop = top;
    }
    return layout;
}

void drawErrorPlot(const char* id, ErrorAxis axis, const std::vector<ErrorSeries>& series, float height) {
    const ImVec2 size(ImGui::GetContentRegionAvail().x, height);
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    ImGui::InvisibleButton(id, size);
    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->AddRectFilled(origin, ImVec2(origin.x + size.x, origin.y + size.y), IM_COL32(20, 20, 24, 255));

    Range xs, ys;
    for (const auto& s : series) {
        for (const auto& sample : *s.samples) {
            if (!placeable(sample, axis)) continue;
            xs.add(std::log10(xOf(sample, axis)));
            ys.add(std::log10(sample.error));
        }
    }
    const ImU32 text = IM_COL32(170, 170, 170, 255);
    if (!std::isfinite(xs.min)) {
        draw->AddText(ImVec2(origin.x + 6, origin.y + 6), text, "error vs ... waiting for 2 passes");
        return;
    }
    const DecadeRange xDecades = xs.decades(), yDecades = ys.decades();
    const ErrorPlotLayout layout = layoutErrorPlot(origin, size, xDecades, yDecades);
    const ImVec2 lo = layout.frameMin, hi = layout.frameMax;
    const auto toScreen = [&](double lx, double ly) {
        return ImVec2(
            lo.x + static_cast<float>((lx - xDecades.min) / (xDecades.max - xDecades.min)) * (hi.x - lo.x),
            hi.y - static_cast<float>((ly - yDecades.min) / (yDecades.max - yDecades.min)) * (hi.y - lo.y));
    };
    const ImU32 grid = IM_COL32(70, 70, 80, 255);
    for (int k = xDecades.min; k <= xDecades.max; ++k) {
        const float x = toScreen(k, yDecades.min).x;
        draw->AddLine(ImVec2(x, lo.y), ImVec2(x, hi.y), grid);
    }
    for (int k = yDecades.min; k <= yDecades.max; ++k) {
        const float y = toScreen(xDecades.min, k).y;
        draw->AddLine(ImVec2(lo.x, y), ImVec2(hi.x, y), grid);
    }
    for (const auto* labels : {&layout.xLabels, &layout.yLabels}) {
        for (const PlotLabel& label : *labels) draw->AddText(label.min, text, label.text.c_str());
    }
    const float lineHeight = ImGui::GetTextLineHeight();
    const char* xName = axis == ErrorAxis::Spp ? "spp" : "seconds";
    draw->AddText(ImVec2(hi.x - ImGui::CalcTextSize(xName).x - kPad, hi.y - lineHeight - kPad), text, xName);

    const int columns = std::max(1, static_cast<int>(hi.x - lo.x));
    float legendY = lo.y + kPad;
    std::vector<ImVec2> points;
    for (const auto& s : series) {
        points.clear();
        for (size_t i : thinForDrawing(*s.samples, axis, columns)) {
            const ErrorSample& sample = (*s.samples)[i];
            points.push_back(toScreen(std::log10(xOf(sample, axis)), std::log10(sample.error)));
        }
        draw->AddPolyline(points.data(), static_cast<int>(points.size()), s.colour, 0, 2.0f);
        if (points.size() <= kMarkedPoints) {
            for (const auto& p : points) draw->AddCircleFilled(p, 2.0f, s.colour);
        }
        draw->AddText(ImVec2(hi.x - ImGui::CalcTextSize(s.label.c_str()).x - kPad, legendY), s.colour,
                      s.label.c_str());
        legendY += lineHeight;
    }
}

}  // namespace strata::viewer
