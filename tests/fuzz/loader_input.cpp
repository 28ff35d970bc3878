#include "loader_input.h"

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <glm/geometric.hpp>

#include "scene/scene_description.h"
#include "scene/scene_format.h"
#include "util/error.h"

namespace strata::fuzz {
namespace {

void require(bool promise, const char* what) {
    if (!promise) throw std::logic_error(std::string("the scene loader returned a mesh with ") + what);
}

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// What a loader promises of every mesh it returns (scene_format.h, mesh.h), which the renderer
// relies on: indices in range, one material per triangle, finite vertices and a non-zero float
// area on every kept triangle, Kd in [0, 1] and finite Ke >= 0, shading normals of unit length
// (none, or three or kNoNormals per triangle) and warnings of one line each.
void checkMesh(const MeshData& mesh, const LoadReport& report) {
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
        require(!warning.empty() && warning.find('\n') == std::string::npos, "a warning not of one line");
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
    }
}

std::string_view nextPart(std::string_view& rest) {
    const size_t end = rest.find('\0');
    const std::string_view part = rest.substr(0, end);
    rest = end == std::string_view::npos ? std::string_view() : rest.substr(end + 1);
    return part;
}

}  // namespace

void parseLoaderInput(std::string_view input) {
    // The OBJ's "mtllib fuzz.mtl" loads the MTL part, as from files; its texture statements and
    // the glTF's image URIs find the texture part as fuzz.png.
    const std::string obj(nextPart(input));
    const std::string mtl(nextPart(input));
    const std::string json(nextPart(input));
    const std::string gltf(nextPart(input));
    const SceneFile texture{"fuzz.png", std::string(input)};
    SceneBundle bundle{"fuzz.obj", {{"fuzz.obj", obj}, {"fuzz.mtl", mtl}, texture}, std::nullopt, std::nullopt};
    try {
        LoadReport report;
        const MeshData mesh = parseSceneMesh(bundle, &report);
        checkMesh(mesh, report);
    } catch (const Error&) {
    }
    if (!gltf.empty()) {
        const SceneBundle gltfBundle{"fuzz.gltf", {{"fuzz.gltf", gltf}, texture}, std::nullopt, std::nullopt};
        try {
            LoadReport report;
            const MeshData mesh = parseSceneMesh(gltfBundle, &report);
            checkMesh(mesh, report);
        } catch (const Error&) {
        }
    }
    try {
        const SceneDescription description = parseSceneDescription(json, "fuzz.json");
        if (description.camera.width < 1 || description.camera.height < 1) {
            throw std::logic_error("camera size below 1");
        }
    } catch (const Error&) {
    }
}

}  // namespace strata::fuzz
