#include "bench/cycles_comparison.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace strata {

Table cyclesComparisonTable(const std::vector<CyclesRow>& rows) {
    Table table{{"renderer", "budget", "spp", "relMSE", "seconds", "relMSE x s", "relMSE / Cycles'",
                 "s / Cycles'", "relMSE x s / Cycles'", "mean R G B / reference"},
                {}};
    for (const CyclesRow& row : rows) {
        const auto cycles = std::find_if(rows.begin(), rows.end(), [&](const CyclesRow& r) {
            return r.renderer == kCyclesRenderer && r.cyclesSpp == row.cyclesSpp;
        });
        const CyclesRow* peer = cycles != rows.end() && &*cycles != &row ? &*cycles : nullptr;
        const auto ratio = [&](auto value) {
            return peer ? cell("%.3f", value(row) / value(*peer)) : std::string("-");
        };
        const auto relMse = [](const CyclesRow& r) { return r.relMse; };
        const auto seconds = [](const CyclesRow& r) { return r.seconds; };
        const auto cost = [](const CyclesRow& r) { return r.relMse * r.seconds; };
        table.add({row.renderer, row.match, std::to_string(row.spp), cell("%.4g", row.relMse),
                   cell("%.3f", row.seconds), cell("%.4g", cost(row)), ratio(relMse), ratio(seconds),
                   ratio(cost),
                   cell("%.4f %.4f %.4f", row.meanOverReference.x, row.meanOverReference.y,
                        row.meanOverReference.z)});
    }
    return table;
}

int equalTimeSpp(TimedSpp a, TimedSpp b, double target, int step) {
    if (a.spp > b.spp) std::swap(a, b);
    double spp = b.seconds > 0.0 ? b.spp * target / b.seconds : double(step);
    if (b.spp > a.spp && b.seconds > a.seconds) {
        const double perSample = (b.seconds - a.seconds) / (b.spp - a.spp);
        spp = a.spp + (target - a.seconds) / perSample;
    }
    const double steps = std::round(spp / step);
    return step * static_cast<int>(std::clamp(steps, 1.0, 1e6));
}

std::string cyclesPlotScript(const std::vector<PlotSeries>& series, const std::string& png,
                             const std::string& title) {
    // The key goes below the axes, a line per series, where no curve can run under it; the
    // picture grows by its lines.
    const int height = 400 + 16 * static_cast<int>(series.size());
    std::string script =
        "set terminal pngcairo noenhanced size 640," + std::to_string(height) + " font ',10'\n"
        "set output '" + png + "'\n"
        "set datafile separator ','\n"
        "set logscale xy\nset format y '%g'\nset grid\nset key outside below vertical Left reverse height 1\n"
        "set xlabel 'seconds (Strata: whole process; Cycles: render() alone)'\n"
        "set ylabel 'relMSE against the reference'\n"
        "set title '" + title + "'\n"
        "plot ";
    for (size_t i = 0; i < series.size(); ++i) {
        script += (i ? ", " : "") + std::string("'") + series[i].csv +
                  "' using 'seconds':'relmse' with linespoints lw 2 title '" + series[i].title + "'";
    }
    return script + "\n";
}

std::vector<std::pair<std::string, std::string>> cyclesPlotData(const std::vector<CyclesRow>& rows) {
    std::vector<std::string> order;  // renderers as they first appear
    std::map<std::string, std::map<int, const CyclesRow*>> points;
    for (const CyclesRow& row : rows) {
        if (!points.count(row.renderer)) order.push_back(row.renderer);
        points[row.renderer].emplace(row.spp, &row);
    }
    std::vector<std::pair<std::string, std::string>> data;
    for (const std::string& renderer : order) {
        std::vector<const CyclesRow*> sorted;
        for (const auto& [spp, row] : points[renderer]) sorted.push_back(row);
        std::sort(sorted.begin(), sorted.end(),
                  [](const CyclesRow* x, const CyclesRow* y) { return x->seconds < y->seconds; });
        Table table{{"spp", "seconds", "relmse"}, {}};
        for (const CyclesRow* row : sorted) {
            table.add({std::to_string(row->spp), cell("%.6g", row->seconds), cell("%.6g", row->relMse)});
        }
        data.emplace_back(renderer, table.csv());
    }
    return data;
}

}  // namespace strata
