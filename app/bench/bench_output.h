#pragma once
// Files of `strata bench`: CSV tables and gnuplot plots in the output folder, each written
// through an OutputFile (io/output_file.h).
#include <filesystem>
#include <string>
#include <vector>

namespace strata {

// A table whose cells are already formatted; written as CSV (header first) or as markdown.
struct Table {
    std::vector<std::string> header;
    std::vector<std::vector<std::string>> rows;

    void add(std::vector<std::string> row) { rows.push_back(std::move(row)); }
    std::string csv() const;
    std::string markdown() const;
};

// printf-style formatting of one cell.
std::string cell(const char* format, ...) __attribute__((format(printf, 1, 2)));

// "1 thread", "2 threads", ...: how many threads a measurement ran on, for titles and labels.
std::string threadsText(int threads);

// Runs gnuplot on `script` (written as DIR/NAME.gp beside the data it reads) in `dir`, so that
// the plot's file names are relative to it. Returns false, with a note on stderr, when gnuplot is
// missing or fails (the bench's figures do not depend on it).
bool runGnuplot(const std::filesystem::path& dir, const std::string& name, const std::string& script);

}  // namespace strata
