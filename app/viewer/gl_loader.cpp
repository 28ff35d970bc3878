#include "gl_loader.h"

#include <string>

#include "util/error.h"

namespace strata::viewer {

void loadGl(GLADloadfunc getProcAddress) {
    const int version = gladLoadGL(getProcAddress);
    if (version == 0) throw Error("OpenGL: cannot load the OpenGL entry points");
    if (GLAD_VERSION_MAJOR(version) * 10 + GLAD_VERSION_MINOR(version) < 33) {
        throw Error("OpenGL: version 3.3 core needed, the context has " +
                    std::to_string(GLAD_VERSION_MAJOR(version)) + "." +
                    std::to_string(GLAD_VERSION_MINOR(version)));
    }
}

}  // namespace strata::viewer
