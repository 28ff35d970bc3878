#include "test_support.h"

#include <array>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <sys/wait.h>
#include <unistd.h>

namespace strata::test {

std::filesystem::path sourceDir() { return STRATA_SOURCE_DIR; }
std::filesystem::path sharedDir() { return STRATA_SHARED_DIR; }

std::filesystem::path scratchDir(const std::string& name) {
    const auto dir = std::filesystem::temp_directory_path() /
                     ("strata-test-" + std::to_string(getpid()) + "-" + name);
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

CommandResult runCommand(const std::string& commandLine) {
    const auto dir = scratchDir("run");
    const auto outFile = dir / "stdout";
    const auto errFile = dir / "stderr";
    const std::string command = "{ " + commandLine + "; } >" + outFile.string() + " 2>" +
                                errFile.string() + " </dev/null";
    const int status = std::system(command.c_str());
    auto slurp = [](const std::filesystem::path& p) {
        std::ifstream in(p);
        std::ostringstream s;
        s << in.rdbuf();
        return s.str();
    };
    CommandResult result{WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status),
                         slurp(outFile), slurp(errFile)};
    std::filesystem::remove_all(dir);
    return result;
}

CommandResult runStrata(const std::string& arguments) {
    return runCommand(std::string(STRATA_BINARY) + " " + arguments);
}

MeanEstimate estimateMean(const std::vector<double>& values) {
    double sum = 0.0;
    for (double v : values) sum += v;
    const double n = static_cast<double>(values.size());
    const double mean = sum / n;
    double squares = 0.0;
    for (double v : values) squares += (v - mean) * (v - mean);
    return {mean, std::sqrt(squares / (n - 1.0) / n)};
}

double chiSquareCritical(size_t degrees) {
    const double k = static_cast<double>(degrees);
    constexpr double z = 3.719;  // standard normal quantile at 1 - 1e-4
    const double a = 2.0 / (9.0 * k);
    return k * std::pow(1.0 - a + z * std::sqrt(a), 3.0);
}

void addQuad(MeshData& mesh, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c,
             const glm::vec3& d, uint32_t material) {
    const auto base = static_cast<uint32_t>(mesh.positions.size());
    mesh.positions.insert(mesh.positions.end(), {a, b, c, d});
    mesh.triangles.push_back({base, base + 1, base + 2});
    mesh.triangles.push_back({base, base + 2, base + 3});
    mesh.triangleMaterials.insert(mesh.triangleMaterials.end(), {material, material});
}

}  // namespace strata::test
