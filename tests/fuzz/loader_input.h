#pragma once
// One input of the scene-loader fuzzer: six parts, each but the last ended by kPartSeparator
// (missing parts are empty): OBJ text, MTL text, scene description JSON, glTF (JSON or binary),
// texture bytes (PNG, JPEG, TGA, BMP or EXR), environment map EXR. The OBJ and MTL become the
// scene files fuzz.obj and fuzz.mtl of a bundle with the JSON as its description fuzz.json, the
// glTF fuzz.gltf of another; both hold the texture as fuzz.png and the environment as sky.exr.
// Each bundle goes through strata::parseSceneContents (all of parsing), and the JSON through
// strata::parseSceneDescription on its own too: the code paths of loading files.
//
// A separator of 17 bytes rather than a byte (NUL, which binary files hold) or length prefixes
// (which any insertion into one part would break for the parts after it): a part can hold any
// binary file, and a mutation stays in its part. Seeds are written with it between the parts:
//   printf '%s\n%%%%strata-part%%%%\n%s' "$(cat a.obj)" "$(cat a.mtl)" > tests/fuzz/corpus/NAME
// Shared by the fuzzer and tests/scene/test_fuzz_regressions.cpp, which replays the seed corpus
// and every finding.
#include <string_view>

namespace strata::fuzz {

inline constexpr std::string_view kPartSeparator = "\n%%strata-part%%\n";

// Returns normally when the loaders accept the input or refuse it with strata::Error. Throws
// std::logic_error when a returned scene breaks the loader's promises; anything else that
// escapes (another exception, a sanitizer report) is a finding too.
void parseLoaderInput(std::string_view input);

}  // namespace strata::fuzz
