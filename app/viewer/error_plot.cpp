#include "error_plot.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <imgui.h>

namespace strata::viewer {
namespace {

double xOf(const ErrorSample& s, ErrorAxis axis) { return axis == ErrorAxis::Spp ? s.spp : s.seconds; }

struct Range {
    double min = std::numeric_limits<double>::infinity();
    double max = -std::numeric_limits<double>::infinity();
    void add(double v) {
        min = std::min(min, v);
        max = std::max(max, v);
    }
    // Whole decades around the data, at least one decade wide.
    void roundToDecades() {
        min = std::floor(min);
        max = std::max(std::ceil(max), min + 1.0);
    }
};

}  // namespace

void drawErrorPlot(const char* id, ErrorAxis axis, const std::vector<ErrorSeries>& series, float height) {
    const ImVec2 size(ImGui::GetContentRegionAvail().x, height);
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    ImGui::InvisibleButton(id, size);
    ImDrawList* draw = ImGui::GetWindowDrawList();
    draw->AddRectFilled(origin, ImVec2(origin.x + size.x, origin.y + size.y), IM_COL32(20, 20, 24, 255));

    Range xs, ys;
    for (const auto& s : series) {
        for (const auto& sample : *s.samples) {
            if (xOf(sample, axis) > 0.0 && sample.error > 0.0) {
                xs.add(std::log10(xOf(sample, axis)));
                ys.add(std::log10(sample.error));
            }
        }
    }
    const char* xName = axis == ErrorAxis::Spp ? "spp" : "seconds";
    if (!std::isfinite(xs.min)) {
        draw->AddText(ImVec2(origin.x + 6, origin.y + 6), IM_COL32(180, 180, 180, 255),
                      "error vs ... waiting for 2 passes");
        return;
    }
    xs.roundToDecades();
    ys.roundToDecades();
    const float left = origin.x + 34.0f, right = origin.x + size.x - 6.0f;
    const float top = origin.y + 6.0f, bottom = origin.y + size.y - 18.0f;
    auto toScreen = [&](double lx, double ly) {
        return ImVec2(left + static_cast<float>((lx - xs.min) / (xs.max - xs.min)) * (right - left),
                      bottom - static_cast<float>((ly - ys.min) / (ys.max - ys.min)) * (bottom - top));
    };
    // Decade grid with labels 10^k.
    const ImU32 grid = IM_COL32(70, 70, 80, 255), text = IM_COL32(170, 170, 170, 255);
    char label[32];
    for (double d = xs.min; d <= xs.max + 0.5; d += 1.0) {
        const ImVec2 p = toScreen(d, ys.min);
        draw->AddLine(ImVec2(p.x, top), ImVec2(p.x, bottom), grid);
        std::snprintf(label, sizeof label, "1e%d", static_cast<int>(d));
        draw->AddText(ImVec2(p.x - 8.0f, bottom + 2.0f), text, label);
    }
    for (double d = ys.min; d <= ys.max + 0.5; d += 1.0) {
        const ImVec2 p = toScreen(xs.min, d);
        draw->AddLine(ImVec2(left, p.y), ImVec2(right, p.y), grid);
        std::snprintf(label, sizeof label, "1e%d", static_cast<int>(d));
        draw->AddText(ImVec2(origin.x + 2.0f, p.y - 7.0f), text, label);
    }
    draw->AddText(ImVec2(right - 50.0f, bottom - 16.0f), text, xName);
    float legendY = top;
    for (const auto& s : series) {
        std::vector<ImVec2> points;
        for (const auto& sample : *s.samples) {
            if (xOf(sample, axis) > 0.0 && sample.error > 0.0) {
                points.push_back(toScreen(std::log10(xOf(sample, axis)), std::log10(sample.error)));
            }
        }
        draw->AddPolyline(points.data(), static_cast<int>(points.size()), s.colour, 0, 2.0f);
        for (const auto& p : points) draw->AddCircleFilled(p, 2.0f, s.colour);
        draw->AddText(ImVec2(right - 110.0f, legendY), s.colour, s.label.c_str());
        legendY += 14.0f;
    }
}

}  // namespace strata::viewer
