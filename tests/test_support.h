#pragma once
// Shared pieces of the test suite: paths, running the strata binary, small analytic scenes and
// the statistics that turn "close enough" into k standard errors.
#include <cmath>
#include <filesystem>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "scene/mesh.h"
#include "integrator/path_integrator.h"
#include "geometry/ray.h"

// Whether this build runs under AddressSanitizer or ThreadSanitizer: their allocators keep freed
// memory, and a sanitized `strata` child process stops on leaks in Mesa, so a few checks of
// resident memory and of child processes apply only without them.
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define STRATA_TEST_SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
#define STRATA_TEST_SANITIZED 1
#endif
#endif

namespace strata::test {

#ifdef STRATA_TEST_SANITIZED
inline constexpr bool kSanitizedBuild = true;
#else
inline constexpr bool kSanitizedBuild = false;
#endif

// A correct estimator fails a 4.5-sigma check with probability 7e-6.
inline constexpr double kSigmas = 4.5;

std::filesystem::path sourceDir();
// The bundled Cornell box, assets/cornell/cornell.obj.
std::filesystem::path cornellScene();
// The scene the suite keeps in tests/data/NAME/NAME.obj (scripts/make_assets.py writes them).
std::filesystem::path testScene(const std::string& name);
// The optional shared collection beside the checkout (../shared), when it is there: a test that
// reads it says it is skipped without it (MESSAGE) and passes; every scene a test needs is in the
// repository.
std::optional<std::filesystem::path> sharedDir();
// A fresh empty folder for one test's files, removed with everything in it when the test's
// handle goes out of scope, so runs do not pile up folders in the temp directory. It is a path,
// so `dir / "file"` and every function taking a path accept it.
class ScratchDir : public std::filesystem::path {
public:
    explicit ScratchDir(std::filesystem::path dir) : std::filesystem::path(std::move(dir)) {}
    ScratchDir(const ScratchDir&) = delete;
    ScratchDir& operator=(const ScratchDir&) = delete;
    ~ScratchDir();
};
ScratchDir scratchDir(const std::string& name);

struct CommandResult {
    int exitCode;
    std::string out;  // stdout
    std::string err;  // stderr
};
// The file's bytes; empty when it cannot be read.
std::string fileBytes(const std::filesystem::path& path);
// Writes `bytes` to `path`, creating its folder.
void writeFile(const std::filesystem::path& path, const std::string& bytes);
// How many newline characters `text` holds.
int lineCount(const std::string& text);
// The names of the folder's entries (to check that nothing was left behind in it).
std::set<std::string> folderEntries(const std::filesystem::path& dir);
// An RLE true-colour TGA of 26 bytes whose header claims 2608 x 29814 texels at 32 bits: stb
// would decode it, padding the missing packets, into 1.2 GB (the loader fuzzer's finding).
std::string forgedTga();
// The process's peak resident memory so far (getrusage), in KB.
long peakRssKilobytes();
// The renderer folders (io, film, ...) that the sources of renderer/`folder` include from, its own
// among them: what the tests of each folder's place in the library's layering compare.
std::set<std::string> includedFolders(const std::string& folder);
// Runs a shell command line, capturing its output.
CommandResult runCommand(const std::string& commandLine);
// Runs the strata binary with `arguments` (already shell-quoted where needed).
CommandResult runStrata(const std::string& arguments);
// Fills `dir` with a file of garbage bytes named after each shared library `program` loads (as
// `ldd` lists them), as a downloaded model's folder could hold; returns how many (0 when `ldd`
// fails). A program that looked for its libraries in the current folder fails to start in `dir`.
int plantLibraryDecoys(const std::filesystem::path& program, const std::filesystem::path& dir);
// A command-line prefix under which a child obeys file permissions as other users do: empty for
// them, for root setpriv dropping the capabilities that override them (CAP_DAC_OVERRIDE,
// CAP_DAC_READ_SEARCH). Empty optional when root has no setpriv.
std::optional<std::string> obeyingPermissions();

// A point of [0,1)^2 from one hashed key (two 24-bit fractions of its hash): reproducible,
// uniform-looking input for the tests of samplers and lights.
glm::vec2 hashedPoint(uint64_t key);

// Checks that `a` lies within `tolerance` of `b` (both captured for the message).
void checkNear(const glm::vec3& a, const glm::vec3& b, float tolerance = 1e-5f);

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

// A UV sphere of `rings` x 2 `rings` quads appended to `mesh` with material `material`, facing
// out (counter-clockwise seen from outside), with unit vertex normals pointing out.
void addSphere(MeshData& mesh, const glm::vec3& centre, float radius, int rings, uint32_t material);

// The furnace (notes section 5.1): the cube [-1,1]^3 seen from inside, every face of `material`
// facing inward. With Kd = rho and Ke = Le the exact radiance at depth K is
// Le (1 - rho^(K+1)) / (1 - rho).
MeshData furnaceMesh(const Material& material);
// A ray from inside the furnace, away from its centre and its symmetry planes.
Ray furnaceRay();
double furnaceRadiance(double albedo, double emission, int depth);

// Lambert's polygon case (notes section 5.2): a receiver plane z = 0 of `receiver` (large,
// facing up) under the unit square [-1/2,1/2]^2 at z = 1, emitting 1 downward (and black).
// At depth 1 the radiance leaving the origin is rho E / pi with E = kLambertSquareIrradiance. No
// environment.
MeshData lambertSquareMesh(const Material& receiver);
inline constexpr double kLambertSquareIrradiance = 0.752274688454;
// Lambert's irradiance at `x` (normal +z) from a polygon of radiance 1 above it (notes 5.2):
// E = 1/2 sum_i Theta_i (n . Gamma_i), vertices counter-clockwise seen from above the emitter.
double lambertIrradiance(const glm::dvec3& x, const std::vector<glm::dvec3>& polygon);
// The ray that sees the origin of the receiver, from `from` (above the plane, below the square).
Ray rayToOrigin(const glm::vec3& from);

// The luminance of `ray`'s radiance, averaged over `passes` full passes (24 paths each) at each
// of `pixels` distinct pixels (seed fixed): one value per pixel, independent across pixels,
// stratified within a pixel as the sampler does it.
std::vector<double> pixelEstimates(const PathIntegrator& integrator, const Ray& ray, int pixels,
                                   uint32_t passes, uint64_t seed);

}  // namespace strata::test
