#include "bench/cycles_inputs.h"

#include <cmath>
#include <cstdint>
#include <algorithm>
#include <array>
#include <cstring>
#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/matrix.hpp>
#include <fstream>
#include <iomanip>
#include <iterator>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "io/image_io.h"
#include "util/constants.h"
#include "util/error.h"

namespace strata {
namespace {

uint32_t readU32(const std::string& bytes, size_t at) {
    uint32_t value = 0;
    std::memcpy(&value, bytes.data() + at, 4);  // glTF is little-endian, as every target here
    return value;
}

void appendU32(std::string& bytes, uint32_t value) {
    char raw[4];
    std::memcpy(raw, &value, 4);
    bytes.append(raw, 4);
}

}  // namespace

void writeLinearTexture(const Texture& texture, const std::filesystem::path& exr) {
    Image image;
    image.width = texture.width();
    image.height = texture.height();
    image.pixels.reserve(static_cast<size_t>(image.width) * image.height);
    for (int y = 0; y < image.height; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const glm::vec4 texel = texture.texel(x, y);
            image.pixels.emplace_back(texel.x, texel.y, texel.z);
        }
    }
    writeImage(exr, image);
}

glm::mat3 cyclesEnvironmentFrame(float rotationDegrees) {
    // Into the map's frame first: Strata turns the map by alpha about +y, so a world direction is
    // turned by -alpha (x' = cos x - sin z, z' = sin x + cos z).
    const float c = std::cos(rotationDegrees * (kPi / 180.0f));
    const float s = std::sin(rotationDegrees * (kPi / 180.0f));
    const glm::mat3 unturn(glm::vec3(c, 0.0f, s), glm::vec3(0.0f, 1.0f, 0.0f), glm::vec3(-s, 0.0f, c));  // columns
    // Then the map's axes onto Cycles': up +y -> +z, the centre -z -> +x, and +x (phi = pi/2,
    // u = 3/4 in both) -> -y.
    const glm::mat3 axes(glm::vec3(0.0f, -1.0f, 0.0f), glm::vec3(0.0f, 0.0f, 1.0f), glm::vec3(-1.0f, 0.0f, 0.0f));
    return axes * unturn;
}

void writeMeshObj(const MeshData& mesh, const std::filesystem::path& obj) {
    std::ofstream out(obj);
    out << std::setprecision(9);  // floats to the last bit
    const std::filesystem::path mtl = std::filesystem::path(obj).replace_extension(".mtl");
    out << "mtllib " << mtl.filename().string() << "\n";
    // Every triangle once, and those of a shared mesh at each placement.
    std::vector<std::pair<size_t, glm::mat4>> drawn;
    std::vector<bool> shared(mesh.triangles.size(), false);
    for (const SharedMesh& s : mesh.sharedMeshes) {
        for (uint32_t t = s.firstTriangle; t < s.firstTriangle + s.triangleCount; ++t) {
            shared[t] = true;
            for (const glm::mat4& placement : s.placements) drawn.emplace_back(t, placement);
        }
    }
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        if (!shared[t]) drawn.emplace_back(t, glm::mat4(1.0f));
    }
    std::stable_sort(drawn.begin(), drawn.end(), [&](const auto& a, const auto& b) {
        return mesh.triangleMaterials[a.first] < mesh.triangleMaterials[b.first];
    });
    uint32_t material = UINT32_MAX;
    size_t corner = 1;  // OBJ indices count from 1
    for (const auto& [t, placement] : drawn) {
        if (mesh.triangleMaterials[t] != material) {
            material = mesh.triangleMaterials[t];
            out << "usemtl " << mesh.materials[material].name << "\n";
        }
        const glm::mat3 normalTransform = glm::transpose(glm::inverse(glm::mat3(placement)));
        // A mirroring placement keeps the front where the transformed normals point (mesh.h):
        // the corners are reversed so that the winding says so too.
        const bool mirrored = glm::determinant(glm::mat3(placement)) < 0.0f;
        const auto& v = mesh.triangles[t];
        std::array<glm::vec3, 3> p;
        for (int k = 0; k < 3; ++k) p[k] = glm::vec3(placement * glm::vec4(mesh.positions[v[k]], 1.0f));
        const bool smooth = !mesh.triangleNormals.empty() && mesh.triangleNormals[t] != kNoNormals;
        const glm::vec3 flat = glm::normalize(glm::cross(p[1] - p[0], p[2] - p[0])) * (mirrored ? -1.0f : 1.0f);
        const auto uv = cornerUvs(mesh, t);
        const std::array<int, 3> order = mirrored ? std::array<int, 3>{0, 2, 1} : std::array<int, 3>{0, 1, 2};
        for (int k : order) {
            const glm::vec3 n =
                smooth ? glm::normalize(normalTransform * mesh.normals[mesh.triangleNormals[t][k]]) : flat;
            out << "v " << p[k].x << " " << p[k].y << " " << p[k].z << "\nvn " << n.x << " " << n.y << " " << n.z
                << "\nvt " << uv[k].x << " " << uv[k].y << "\n";
        }
        out << "f";
        for (int k = 0; k < 3; ++k) out << " " << corner + k << "/" << corner + k << "/" << corner + k;
        out << "\n";
        corner += 3;
    }
    std::ofstream materials(mtl);
    for (const Material& m : mesh.materials) {
        materials << "newmtl " << m.name << "\nKd " << m.diffuse.x << " " << m.diffuse.y << " " << m.diffuse.z << "\n";
    }
    if (!out || !materials) throw Error(obj.string() + ": cannot write");
}

void writeWhiteMetalGlb(const std::filesystem::path& glb, const std::filesystem::path& out, float roughness) {
    std::ifstream in(glb, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    // The header (magic, version, length), then chunks of (length, type, data): JSON first.
    if (bytes.size() < 20 || bytes.compare(0, 4, "glTF") != 0 || readU32(bytes, 4) != 2 ||
        readU32(bytes, 16) != 0x4E4F534Au /* "JSON" */ || 20 + size_t(readU32(bytes, 12)) > bytes.size()) {
        throw Error(glb.string() + ": not a binary glTF 2.0 file");
    }
    const size_t jsonLength = readU32(bytes, 12);
    nlohmann::json gltf = nlohmann::json::parse(bytes.substr(20, jsonLength), nullptr, false);
    if (gltf.is_discarded() || !gltf.is_object()) throw Error(glb.string() + ": its JSON chunk does not parse");
    gltf["materials"] = nlohmann::json::array(
        {{{"name", "white metal"},
          {"pbrMetallicRoughness",
           {{"baseColorFactor", {1.0, 1.0, 1.0, 1.0}}, {"metallicFactor", 1.0}, {"roughnessFactor", roughness}}}}});
    if (gltf.contains("meshes")) {
        for (auto& mesh : gltf["meshes"]) {
            for (auto& primitive : mesh["primitives"]) primitive["material"] = 0;
        }
    }
    std::string json = gltf.dump();
    json.append((4 - json.size() % 4) % 4, ' ');  // chunks are 4-byte aligned, JSON padded with spaces
    const std::string rest = bytes.substr(20 + jsonLength);
    std::string written = "glTF";
    appendU32(written, 2);
    appendU32(written, static_cast<uint32_t>(12 + 8 + json.size() + rest.size()));
    appendU32(written, static_cast<uint32_t>(json.size()));
    appendU32(written, 0x4E4F534Au);
    written += json;
    written += rest;
    std::ofstream file(out, std::ios::binary);
    file.write(written.data(), static_cast<std::streamsize>(written.size()));
    if (!file) throw Error(out.string() + ": cannot write");
}

}  // namespace strata
