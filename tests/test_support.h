#pragma once
// Shared pieces of the test suite: paths, running the strata binary, small analytic scenes and
// the statistics that turn "close enough" into k standard errors.
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>
#include <glm/vec3.hpp>

#include "mesh.h"

namespace strata::test {

std::filesystem::path sourceDir();
std::filesystem::path sharedDir();
// A fresh empty folder for one test's files.
std::filesystem::path scratchDir(const std::string& name);

struct CommandResult {
    int exitCode;
    std::string out;  // stdout
    std::string err;  // stderr
};
// Runs a shell command line, capturing its output.
CommandResult runCommand(const std::string& commandLine);
// Runs the strata binary with `arguments` (already shell-quoted where needed).
CommandResult runStrata(const std::string& arguments);

// Mean and standard error of the mean of a sample.
struct MeanEstimate {
    double mean;
    double standardError;
};
MeanEstimate estimateMean(const std::vector<double>& values);

// The chi-square value that a correct sampler exceeds with probability 1e-4 (Wilson-Hilferty),
// for `degrees` degrees of freedom. With fixed seeds the tests are deterministic; this bound
// makes a false failure on any seed change very unlikely while still catching a wrong density.
double chiSquareCritical(size_t degrees);

// A quad (counter-clockwise as given) appended to `mesh` with material `material`.
void addQuad(MeshData& mesh, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c,
             const glm::vec3& d, uint32_t material);

}  // namespace strata::test
