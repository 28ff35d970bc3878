#pragma once
// The one OpenGL loader of the viewer (glad, generated at build time): every context, windowed
// (GLFW) or offscreen (EGL, OSMesa), hands it its own get-proc-address function.
#include <glad/gl.h>

namespace strata::viewer {

// Loads the OpenGL 3.3 core entry points of the current context; throws strata::Error when the
// context is older or cannot be loaded.
void loadGl(GLADloadfunc getProcAddress);

}  // namespace strata::viewer
