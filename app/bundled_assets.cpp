#include "bundled_assets.h"

#include <system_error>

#include "util/error.h"

namespace strata {

namespace fs = std::filesystem;

fs::path bundledAssetsDir() {
    // /proc/self/exe is the program file itself, whatever PATH entry or symlink started it.
    const fs::path exeDir = fs::read_symlink("/proc/self/exe").parent_path();
    const fs::path installed = (exeDir / STRATA_ASSETS_FROM_EXE).lexically_normal();
    if (fs::is_directory(installed)) return installed;
    // The build folder has no share/strata: there the scenes are read from the source tree, so
    // that running the program needs no install step. An installed copy never looks there.
    std::error_code notThere;
    if (fs::equivalent(exeDir, STRATA_BUILD_EXE_DIR, notThere) &&
        fs::is_directory(STRATA_SOURCE_ASSETS_DIR)) {
        return STRATA_SOURCE_ASSETS_DIR;
    }
    throw Error("the bundled scenes are missing: no folder " + installed.string() +
                " (reinstall strata, or give a scene)");
}

fs::path bundledScene(const std::string& name) { return bundledAssetsDir() / name / (name + ".obj"); }

}  // namespace strata
