#pragma once
// The GLSL sources of shaders/, compiled into the program (see app/viewer/CMakeLists.txt).

namespace strata::viewer {

extern const char* const kDisplayVertexShader;
extern const char* const kDisplayFragmentShader;

}  // namespace strata::viewer
