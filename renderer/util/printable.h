#pragma once
// Strings read from scene files (names, URIs, words of a bad line), made fit for the one-line
// messages of strata::Error and LoadReport: a file decides what they hold, and a message must
// not carry a terminal's control sequences, break into lines or swallow a megabyte of base64.
#include <cstddef>
#include <string>
#include <string_view>

namespace strata {

// `text` with its control characters escaped (\n, \r, \t, \xHH; the C1 controls U+0080..U+009F
// as \u0080.. and bytes that are not UTF-8 as \xHH), every data: URI cut to its header and size
// ("data:image/png;base64,... (123456 bytes)") and anything beyond `longest` bytes cut to them and
// its size ("... (5000 bytes)"). Printable ASCII and UTF-8 pass unchanged, so that a printable
// text stays as it is.
std::string printable(std::string_view text, size_t longest = 200);

// printable(text) in single quotes, as messages quote names: 'Red Plastic'.
std::string quote(std::string_view text);

}  // namespace strata
