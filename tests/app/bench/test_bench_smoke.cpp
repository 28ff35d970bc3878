// The bench smoke test: `strata bench --quick` runs end to end (as CI does, keeping its summary in
// the log) and its error curves are sane. Speed figures are printed, never asserted.
#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <fstream>

#include "test_support.h"

using namespace strata;

namespace {
// The bench's CSV as RFC 4180 reads it: a quoted cell may hold commas, its quotes doubled.
std::vector<std::vector<std::string>> readCsv(const std::filesystem::path& path) {
    std::vector<std::vector<std::string>> rows;
    std::ifstream in(path);
    for (std::string line; std::getline(in, line);) {
        std::vector<std::string> cells(1);
        bool quoted = false;
        for (size_t i = 0; i < line.size(); ++i) {
            const char c = line[i];
            if (c == '"' && quoted && i + 1 < line.size() && line[i + 1] == '"') {
                cells.back() += '"';
                ++i;
            } else if (c == '"') {
                quoted = !quoted;
            } else if (c == ',' && !quoted) {
                cells.emplace_back();
            } else {
                cells.back() += c;
            }
        }
        rows.push_back(cells);
    }
    return rows;
}
}  // namespace

TEST_CASE("bench_smoke: strata bench --quick finishes, no NaN, error falls as spp grows") {
    const auto dir = test::scratchDir("bench-smoke");
    // Under the sanitizers the error runs take a quarter of the pixels (24 wide): the section cost
    // 92 of the bench's 238 s under ASan, and its checks hold as well on 24 x 24 pixels.
    const std::string size = test::kSanitizedBuild ? " --width 24" : "";
    const auto result = test::runStrata("bench --quick" + size + " --out-dir " + dir.string());
    MESSAGE(result.out);  // the summary, for the CI log
    REQUIRE_MESSAGE(result.exitCode == 0, result.err);
    CHECK(std::filesystem::is_regular_file(dir / "summary.md"));
    // The throughput section's progress counts its stages, not a render's passes, spp and rate.
    CHECK_MESSAGE(result.err.find("throughput: stage 7/7, ") != std::string::npos, result.err);

    int runs = 0;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        const std::string name = entry.path().filename().string();
        if (name.rfind("convergence-", 0) != 0 || entry.path().extension() != ".csv") continue;
        ++runs;
        const auto rows = readCsv(entry.path());
        REQUIRE(rows.size() >= 4);  // header + at least 3 checkpoints
        const auto& header = rows.front();
        const auto column = [&](const std::string& key) {
            return static_cast<size_t>(std::find(header.begin(), header.end(), key) - header.begin());
        };
        const size_t rmse = column("rmse"), relmse = column("relmse"), nonfinite = column("nonfinite");
        REQUIRE(rmse < header.size());
        for (size_t r = 1; r < rows.size(); ++r) {
            CHECK(std::isfinite(std::stod(rows[r][rmse])));
            CHECK(std::isfinite(std::stod(rows[r][relmse])));
            CHECK(rows[r][nonfinite] == "0");
        }
        INFO(name);
        // 16x the samples: the error of an unbiased estimator falls by about 4; ask for 2. A
        // zero-variance estimator (cosine or BSDF sampling of the furnace) is exact from the start
        // and stays within float rounding of the exact value.
        if (name.find("adaptive") != std::string::npos) {
            // Adaptive sampling stops pixels at 5% relative error: its curve flattens by design.
            CHECK(std::stod(rows.back()[rmse]) <= std::stod(rows[1][rmse]));
        } else if (std::stod(rows[1][rmse]) == 0.0) {
            CHECK(std::stod(rows.back()[rmse]) < 1e-3);
        } else {
            CHECK(std::stod(rows.back()[rmse]) < 0.5 * std::stod(rows[1][rmse]));
        }
    }
    CHECK(runs >= 4);  // two bundled scenes x two samplers

    // The viewer's section: its figures (offscreen OpenGL works wherever the suite runs), or, in a
    // sanitizer build whose child `strata view` stops on Mesa's leaks, why it could not run.
    const size_t viewer = result.out.find("### The viewer:");
    REQUIRE(viewer != std::string::npos);
    const bool skipped = result.out.compare(result.out.find('\n', viewer) + 2, 8, "Skipped:") == 0;
    CHECK((!skipped || test::kSanitizedBuild));
    if (!skipped) {
        const auto rows = readCsv(dir / "viewer.csv");
        REQUIRE(rows.size() == 3);  // header, strata render, strata view
        CHECK(std::stod(rows[1][1]) > 0.0);
        CHECK(std::stod(rows[2][1]) > 0.0);
        CHECK(result.out.find("UI frame times while rendering the split view") != std::string::npos);
    }

    // The real scenes: their table beside the Cornell box's row, or, without assimp-testmodels
    // installed, the note saying so.
    const size_t real = result.out.find("### Real scenes:");
    REQUIRE(real != std::string::npos);
    if (result.out.compare(result.out.find('\n', real) + 2, 8, "Skipped:") == 0) {
        CHECK(result.out.find("assimp-testmodels", real) != std::string::npos);
    } else {
        const auto rows = readCsv(dir / "real-scenes.csv");
        REQUIRE(rows.size() >= 3);  // header, the Cornell box, at least one model
        CHECK(rows[1][0] == "Cornell box");
        for (size_t r = 1; r < rows.size(); ++r) {
            INFO(rows[r][0]);
            CHECK(std::stoul(rows[r][1]) > 0);    // triangles
            CHECK(std::stod(rows[r][5]) > 0.0);   // first image, s
            // The viewer's first image, s, as the viewer's section: measured but in a sanitizer
            // build, whose child `strata view` may stop on Mesa's leaks.
            CHECK((rows[r][6] == "-" ? test::kSanitizedBuild : std::stod(rows[r][6]) > 0.0));
            CHECK(std::stod(rows[r][7]) > 0.0);   // Mpaths/CPU-s
            CHECK(std::stod(rows[r][9]) > 0.0);   // peak RSS, MiB
        }
    }
}
