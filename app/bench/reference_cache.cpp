#include "bench/reference_cache.h"

#include <cmath>
#include <cstdio>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>

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
    void addText(const std::string& text) {
        const uint64_t size = text.size();
        addValue(size);  // separates one text from the next
        add(text.data(), text.size());
    }
    void addFile(const SceneFile& file) {
        addText(file.name);
        addText(file.bytes);
    }
    // Whether the file is there, then the file, so that the same bytes as the description or as
    // the camera file key differently.
    void addFile(const std::optional<SceneFile>& file) {
        const uint8_t present = file ? 1 : 0;
        addValue(present);
        if (file) addFile(*file);
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
    const uint64_t files = loaded.bundle.files.size();
    hash.addValue(files);
    for (const SceneFile& file : loaded.bundle.files) hash.addFile(file);
    hash.addFile(loaded.bundle.description);
    hash.addFile(loaded.bundle.camera);
    const CameraPose& pose = camera.pose();
    for (const glm::vec3& v : {pose.position, pose.lookAt, pose.up}) {
        hash.addValue(v.x);
        hash.addValue(v.y);
        hash.addValue(v.z);
    }
    hash.addValue(pose.fovYDegrees);
    // A lens, where there is one: a pinhole adds nothing, so keys made before lenses still hold.
    if (camera.hasLens()) {
        hash.addValue(pose.apertureRadius);
        hash.addValue(pose.focusDistance);
    }
    hash.addValue(camera.width());
    hash.addValue(camera.height());
    hash.addValue(integrator.depth);
    const uint8_t nee = integrator.nextEventEstimation ? 1 : 0;
    hash.addValue(nee);
    // The sky the scene is lit by, which options (--env-color, --env) give outside its files. A
    // scene that is dark outside adds nothing, so keys made before skies were hashed still hold.
    const Environment& environment = loaded.scene.lights().environment();
    if (environment.kind == Environment::Kind::Uniform) {
        hash.addValue(environment.radiance.x);
        hash.addValue(environment.radiance.y);
        hash.addValue(environment.radiance.z);
    } else if (environment.kind == Environment::Kind::Map) {
        hash.addValue(environment.rotationDegrees);
        for (const glm::vec3& texel : environment.map->image().pixels) hash.addValue(texel);
    }
    return hash.value();
}

std::string sceneName(const std::filesystem::path& scenePath) {
    const std::string stem = scenePath.stem().string();
    if (stem == "scene" && scenePath.has_parent_path()) {
        const std::string folder = scenePath.parent_path().filename().string();
        if (!folder.empty()) return folder;
    }
    return stem;
}

std::filesystem::path referencePath(const std::filesystem::path& dir, const LoadedScene& loaded,
                                    const Camera& camera, const PathIntegratorSettings& integrator) {
    char key[17];
    std::snprintf(key, sizeof key, "%016llx",
                  static_cast<unsigned long long>(referenceKey(loaded, camera, integrator)));
    return dir / (sceneName(loaded.scenePath()) + "-d" + std::to_string(integrator.depth) +
                  (integrator.nextEventEstimation ? "-nee-" : "-") + key + ".exr");
}

Reference renderedReference(Image mean, const Image& firstHalf, std::string kind) {
    const ImageError own = imageError(firstHalf, mean);
    return Reference{std::nullopt, std::move(mean), std::move(kind), own};
}

ImageError measure(const Image& image, const Reference& reference) {
    ImageError error = reference.constant ? imageError(image, *reference.constant)
                                          : imageError(image, reference.image);
    error.mse = std::max(0.0, error.mse - reference.own.mse);
    error.relMse = std::max(0.0, error.relMse - reference.own.relMse);
    error.rmse = std::sqrt(error.mse);
    return error;
}

}  // namespace strata
