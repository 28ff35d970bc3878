#include "bench/reference_cache.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <map>
#include <utility>
#include <vector>
#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>

#include "util/error.h"

namespace strata {
namespace {

class Fnv1a {
public:
    void add(const void* data, size_t size) {
        const auto* bytes = static_cast<const unsigned char*>(data);
        for (size_t i = 0; i < size; ++i) {
            hash_ ^= bytes[i];
            hash_ *= 0x100000001b3ull;
        }
    }
    template <typename T>
    void addValue(const T& value) { add(&value, sizeof value); }
    void addFile(const std::filesystem::path& path) {
        std::ifstream in(path, std::ios::binary);
        if (!in) throw Error(path.string() + ": cannot read it to key the reference");
        const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
        const uint64_t size = bytes.size();
        addValue(size);  // separates one file's bytes from the next
        add(bytes.data(), bytes.size());
    }
    uint64_t value() const { return hash_; }

private:
    uint64_t hash_ = 0xcbf29ce484222325ull;
};

// Every edge of a closed, consistently oriented mesh appears once in each direction.
bool closedAndOriented(const MeshData& mesh) {
    std::map<std::pair<uint32_t, uint32_t>, int> directed;
    for (const auto& tri : mesh.triangles) {
        for (int e = 0; e < 3; ++e) ++directed[{tri[e], tri[(e + 1) % 3]}];
    }
    for (const auto& [edge, count] : directed) {
        if (count != 1) return false;
        const auto reverse = directed.find({edge.second, edge.first});
        if (reverse == directed.end()) return false;
    }
    return true;
}

}  // namespace

std::optional<glm::vec3> furnaceRadiance(const Scene& scene, const CameraPose& camera,
                                         const PathIntegratorSettings& integrator) {
    const MeshData& mesh = scene.mesh();
    if (integrator.nextEventEstimation && !mesh.pointLights.empty()) return std::nullopt;
    const Material& first = scene.material(0);
    for (uint32_t t = 0; t < mesh.triangles.size(); ++t) {
        const Material& m = scene.material(t);
        if (m.diffuse != first.diffuse || m.emission != first.emission) return std::nullopt;
    }
    const glm::vec3 rho = first.diffuse;
    if (!(glm::all(glm::lessThan(rho, glm::vec3(1.0f))))) return std::nullopt;
    if (!closedAndOriented(mesh)) return std::nullopt;
    // Inside: rays from the camera along the six axes all meet front faces (which face inward).
    for (int axis = 0; axis < 6; ++axis) {
        glm::vec3 direction(0.0f);
        direction[axis % 3] = axis < 3 ? 1.0f : -1.0f;
        const auto hit = scene.intersect(Ray{camera.position, direction});
        if (!hit || glm::dot(scene.triangle(hit->triangle).normal, direction) >= 0.0f) return std::nullopt;
    }
    glm::vec3 radiance;
    for (int c = 0; c < 3; ++c) {
        const double r = rho[c];
        radiance[c] = static_cast<float>(first.emission[c] * (1.0 - std::pow(r, integrator.depth + 1)) /
                                         (1.0 - r));
    }
    return radiance;
}

uint64_t referenceKey(const LoadedScene& loaded, const Camera& camera,
                      const PathIntegratorSettings& integrator) {
    Fnv1a hash;
    constexpr uint32_t kKeyVersion = 1;  // bump when the renderer's output changes meaning
    hash.addValue(kKeyVersion);
    hash.addFile(loaded.objPath);
    std::vector<std::filesystem::path> materials;
    const auto folder = loaded.objPath.has_parent_path() ? loaded.objPath.parent_path()
                                                         : std::filesystem::path(".");
    for (const auto& entry : std::filesystem::directory_iterator(folder)) {
        if (entry.path().extension() == ".mtl") materials.push_back(entry.path());
    }
    std::sort(materials.begin(), materials.end());
    for (const auto& m : materials) hash.addFile(m);
    if (!loaded.cameraPath.empty()) hash.addFile(loaded.cameraPath);
    const CameraPose& pose = camera.pose();
    for (const glm::vec3& v : {pose.position, pose.lookAt, pose.up}) {
        hash.addValue(v.x);
        hash.addValue(v.y);
        hash.addValue(v.z);
    }
    hash.addValue(pose.fovYDegrees);
    hash.addValue(camera.width());
    hash.addValue(camera.height());
    hash.addValue(integrator.depth);
    const uint8_t nee = integrator.nextEventEstimation ? 1 : 0;
    hash.addValue(nee);
    return hash.value();
}

std::string sceneName(const std::filesystem::path& objPath) {
    const std::string stem = objPath.stem().string();
    if (stem == "scene" && objPath.has_parent_path()) {
        const std::string folder = objPath.parent_path().filename().string();
        if (!folder.empty()) return folder;
    }
    return stem;
}

std::filesystem::path referencePath(const std::filesystem::path& dir, const LoadedScene& loaded,
                                    const Camera& camera, const PathIntegratorSettings& integrator) {
    char key[17];
    std::snprintf(key, sizeof key, "%016llx",
                  static_cast<unsigned long long>(referenceKey(loaded, camera, integrator)));
    return dir / (sceneName(loaded.objPath) + "-d" + std::to_string(integrator.depth) +
                  (integrator.nextEventEstimation ? "-nee-" : "-") + key + ".exr");
}

}  // namespace strata
