#pragma once
// Where the scenes that come with Strata are (cornell/, furnace/, glossy/, each NAME/NAME.obj with
// its .mtl and .json), for every command that needs one when none is given.
#include <filesystem>
#include <string>

namespace strata {

// The bundled scenes' folder. An installed program finds it from its own path (PREFIX/bin/strata
// reads PREFIX/share/strata), so a moved prefix keeps working and nothing points back at the
// clone it was built from; only a program run where it was built reads its source tree's
// assets/. Throws strata::Error naming the folder when neither is there.
std::filesystem::path bundledAssetsDir();

// The bundled scene `name`: NAME/NAME.obj in that folder.
std::filesystem::path bundledScene(const std::string& name);

}  // namespace strata
