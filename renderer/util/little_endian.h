#pragma once
// Unsigned 32-bit words of binary file formats, least significant byte first (binary glTF's
// headers and chunks), read and written byte by byte whatever the host's order.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace strata {

// The word at `offset`; bytes.size() must be at least offset + 4.
inline uint32_t littleEndian32(std::string_view bytes, size_t offset) {
    const auto byte = [&](size_t k) { return static_cast<uint32_t>(static_cast<unsigned char>(bytes[offset + k])); };
    return byte(0) | byte(1) << 8 | byte(2) << 16 | byte(3) << 24;
}

inline void appendLittleEndian32(std::string& out, uint32_t word) {
    for (int k = 0; k < 4; ++k) out += static_cast<char>((word >> (8 * k)) & 0xFFu);
}

}  // namespace strata
