#pragma once
// Binary glTF 2.0 files assembled in memory (glTF 2.0, "Binary glTF Layout"): the loader's
// rewritten JSON in place of a file's, and glTF 1.0's binary files upgraded (gltf_version1.h).
#include <cstdint>
#include <string>
#include <string_view>

#include "util/little_endian.h"

namespace strata {

constexpr uint32_t kGlbJsonChunk = 0x4E4F534A;  // "JSON"
constexpr uint32_t kGlbBinChunk = 0x004E4942;   // "BIN\0"

// A chunk of `type` holding `data`, padded with `pad` to a multiple of 4 bytes.
inline std::string glbChunk(uint32_t type, std::string_view data, char pad) {
    std::string chunk;
    const size_t padded = (data.size() + 3) / 4 * 4;
    appendLittleEndian32(chunk, static_cast<uint32_t>(padded));
    appendLittleEndian32(chunk, type);
    chunk += data;
    chunk.append(padded - data.size(), pad);
    return chunk;
}

// The .glb of the JSON `json` (padded with spaces), followed by the whole chunks `chunks`.
inline std::string glbOf(std::string_view json, std::string_view chunks) {
    std::string out = "glTF";
    appendLittleEndian32(out, 2);
    const std::string jsonChunk = glbChunk(kGlbJsonChunk, json, ' ');
    appendLittleEndian32(out, static_cast<uint32_t>(12 + jsonChunk.size() + chunks.size()));
    out += jsonChunk;
    out += chunks;
    return out;
}

}  // namespace strata
