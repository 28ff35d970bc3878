#include "bench/bench_process.h"

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <string_view>
#include <unistd.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <nlohmann/json.hpp>

#include "io/output_file.h"

extern char** environ;

namespace strata {

ProcessTiming runTimed(std::vector<std::string> args, const std::filesystem::path& log,
                       const std::filesystem::path& directory) {
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    // The child writes into the log's temporary, which becomes the log once it has exited.
    OutputFile logFile(log);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, logFile.descriptor(), 1);
    posix_spawn_file_actions_adddup2(&actions, 1, 2);
    if (!directory.empty()) posix_spawn_file_actions_addchdir_np(&actions, directory.c_str());
    const auto start = std::chrono::steady_clock::now();
    pid_t pid = 0;
    const int spawned = posix_spawnp(&pid, argv[0], &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    if (spawned != 0) {
        logFile.commit();  // empty, as the note that names it expects
        return {};
    }
    int status = 0;
    rusage usage{};
    // wait4's usage covers the child's own waited-for children too (mpiexec's ranks).
    wait4(pid, &status, 0, &usage);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    logFile.commit();
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) return {};
    const auto toSeconds = [](const timeval& t) { return t.tv_sec + 1e-6 * t.tv_usec; };
    return {seconds, toSeconds(usage.ru_utime) + toSeconds(usage.ru_stime)};
}

nlohmann::json lastJsonReport(const std::filesystem::path& log) {
    std::ifstream in(log);
    std::string report;
    for (std::string line; std::getline(in, line);) {
        if (!line.empty() && line.front() == '{') report = line;
    }
    return nlohmann::json::parse(report, nullptr, false);
}

bool onPath(const std::string& program) {
    const char* path = std::getenv("PATH");
    std::string_view folders = path ? path : "";
    while (true) {
        const size_t colon = folders.find(':');
        const std::string_view folder = folders.substr(0, colon);
        const auto candidate = std::filesystem::path(folder.empty() ? "." : folder) / program;
        if (access(candidate.c_str(), X_OK) == 0 && std::filesystem::is_regular_file(candidate)) return true;
        if (colon == std::string_view::npos) return false;
        folders.remove_prefix(colon + 1);
    }
}

}  // namespace strata
