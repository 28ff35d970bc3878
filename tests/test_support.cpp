#include "test_support.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <fstream>
#include <regex>
#include <sstream>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#include <doctest/doctest.h>
#include <glm/geometric.hpp>

#include "film/accumulation_buffer.h"
#include "sampling/path_samples.h"
#include "sampling/random.h"

namespace strata::test {

std::filesystem::path sourceDir() { return STRATA_SOURCE_DIR; }
std::filesystem::path cornellScene() { return sourceDir() / "assets" / "cornell" / "cornell.obj"; }
std::filesystem::path testScene(const std::string& name) {
    return sourceDir() / "tests" / "data" / name / (name + ".obj");
}

std::optional<std::filesystem::path> sharedDir() {
    const std::filesystem::path shared = STRATA_SHARED_DIR;
    if (!std::filesystem::is_directory(shared)) return std::nullopt;
    return shared;
}

ScratchDir::~ScratchDir() {
    std::error_code ignored;  // a destructor must not throw; a leftover folder is harmless
    std::filesystem::remove_all(*this, ignored);
}

ScratchDir scratchDir(const std::string& name) {
    const auto dir = std::filesystem::temp_directory_path() /
                     ("strata-test-" + std::to_string(getpid()) + "-" + name);
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return ScratchDir(dir);
}

std::string fileBytes(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    return bytes.str();
}

void writeFile(const std::filesystem::path& path, const std::string& bytes) {
    std::filesystem::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary) << bytes;
}

int lineCount(const std::string& text) { return static_cast<int>(std::count(text.begin(), text.end(), '\n')); }

std::set<std::string> folderEntries(const std::filesystem::path& dir) {
    std::set<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) names.insert(entry.path().filename().string());
    return names;
}

std::string forgedTga() {
    std::string tga(18, '\0');
    tga[2] = 10;  // run-length encoded true colour
    tga[12] = '\x30', tga[13] = '\x0a', tga[14] = '\x76', tga[15] = '\x74', tga[16] = 32;
    return tga + std::string(8, '\x7f');
}

long peakRssKilobytes() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return usage.ru_maxrss;
}

std::set<std::string> includedFolders(const std::string& folder) {
    const std::regex include(R"re(#include "([a-z_]+)/)re");
    std::set<std::string> folders;
    for (const auto& entry : std::filesystem::directory_iterator(sourceDir() / "renderer" / folder)) {
        std::ifstream in(entry.path());
        for (std::string line; std::getline(in, line);) {
            std::smatch match;
            if (std::regex_search(line, match, include)) folders.insert(match[1]);
        }
    }
    return folders;
}

CommandResult runCommand(const std::string& commandLine) {
    const auto dir = scratchDir("run");
    const auto outFile = dir / "stdout";
    const auto errFile = dir / "stderr";
    const std::string command = "{ " + commandLine + "; } >" + outFile.string() + " 2>" +
                                errFile.string() + " </dev/null";
    const int status = std::system(command.c_str());
    CommandResult result{WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status),
                         fileBytes(outFile), fileBytes(errFile)};
    std::filesystem::remove_all(dir);
    return result;
}

CommandResult runStrata(const std::string& arguments) {
    return runCommand(std::string(STRATA_BINARY) + " " + arguments);
}

int plantLibraryDecoys(const std::filesystem::path& program, const std::filesystem::path& dir) {
    const CommandResult listed = runCommand("ldd " + program.string());
    const std::regex library(R"re(^\s*(lib[^ /]+\.so[^ ]*) => )re");
    int planted = 0;
    std::istringstream lines(listed.out);
    for (std::string line; std::getline(lines, line);) {
        std::smatch match;
        if (!std::regex_search(line, match, library)) continue;
        writeFile(dir / match[1].str(), "not a shared library\n");
        ++planted;
    }
    return planted;
}

std::optional<std::string> obeyingPermissions() {
    if (geteuid() != 0) return "";
    if (std::system("command -v setpriv >/dev/null 2>&1") != 0) return std::nullopt;
    return "setpriv --bounding-set=-dac_override,-dac_read_search ";
}

glm::vec2 hashedPoint(uint64_t key) {
    const uint64_t bits = mixBits(key);
    return {uniformFloat(bits), uniformFloat(bits << 24)};
}

