#include "bench/strata_child.h"

namespace strata {

std::vector<std::string> strataCommandLine(const std::string& command, const RenderOptions& options,
                                           const std::vector<std::string>& more) {
    std::vector<std::string> args = {std::filesystem::read_symlink("/proc/self/exe").string(), command};
    const std::vector<std::string> rendering = options.arguments();
    args.insert(args.end(), rendering.begin(), rendering.end());
    args.insert(args.end(), more.begin(), more.end());
    return args;
}

std::vector<std::string> renderCommandLine(const RenderOptions& options, int spp,
                                           const std::filesystem::path& out) {
    std::vector<std::string> more = {"--spp", std::to_string(spp)};
    if (!out.empty()) more.insert(more.end(), {"--out", out.string()});
    return strataCommandLine("render", options, more);
}

}  // namespace strata
