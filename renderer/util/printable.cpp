#include "util/printable.h"

#include <cctype>
#include <cstdio>

namespace strata {
namespace {

std::string hexEscape(const char* format, unsigned value) {
    char text[8];
    std::snprintf(text, sizeof text, format, value);
    return text;
}

// The length of the well-formed UTF-8 sequence of two or more bytes at `text[i]`; 0 when there is
// none (RFC 3629: no overlong forms, no surrogates, nothing above U+10FFFF).
size_t utf8Length(std::string_view text, size_t i) {
    const auto byte = [&](size_t k) { return static_cast<unsigned char>(text[k]); };
    const unsigned lead = byte(i);
    size_t length = 0;
    unsigned low = 0x80, high = 0xBF;  // the range of the second byte
    if (lead >= 0xC2 && lead <= 0xDF) {
        length = 2;
    } else if (lead >= 0xE0 && lead <= 0xEF) {
        length = 3;
        if (lead == 0xE0) low = 0xA0;
        if (lead == 0xED) high = 0x9F;
    } else if (lead >= 0xF0 && lead <= 0xF4) {
        length = 4;
        if (lead == 0xF0) low = 0x90;
        if (lead == 0xF4) high = 0x8F;
    } else {
        return 0;
    }
    if (i + length > text.size()) return 0;
    if (byte(i + 1) < low || byte(i + 1) > high) return 0;
    for (size_t k = 2; k < length; ++k) {
        if (byte(i + k) < 0x80 || byte(i + k) > 0xBF) return 0;
    }
    return length;
}

// The data: URI that starts at `text[i]`: its header up to the comma, then its size; the index
// after it, or `i` itself (nothing appended) when nothing follows the "data:", which is then a
// word of a message ("Corrupt JPEG data: premature end") rather than a URI.
size_t appendDataUri(std::string_view text, size_t i, std::string& out) {
    size_t end = i;
    while (end < text.size() && text[end] != ' ' && text[end] != '\'' && text[end] != '"') ++end;
    if (end - i == 5) return i;
    const std::string_view uri = text.substr(i, end - i);
    const size_t comma = uri.find(',');
    // The media type and encoding, when short: "data:image/png;base64,".
    const size_t header = comma != std::string_view::npos && comma <= 64 ? comma + 1 : 5;
    out += "data:" + printable(uri.substr(5, header - 5));
    out += "... (" + std::to_string(uri.size()) + " bytes)";
    return end;
}

}  // namespace

std::string printable(std::string_view text, size_t longest) {
    std::string out;
    size_t i = 0;
    while (i < text.size() && i < longest) {
        const auto c = static_cast<unsigned char>(text[i]);
        const bool wordStart = i == 0 || !std::isalnum(static_cast<unsigned char>(text[i - 1]));
        if (wordStart && text.compare(i, 5, "data:") == 0) {
            if (const size_t end = appendDataUri(text, i, out); end > i) {
                i = end;
                continue;
            }
        }
        if (c >= 0x20 && c < 0x7F) {
            out += static_cast<char>(c);
            ++i;
        } else if (c == '\n') {
            out += "\\n", ++i;
        } else if (c == '\r') {
            out += "\\r", ++i;
        } else if (c == '\t') {
            out += "\\t", ++i;
        } else if (const size_t length = c >= 0x80 ? utf8Length(text, i) : 0; length > 0) {
            const auto second = static_cast<unsigned char>(text[i + 1]);
            if (c == 0xC2 && second < 0xA0) {
                out += hexEscape("\\u%04x", second);
            } else {
                out.append(text.substr(i, length));
            }
            i += length;
        } else {
            out += hexEscape("\\x%02x", c);
            ++i;
        }
    }
    if (i < text.size()) out += "... (" + std::to_string(text.size()) + " bytes)";
    return out;
}

std::string quote(std::string_view text) { return "'" + printable(text) + "'"; }

}  // namespace strata
