// The split view's noise plots without OpenGL: a history of thousands of passes is drawn from a
// bounded number of points that keep its span and its extremes, and the axis labels, measured
// with ImGui's own font, fit inside the plot beside its frame.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <imgui.h>

#include "app/viewer/headless_imgui.h"
#include "error_plot.h"

using namespace strata;
using namespace strata::viewer;

namespace {

// Inside a frame, as the panel measures its labels; nothing is drawn.
struct ImGuiFrame {
    test::HeadlessImGui context{ImVec2(1280, 720)};
    ImGuiFrame() { ImGui::NewFrame(); }
    ~ImGuiFrame() { ImGui::EndFrame(); }
};

bool inside(const PlotLabel& label, ImVec2 origin, ImVec2 size) {
    return label.min.x >= origin.x && label.min.y >= origin.y && label.max.x <= origin.x + size.x &&
           label.max.y <= origin.y + size.y;
}

bool overlap(const PlotLabel& a, const PlotLabel& b) {
    return a.min.x < b.max.x && b.min.x < a.max.x && a.min.y < b.max.y && b.min.y < a.max.y;
}

}  // namespace

TEST_CASE("error plot: thousands of passes are drawn from a bounded set that keeps the span and the extremes") {
    // A pass every 24 spp from the second on, error falling as 1/sqrt(spp), with one spike and one
    // dip far from the ends.
    std::vector<ErrorSample> history;
    for (int pass = 2; pass <= 6001; ++pass) {
        const double spp = 24.0 * pass;
        history.push_back({spp, 0.01 * pass, 1.0 / std::sqrt(spp)});
    }
    history[3000].error = 10.0;
    history[4500].error = 1e-6;
    constexpr int kColumns = 300;
    for (ErrorAxis axis : {ErrorAxis::Spp, ErrorAxis::Seconds}) {
        const std::vector<size_t> drawn = thinForDrawing(history, axis, kColumns);
        CHECK(drawn.size() <= 2 * kColumns + 2);
        CHECK(drawn.size() > kColumns / 2);  // thinned, not reduced to a few points
        REQUIRE(!drawn.empty());
        CHECK(drawn.front() == 0);
        CHECK(drawn.back() == history.size() - 1);
        CHECK(std::is_sorted(drawn.begin(), drawn.end()));
        CHECK(std::adjacent_find(drawn.begin(), drawn.end()) == drawn.end());
        CHECK(std::count(drawn.begin(), drawn.end(), 3000) == 1);
        CHECK(std::count(drawn.begin(), drawn.end(), 4500) == 1);
    }
    // A short history is drawn whole, and points the log axes cannot place are left out.
    std::vector<ErrorSample> young(history.begin(), history.begin() + 10);
    young[4].error = 0.0;
    const std::vector<size_t> drawn = thinForDrawing(young, ErrorAxis::Spp, kColumns);
    CHECK(drawn == std::vector<size_t>{0, 1, 2, 3, 5, 6, 7, 8, 9});
}

TEST_CASE("error plot: every axis label fits inside the plot, beside its frame, overlapping no other") {
    const ImGuiFrame frame;
    const ImVec2 origin(8, 400), size(364, 100);  // the panel's plot
    struct Axes {
        DecadeRange x, y;
    };
    // One decade; the viewer's usual spans; exponents of two digits and a sign (the widest
    // labels); and more decades than the plot has room to label.
    for (const Axes& axes : {Axes{{1, 2}, {-3, -2}}, Axes{{1, 4}, {-3, -1}}, Axes{{-2, 3}, {-12, -9}},
                             Axes{{-20, 20}, {-30, 10}}}) {
        CAPTURE(axes.x.min);
        CAPTURE(axes.y.min);
        const ErrorPlotLayout layout = layoutErrorPlot(origin, size, axes.x, axes.y);
        CHECK(layout.frameMin.x > origin.x);
        CHECK(layout.frameMax.x <= origin.x + size.x);
        CHECK(layout.frameMax.y < origin.y + size.y);
        REQUIRE(layout.xLabels.size() >= 2);
        REQUIRE(layout.yLabels.size() >= 2);
        // The ends are always labelled when there is room for them.
        CHECK(layout.xLabels.front().text == "1e" + std::to_string(axes.x.min));
        CHECK(layout.yLabels.front().text == "1e" + std::to_string(axes.y.min));
        for (const PlotLabel& label : layout.xLabels) {
            CAPTURE(label.text);
            CHECK(inside(label, origin, size));
            CHECK(label.min.y >= layout.frameMax.y);  // under the frame
            CHECK(label.max.x - label.min.x == doctest::Approx(ImGui::CalcTextSize(label.text.c_str()).x));
        }
        for (const PlotLabel& label : layout.yLabels) {
            CAPTURE(label.text);
            CHECK(inside(label, origin, size));
            CHECK(label.max.x <= layout.frameMin.x);  // left of the frame
            CHECK(label.max.x - label.min.x == doctest::Approx(ImGui::CalcTextSize(label.text.c_str()).x));
        }
        std::vector<PlotLabel> all = layout.xLabels;
        all.insert(all.end(), layout.yLabels.begin(), layout.yLabels.end());
        for (size_t i = 0; i < all.size(); ++i) {
            for (size_t j = i + 1; j < all.size(); ++j) {
                CAPTURE(all[i].text);
                CAPTURE(all[j].text);
                CHECK_FALSE(overlap(all[i], all[j]));
            }
        }
    }
}
