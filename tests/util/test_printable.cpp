// Strings from scene files made fit for one-line messages (util/printable.h).
#include <doctest/doctest.h>

#include <string>

#include "util/printable.h"

using namespace strata;

TEST_CASE("printable: control characters, C1 controls and bytes that are not UTF-8 are escaped") {
    CHECK(printable("Red Plastic") == "Red Plastic");
    CHECK(printable("a\nb\r\tc") == "a\\nb\\r\\tc");
    CHECK(printable(std::string("\x1b[31mred\x7f\0", 10)) == "\\x1b[31mred\\x7f\\x00");
    // UTF-8 passes, but not U+009B (CSI, a C1 control some terminals obey), nor a lone or
    // overlong byte, nor a surrogate.
    CHECK(printable("caf\xc3\xa9 \xe6\x9d\xb1 \xf0\x9f\x8e\xa8") ==
          "caf\xc3\xa9 \xe6\x9d\xb1 \xf0\x9f\x8e\xa8");
    CHECK(printable("\xc2\x9b"
                    "2J") == "\\u009b2J");
    CHECK(printable("\xff\xc0\xaf\xed\xa0\x80") == "\\xff\\xc0\\xaf\\xed\\xa0\\x80");
    CHECK(printable("\xe6\x9d") == "\\xe6\\x9d");
    CHECK(quote("it's\n") == "'it's\\n'");
    // What is printable stays so: escaping twice changes nothing.
    const std::string once = printable("a\nb\xc2\x9b\xff");
    CHECK(printable(once) == once);
}

TEST_CASE("printable: a data: URI shows its header and size, a long text its first 200 bytes and size") {
    const std::string uri = "data:application/octet-stream;base64," + std::string(100000, 'A');
    CHECK(printable(uri) == "data:application/octet-stream;base64,... (100037 bytes)");
    CHECK(printable("Failed to decode 'uri' : " + uri + " in Buffer", SIZE_MAX) ==
          "Failed to decode 'uri' : data:application/octet-stream;base64,... (100037 bytes) in Buffer");
    CHECK(printable("data:" + std::string(300, 'x')) == "data:... (305 bytes)");
    CHECK(printable("Corrupt JPEG data: premature end") == "Corrupt JPEG data: premature end");
    // Not a URI's start: inside a word.
    CHECK(printable("metadata:x") == "metadata:x");
    CHECK(printable(std::string(250, 'n')) == std::string(200, 'n') + "... (250 bytes)");
    CHECK(printable(std::string(250, 'n'), 1000) == std::string(250, 'n'));
}
