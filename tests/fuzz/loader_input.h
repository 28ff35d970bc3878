#pragma once
// One input of the scene-loader fuzzer: OBJ text, a NUL byte, MTL text, a NUL byte, scene
// description JSON, a NUL byte, glTF JSON, a NUL byte, texture bytes (the rest, NULs included;
// missing parts are empty). The OBJ and MTL become the scene files fuzz.obj and fuzz.mtl of a
// bundle, the glTF fuzz.gltf of another, each with the texture as fuzz.png, parsed by
// strata::parseSceneMesh, and the JSON goes through strata::parseSceneDescription: the code paths
// of loading files. Shared by the fuzzer and
// tests/scene/test_fuzz_regressions.cpp, which replays the seed corpus and every finding.
#include <string_view>

namespace strata::fuzz {

// Returns normally when the loaders accept the input or refuse it with strata::Error. Throws
// std::logic_error when a returned mesh breaks the loader's promises; anything else that escapes
// (another exception, a sanitizer report) is a finding too.
void parseLoaderInput(std::string_view input);

}  // namespace strata::fuzz
