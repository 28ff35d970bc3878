#include "util/text_file.h"

#include <fstream>
#include <sstream>

#include "util/error.h"

namespace strata {

std::string readTextFile(const std::filesystem::path& path, const std::string& what) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(path.string() + ": cannot open " + what);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

}  // namespace strata
