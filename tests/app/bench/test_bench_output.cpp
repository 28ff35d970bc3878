// The bench's text helpers: a formatted cell holds the whole text, however long (the summary's
// paragraphs are formatted with it).
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
