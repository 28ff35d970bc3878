#pragma once
// Whole-file reads for the scene's text formats (OBJ, MTL, camera JSON), with the one error
// message every loader uses.
#include <filesystem>
#include <string>

namespace strata {

// The file's bytes; throws strata::Error "PATH: cannot open WHAT" when it cannot be read.
std::string readTextFile(const std::filesystem::path& path, const std::string& what);

}  // namespace strata
