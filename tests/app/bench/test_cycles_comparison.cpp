// Reading `strata bench --vs-cycles` from given figures: the table's products and ratios, the
// equal-time spp, the plot's data and script.
#include <doctest/doctest.h>

#include <algorithm>

#include "bench/cycles_comparison.h"

using namespace strata;

TEST_CASE("cycles comparison: relMSE x s and every ratio against the Cycles row of the same spp") {
    const std::vector<CyclesRow> rows = {
        {kCyclesRenderer, "", 72, 72, 0.01, 2.0, {1.0, 1.0, 1.0}},
        {"Strata defaults", "same spp", 72, 72, 0.02, 0.5, {1.001, 0.999, 1.0}},
        {"Strata defaults", "equal time", 72, 288, 0.005, 2.0, {1.0, 1.0, 1.0}},
        {"Strata defaults", "same spp", 264, 264, 0.004, 1.0, {1.0, 1.0, 1.0}}};  // no Cycles at 264
    const Table table = cyclesComparisonTable(rows);
    REQUIRE(table.rows.size() == 4);
    const auto column = [&](const std::string& name) {
        return size_t(std::find(table.header.begin(), table.header.end(), name) - table.header.begin());
    };
    const size_t product = column("relMSE x s"), relMse = column("relMSE / Cycles'"),
                 seconds = column("s / Cycles'"), cost = column("relMSE x s / Cycles'");
    REQUIRE(cost < table.header.size());
    CHECK(table.rows[0][product] == "0.02");
    CHECK(table.rows[0][cost] == "-");  // Cycles against itself
    CHECK(table.rows[1][product] == "0.01");
    CHECK(table.rows[1][relMse] == "2.000");
    CHECK(table.rows[1][seconds] == "0.250");
    CHECK(table.rows[1][cost] == "0.500");
    CHECK(table.rows[2][column("spp")] == "288");
    CHECK(table.rows[2][relMse] == "0.500");
    CHECK(table.rows[2][seconds] == "1.000");
    CHECK(table.rows[2][cost] == "0.500");
    CHECK(table.rows[3][cost] == "-");
    CHECK(table.rows[1].back() == "1.0010 0.9990 1.0000");
}

TEST_CASE("cycles comparison: the equal-time spp lies on the line through two measurements") {
    // 1 s of start-up and 0.01 s a sample: 3 s is 200 spp, and 192 the nearest multiple of 24.
    const TimedSpp a{72, 1.72}, b{264, 3.64};
    CHECK(equalTimeSpp(a, b, 3.0, 24) == 192);
    CHECK(equalTimeSpp(b, a, 3.0, 24) == 192);  // in either order
    CHECK(equalTimeSpp(a, b, 1.72, 24) == 72);
    CHECK(equalTimeSpp(a, b, 0.2, 24) == 24);   // under the start-up: the smallest budget
    CHECK(equalTimeSpp(a, b, 11.0, 24) == 1008);  // 1000 spp, to the nearest multiple of 24
    // Two times that do not rise with spp (noise): proportional to the larger measurement.
    CHECK(equalTimeSpp({72, 2.0}, {264, 2.0}, 4.0, 24) == 528);
    CHECK(equalTimeSpp({72, 2.0}, {72, 2.0}, 1.0, 24) == 48);  // 36, to the nearest multiple of 24
}

TEST_CASE("cycles comparison: one curve per renderer, one point per spp, in order of time") {
    const std::vector<CyclesRow> rows = {
        {kCyclesRenderer, "", 72, 72, 0.01, 2.0, {1.0, 1.0, 1.0}},
        {"Strata", "same spp", 72, 72, 0.02, 0.5, {1.0, 1.0, 1.0}},
        {"Strata", "equal time", 72, 288, 0.005, 2.0, {1.0, 1.0, 1.0}},
        {kCyclesRenderer, "", 264, 264, 0.003, 7.0, {1.0, 1.0, 1.0}},
        {"Strata", "same spp", 264, 264, 0.006, 1.8, {1.0, 1.0, 1.0}},
        {"Strata", "equal time", 264, 288, 0.005, 2.0, {1.0, 1.0, 1.0}}};  // the same run twice
    const auto data = cyclesPlotData(rows);
    REQUIRE(data.size() == 2);
    CHECK(data[0].first == kCyclesRenderer);
    CHECK(data[0].second == "spp,seconds,relmse\n72,2,0.01\n264,7,0.003\n");
    CHECK(data[1].first == "Strata");
    CHECK(data[1].second == "spp,seconds,relmse\n72,0.5,0.02\n264,1.8,0.006\n288,2,0.005\n");

    const std::string script = cyclesPlotScript({{"Cycles", "a.csv"}, {"Strata", "b.csv"}}, "plot.png", "cornell");
    CHECK(script.find("set output 'plot.png'") != std::string::npos);
    CHECK(script.find("set logscale xy") != std::string::npos);
    CHECK(script.find("'a.csv' using 'seconds':'relmse' with linespoints lw 2 title 'Cycles', "
                      "'b.csv' using 'seconds':'relmse' with linespoints lw 2 title 'Strata'") != std::string::npos);
    CHECK(script.find("set title 'cornell'") != std::string::npos);
    // The key below the axes, the picture taller by a line per series.
    CHECK(script.find("set key outside below") != std::string::npos);
    CHECK(script.find("size 640,432 ") != std::string::npos);
}
