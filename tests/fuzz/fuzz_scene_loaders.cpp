// libFuzzer target for the scene loaders (OBJ, MTL, description JSON, glTF or GLB, a texture and an
// EXR environment in one input, see loader_input.h). Built by -DSTRATA_FUZZ=ON with clang and run by
// scripts/check.sh fuzz; a finding is copied into tests/fuzz/findings/, which
// tests/scene/test_fuzz_regressions.cpp replays in every build.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "loader_input.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    strata::fuzz::parseLoaderInput(std::string_view(reinterpret_cast<const char*>(data), size));
    return 0;
}
