#include "bench/bench_output.h"

#include <algorithm>
#include <cstdarg>
#include <cstdio>

#include "bench/bench_process.h"
#include "io/output_file.h"

namespace strata {

namespace {

// A cell as RFC 4180 writes it: quoted, its quotes doubled, when it holds a comma, a quote or a
// line break (labels such as "Strata defaults (strata24-bsdf, NEE, ...)" do), so that a CSV
// reader sees the columns the header names.
std::string csvField(const std::string& cell) {
    if (cell.find_first_of(",\"\r\n") == std::string::npos) return cell;
    std::string quoted = "\"";
    for (char c : cell) {
        if (c == '"') quoted += '"';
        quoted += c;
    }
    return quoted + "\"";
}

}  // namespace

std::string Table::csv() const {
    auto line = [](const std::vector<std::string>& cells) {
        std::string s;
        for (size_t i = 0; i < cells.size(); ++i) {
            if (i > 0) s += ',';
            s += csvField(cells[i]);
        }
        return s + "\n";
    };
    std::string text = line(header);
    for (const auto& row : rows) text += line(row);
    return text;
}

std::string Table::markdown() const {
    auto line = [](const std::vector<std::string>& cells) {
        std::string s = "|";
        for (const auto& c : cells) s += " " + c + " |";
        return s + "\n";
    };
    std::string text = line(header) + "|";
    for (size_t i = 0; i < header.size(); ++i) text += "---|";
    text += "\n";
    for (const auto& row : rows) text += line(row);
    return text;
}

std::string cell(const char* format, ...) {
    va_list args;
    va_start(args, format);
    va_list copy;
    va_copy(copy, args);
    // Measured first, so that a long sentence is never cut short.
    const int length = std::vsnprintf(nullptr, 0, format, copy);
    va_end(copy);
    std::string text(static_cast<size_t>(std::max(length, 0)), '\0');
    std::vsnprintf(text.data(), text.size() + 1, format, args);
    va_end(args);
    return text;
}

std::string threadsText(int threads) {
    return std::to_string(threads) + (threads == 1 ? " thread" : " threads");
}

bool runGnuplot(const std::filesystem::path& dir, const std::string& name, const std::string& script) {
    writeFile(dir / (name + ".gp"), script);
    const auto log = dir / (name + ".gp.log");
    if (!runTimed({"gnuplot", name + ".gp"}, log, dir).ok()) {
        std::fprintf(stderr, "note: gnuplot failed on %s/%s.gp (see %s; install gnuplot-nox); no plot\n",
                     dir.string().c_str(), name.c_str(), log.string().c_str());
        return false;
    }
    std::filesystem::remove(log);
    return true;
}

}  // namespace strata
