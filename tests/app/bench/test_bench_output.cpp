// The bench's text helpers: a formatted cell holds the whole text, however long (the summary's
// paragraphs are formatted with it), and a table's CSV keeps one column per header cell.
#include <doctest/doctest.h>

#include <string>

#include "bench/bench_output.h"

using namespace strata;

TEST_CASE("bench output: a formatted cell is never cut short") {
    CHECK(cell("%.3f", 0.1234) == "0.123");
    CHECK(cell("%s", "") == "");
    const std::string sentence(1000, 'x');
    const std::string text = cell("%s and %d more words", sentence.c_str(), 42);
    CHECK(text.size() == sentence.size() + 18);
    CHECK(text.substr(sentence.size()) == " and 42 more words");
}

TEST_CASE("bench output: a CSV cell with a comma or a quote is quoted, the others are not") {
    Table table;
    table.header = {"renderer", "spp"};
    table.add({"Strata defaults (strata24-bsdf, NEE)", "72"});
    table.add({"a \"quoted\" name", "1.5e-05"});
    table.add({"plain", "-"});
    CHECK(table.csv() ==
          "renderer,spp\n"
          "\"Strata defaults (strata24-bsdf, NEE)\",72\n"
          "\"a \"\"quoted\"\" name\",1.5e-05\n"
          "plain,-\n");
}
