#include "loader_input.h"

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "scene/scene_description.h"
#include "scene/scene_loader.h"
#include "util/error.h"

namespace strata::fuzz {
namespace {

void require(bool promise, const char* what) {
    if (!promise) throw std::logic_error(std::string("the scene loader returned a scene with ") + what);
}

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Whether every value of a texture is finite and >= 0, as the loaders make them (scene_textures.h).
bool finiteNonNegative(const Texture& texture) {
    for (int y = 0; y < texture.height(); ++y) {
        for (int x = 0; x < texture.width(); ++x) {
            const glm::vec4 t = texture.texel(x, y);
            if (!(finite(glm::vec3(t)) && std::isfinite(t.w) && glm::min(glm::min(t.x, t.y), glm::min(t.z, t.w)) >= 0.0f)) {
                return false;
            }
        }
    }
    return true;
}

// What a loader promises of every scene it returns (scene_format.h, mesh.h), which the renderer
// relies on: indices in range, one material per triangle, finite vertices and a non-zero float
// area on every kept triangle, Kd in [0, 1], finite Ke >= 0 and textures of finite values >= 0,
// shading normals of unit length (none, or three or kNoNormals per triangle), lights of finite
// positions and intensities >= 0, and warnings of one line each.
void checkScene(const SceneContents& contents) {
    const MeshData& mesh = contents.parsed.mesh;
    const LoadReport& report = contents.report;
    require(mesh.triangleMaterials.size() == mesh.triangles.size(), "not one material per triangle");
    require(report.faces == mesh.triangles.size(), "a wrong face count");
    require(mesh.triangleNormals.empty() || mesh.triangleNormals.size() == mesh.triangles.size(),
            "not one normal triple per triangle");
    require(mesh.triangleUvs.empty() || mesh.triangleUvs.size() == mesh.triangles.size(),
            "not one texture coordinate triple per triangle");
    for (const auto& corners : mesh.triangleUvs) {
        if (corners == kNoUvs) continue;
        for (uint32_t index : corners) require(index < mesh.uvs.size(), "a texture coordinate index out of range");
    }
    for (const auto& corners : mesh.triangleNormals) {
        if (corners == kNoNormals) continue;
        for (uint32_t index : corners) require(index < mesh.normals.size(), "a normal index out of range");
    }
    for (const glm::vec3& n : mesh.normals) {
        require(finite(n) && std::abs(glm::length(n) - 1.0f) < 1e-5f, "a normal not of unit length");
    }
    for (const std::string& warning : report.warnings) {
        require(!warning.empty() && warning.find_first_of("\n\r") == std::string::npos, "a warning not of one line");
    }
    for (size_t i = 0; i < mesh.triangles.size(); ++i) {
        require(mesh.triangleMaterials[i] < mesh.materials.size(), "a material index out of range");
        for (uint32_t index : mesh.triangles[i]) {
            require(index < mesh.positions.size(), "a vertex index out of range");
            require(finite(mesh.positions[index]), "a non-finite vertex in a triangle");
        }
        const auto& t = mesh.triangles[i];
        const glm::vec3 n = glm::cross(mesh.positions[t[1]] - mesh.positions[t[0]],
                                       mesh.positions[t[2]] - mesh.positions[t[0]]);
        require(glm::dot(n, n) > 0.0f, "a zero-area triangle");
    }
    for (const Material& m : mesh.materials) {
        for (int c = 0; c < 3; ++c) {
            require(m.diffuse[c] >= 0.0f && m.diffuse[c] <= 1.0f, "a Kd outside [0, 1]");
            require(m.emission[c] >= 0.0f && std::isfinite(m.emission[c]), "a negative or non-finite Ke");
        }
        require(std::isfinite(m.textures.normalScale), "a non-finite normal map scale");
        const MaterialTextures& maps = m.textures;
        for (const auto* texture : {&maps.colour, &maps.roughness, &maps.metallic, &maps.emission, &maps.coverage, &maps.normal}) {
            require(!*texture || finiteNonNegative(**texture), "a texture value not finite and >= 0");
        }
    }
    const auto light = [](const glm::vec3& where, const glm::vec3& power) {
        require(finite(where) && finite(power) && glm::min(glm::min(power.x, power.y), power.z) >= 0.0f,
                "a light not finite or of negative intensity");
    };
    for (const PointLight& l : mesh.pointLights) light(l.position, l.intensity);
    for (const DirectionalLight& l : mesh.directionalLights) light(l.direction, l.irradiance);
    const Environment& environment = mesh.environment;
    require(std::isfinite(environment.rotationDegrees) && finite(environment.radiance) &&
                glm::min(glm::min(environment.radiance.x, environment.radiance.y), environment.radiance.z) >= 0.0f,
            "an environment not finite or of negative radiance");
    require(contents.settings.width >= 1 && contents.settings.height >= 1, "a camera size below 1");
}

// The next part of the input, the rest when no separator follows.
std::string nextPart(std::string_view& rest) {
    const size_t end = rest.find(kPartSeparator);
    const std::string part(rest.substr(0, end));
    rest = end == std::string_view::npos ? std::string_view() : rest.substr(end + kPartSeparator.size());
    return part;
}

void parseBundle(const SceneBundle& bundle) {
    try {
        checkScene(parseSceneContents(bundle));
    } catch (const Error&) {
    }
}

}  // namespace

void parseLoaderInput(std::string_view input) {
    // The OBJ's "mtllib fuzz.mtl" loads the MTL part, as from files; its texture statements and
    // the glTF's image URIs find the texture part as fuzz.png, the description's environment
    // {"file": "sky.exr"} the environment part.
    const std::string obj = nextPart(input);
    const std::string mtl = nextPart(input);
    const std::string json = nextPart(input);
    const std::string gltf = nextPart(input);
    const SceneFile texture{"fuzz.png", nextPart(input)};
    const SceneFile environment{"sky.exr", nextPart(input)};
    SceneBundle objBundle{"fuzz.obj", {{"fuzz.obj", obj}, {"fuzz.mtl", mtl}, texture, environment}, std::nullopt,
                          std::nullopt};
    if (!json.empty()) objBundle.description = SceneFile{"fuzz.json", json};
    parseBundle(objBundle);
    if (!gltf.empty()) parseBundle(SceneBundle{"fuzz.gltf", {{"fuzz.gltf", gltf}, texture, environment}, std::nullopt,
                                               std::nullopt});
    try {
        const SceneDescription description = parseSceneDescription(json, "fuzz.json");
        if (description.camera.width < 1 || description.camera.height < 1) {
            throw std::logic_error("camera size below 1");
        }
    } catch (const Error&) {
    }
}

}  // namespace strata::fuzz