void checkNear(const glm::vec3& a, const glm::vec3& b, float tolerance) {
    CAPTURE(a);
    CAPTURE(b);
    CHECK(glm::length(a - b) < tolerance);
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

double lambertIrradiance(const glm::dvec3& x, const std::vector<glm::dvec3>& polygon) {
    double sum = 0.0;
    for (size_t i = 0; i < polygon.size(); ++i) {
        const glm::dvec3 v0 = glm::normalize(polygon[i] - x);
        const glm::dvec3 v1 = glm::normalize(polygon[(i + 1) % polygon.size()] - x);
        sum += std::acos(glm::dot(v0, v1)) * glm::normalize(glm::cross(v0, v1)).z;
    }
    return 0.5 * sum;
}

void addQuad(MeshData& mesh, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c,
             const glm::vec3& d, uint32_t material) {
    const auto base = static_cast<uint32_t>(mesh.positions.size());
    mesh.positions.insert(mesh.positions.end(), {a, b, c, d});
    mesh.triangles.push_back({base, base + 1, base + 2});
    mesh.triangles.push_back({base, base + 2, base + 3});
    mesh.triangleMaterials.insert(mesh.triangleMaterials.end(), {material, material});
    if (!mesh.triangleNormals.empty()) mesh.triangleNormals.insert(mesh.triangleNormals.end(), {kNoNormals, kNoNormals});
}

void addSphere(MeshData& mesh, const glm::vec3& centre, float radius, int rings, uint32_t material) {
    const int segments = 2 * rings;
    const auto first = static_cast<uint32_t>(mesh.positions.size());
    const auto firstNormal = static_cast<uint32_t>(mesh.normals.size());
    // Vertex (ring, segment), ring 0 at the +z pole; the seam's segment repeats segment 0.
    for (int ring = 0; ring <= rings; ++ring) {
        const double theta = M_PI * ring / rings;
        for (int segment = 0; segment <= segments; ++segment) {
            const double phi = 2.0 * M_PI * segment / segments;
            const glm::vec3 n(static_cast<float>(std::sin(theta) * std::cos(phi)),
                              static_cast<float>(std::sin(theta) * std::sin(phi)), static_cast<float>(std::cos(theta)));
            mesh.positions.push_back(centre + radius * n);
            mesh.normals.push_back(n);
        }
    }
    if (mesh.triangleNormals.size() < mesh.triangles.size()) mesh.triangleNormals.resize(mesh.triangles.size(), kNoNormals);
    const auto index = [&](int ring, int segment) { return static_cast<uint32_t>(ring * (segments + 1) + segment); };
    const auto add = [&](uint32_t a, uint32_t b, uint32_t c) {
        if (mesh.positions[first + a] == mesh.positions[first + b] || mesh.positions[first + b] == mesh.positions[first + c] ||
            mesh.positions[first + a] == mesh.positions[first + c]) {
            return;  // the poles' degenerate halves
        }
        mesh.triangles.push_back({first + a, first + b, first + c});
        mesh.triangleMaterials.push_back(material);
        mesh.triangleNormals.push_back({firstNormal + a, firstNormal + b, firstNormal + c});
    };
    for (int ring = 0; ring < rings; ++ring) {
        for (int segment = 0; segment < segments; ++segment) {
            // Counter-clockwise seen from outside: down the ring, then along increasing phi.
            add(index(ring, segment), index(ring + 1, segment), index(ring + 1, segment + 1));
            add(index(ring, segment), index(ring + 1, segment + 1), index(ring, segment + 1));
        }
    }
}

MeshData furnaceMesh(const Material& material) {
    MeshData mesh;
    mesh.materials.push_back(material);
    // Each face counter-clockwise as seen from inside the cube.
    const float s = 1.0f;
    addQuad(mesh, {-s, -s, -s}, {s, -s, -s}, {s, s, -s}, {-s, s, -s}, 0);  // z = -1, faces +z
    addQuad(mesh, {-s, -s, s}, {-s, s, s}, {s, s, s}, {s, -s, s}, 0);      // z = +1, faces -z
    addQuad(mesh, {-s, -s, -s}, {-s, s, -s}, {-s, s, s}, {-s, -s, s}, 0);  // x = -1, faces +x
    addQuad(mesh, {s, -s, -s}, {s, -s, s}, {s, s, s}, {s, s, -s}, 0);      // x = +1, faces -x
    addQuad(mesh, {-s, -s, -s}, {-s, -s, s}, {s, -s, s}, {s, -s, -s}, 0);  // y = -1, faces +y
    addQuad(mesh, {-s, s, -s}, {s, s, -s}, {s, s, s}, {-s, s, s}, 0);      // y = +1, faces -y
    return mesh;
}

Ray furnaceRay() { return Ray{{0.1f, -0.05f, 0.02f}, glm::normalize(glm::vec3(0.3f, 0.2f, 1.0f))}; }

double furnaceRadiance(double albedo, double emission, int depth) {
    return emission * (1.0 - std::pow(albedo, depth + 1)) / (1.0 - albedo);
}

MeshData lambertSquareMesh(const Material& receiver) {
    MeshData mesh;
    Material emitter;
    emitter.name = "square";
    emitter.emission = glm::vec3(1.0f);
    mesh.materials = {receiver, emitter};
    addQuad(mesh, {-50, -50, 0}, {50, -50, 0}, {50, 50, 0}, {-50, 50, 0}, 0);  // faces +z
    // Counter-clockwise seen from below: its front faces the receiver.
    addQuad(mesh, {-0.5f, -0.5f, 1}, {-0.5f, 0.5f, 1}, {0.5f, 0.5f, 1}, {0.5f, -0.5f, 1}, 1);
    // The square is the only light: of radiance 1, no brighter than the default sky, which would
    // light the scene otherwise (lights/scene_lights.h).
    mesh.environment.kind = Environment::Kind::None;
    return mesh;
}

Ray rayToOrigin(const glm::vec3& from) { return Ray{from, glm::normalize(-from)}; }

std::vector<double> pixelEstimates(const PathIntegrator& integrator, const Ray& ray, int pixels,
                                   uint32_t passes, uint64_t seed) {
    std::vector<double> estimates;
    estimates.reserve(pixels);
    for (int pixel = 0; pixel < pixels; ++pixel) {
        double sum = 0.0;
        uint64_t rays = 0;
        for (uint32_t pass = 0; pass < passes; ++pass) {
            for (int step = 0; step < 24; ++step) {
                const PathSamples samples(seed, static_cast<uint64_t>(pixel), pass, step);
                sum += luminance(glm::dvec3(integrator.radiance(ray, samples, rays)));
            }
        }
        estimates.push_back(sum / (24.0 * passes));
    }
    return estimates;
}

}  // namespace strata::test
