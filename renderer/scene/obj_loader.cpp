#include "scene/obj_loader.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <set>
#include <string_view>
#include <vector>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <tiny_obj_loader.h>

#include "util/error.h"
#include "materials/microfacet.h"
#include "util/text_file.h"

namespace strata {
namespace {

std::vector<std::string_view> splitWords(std::string_view line) {
    std::vector<std::string_view> words;
    size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
        size_t j = i;
        while (j < line.size() && line[j] != ' ' && line[j] != '\t' && line[j] != '\r') ++j;
        if (j > i) words.push_back(line.substr(i, j - i));
        i = j;
    }
    return words;
}

enum class NumberKind { Finite, NonFinite, OutOfRange, Invalid };

// What a word holds as a number. tinyobjloader reads "nan" and "inf" as 0 and converts doubles
// beyond float range to float (undefined behaviour), so both must be caught here, before it reads
// them: a vertex coordinate "nan"/"inf" marks the vertex non-finite (its triangles are dropped and
// counted), anything else that is not a finite float is an error on its line.
NumberKind classifyNumber(std::string_view word) {
    double value;
    if (!word.empty() && word.front() == '+') word.remove_prefix(1);
    const auto result = std::from_chars(word.data(), word.data() + word.size(), value);
    if (result.ptr != word.data() + word.size() || word.empty()) return NumberKind::Invalid;
    if (result.ec == std::errc::result_out_of_range) return NumberKind::OutOfRange;
    if (result.ec != std::errc()) return NumberKind::Invalid;
    if (!std::isfinite(value)) return NumberKind::NonFinite;
    return std::abs(value) <= std::numeric_limits<float>::max() ? NumberKind::Finite
                                                                 : NumberKind::OutOfRange;
}

bool isInteger(std::string_view word) {
    long value;
    const auto result = std::from_chars(word.data(), word.data() + word.size(), value);
    return result.ec == std::errc() && result.ptr == word.data() + word.size() && value != 0;
}

// A face corner: v, v/vt, v//vn or v/vt/vn, with non-zero (possibly negative) integers.
bool isFaceCorner(std::string_view word) {
    std::vector<std::string_view> parts;
    size_t start = 0;
    for (size_t i = 0; i <= word.size(); ++i) {
        if (i == word.size() || word[i] == '/') {
            parts.push_back(word.substr(start, i - start));
            start = i + 1;
        }
    }
    if (parts.size() > 3 || !isInteger(parts[0])) return false;
    for (size_t i = 1; i < parts.size(); ++i) {
        if (!parts[i].empty() && !isInteger(parts[i])) return false;
    }
    return true;
}

[[noreturn]] void failAt(const std::string& name, size_t line, const std::string& message) {
    throw Error(name + ":" + std::to_string(line) + ": " + message);
}

template <typename Visit>
void forEachLine(const std::string& text, Visit visit) {
    size_t lineNumber = 0;
    size_t start = 0;
    while (start <= text.size()) {
        size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        ++lineNumber;
        std::string_view line(text.data() + start, end - start);
        if (const auto hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
        const auto words = splitWords(line);
        if (!words.empty()) visit(lineNumber, words);
        start = end + 1;
    }
}

// Checks the count and the values of a line's numbers. Returns whether they are all finite;
// a non-finite one is an error unless `allowNonFinite`.
bool checkNumbers(const std::string& name, size_t line, const std::vector<std::string_view>& words,
                  size_t minCount, size_t maxCount, bool allowNonFinite = false) {
    const size_t count = words.size() - 1;
    if (count < minCount || count > maxCount) {
        failAt(name, line, "'" + std::string(words[0]) + "' takes " + std::to_string(minCount) +
                               (maxCount > minCount ? " to " + std::to_string(maxCount) : "") +
                               " numbers, got " + std::to_string(count));
    }
    bool finite = true;
    for (size_t i = 1; i < words.size(); ++i) {
        const std::string word(words[i]);
        switch (classifyNumber(words[i])) {
            case NumberKind::Finite: break;
            case NumberKind::NonFinite:
                if (!allowNonFinite) failAt(name, line, "'" + word + "' is not a finite number");
                finite = false;
                break;
            case NumberKind::OutOfRange:
                failAt(name, line, "'" + word + "' is out of range for a 32-bit float");
            case NumberKind::Invalid: failAt(name, line, "'" + word + "' is not a number");
        }
    }
    return finite;
}

struct ObjScan {
    std::vector<std::string> libraries;     // mtllib file names
    std::vector<size_t> nonFiniteVertices;  // 0-based indices of vertices with a nan/inf coordinate
};

ObjScan validateObj(const std::string& text, const std::string& name) {
    ObjScan scan;
    size_t vertices = 0;
    forEachLine(text, [&](size_t line, const std::vector<std::string_view>& words) {
        const std::string_view key = words[0];
        if (key == "v") {
            // x y z [w] or x y z r g b
            if (!checkNumbers(name, line, words, 3, 7, true)) scan.nonFiniteVertices.push_back(vertices);
            ++vertices;
        } else if (key == "vn") {
            checkNumbers(name, line, words, 3, 3);
        } else if (key == "vt") {
            checkNumbers(name, line, words, 1, 3);
        } else if (key == "f") {
            if (words.size() < 4) failAt(name, line, "a face needs at least 3 vertices");
            for (size_t i = 1; i < words.size(); ++i) {
                if (!isFaceCorner(words[i])) {
                    failAt(name, line, "'" + std::string(words[i]) + "' is not a face vertex");
                }
                long index = 0;
                std::from_chars(words[i].data(), words[i].data() + words[i].size(), index);
                const long resolved = index > 0 ? index : static_cast<long>(vertices) + 1 + index;
                if (resolved < 1 || resolved > static_cast<long>(vertices)) {
                    failAt(name, line, "vertex index " + std::to_string(index) +
                                           " is out of range (" + std::to_string(vertices) +
                                           " vertices so far)");
                }
            }
        } else if (key == "mtllib") {
            if (words.size() < 2) failAt(name, line, "mtllib needs a file name");
            for (size_t i = 1; i < words.size(); ++i) scan.libraries.emplace_back(words[i]);
        } else if (key == "usemtl") {
            if (words.size() != 2) failAt(name, line, "usemtl needs one material name");
        }
    });
    return scan;
}

// Returns the names of the materials that give a roughness Pr (the others take it from Ns:
// tinyobjloader reads an absent Pr as 0, which cannot be told from an explicit 0).
std::set<std::string> validateMtl(const std::string& text, const std::string& name) {
    bool inMaterial = false;
    std::string material;
    std::set<std::string> withRoughness;
    forEachLine(text, [&](size_t line, const std::vector<std::string_view>& words) {
        const std::string_view key = words[0];
        if (key == "newmtl") {
            if (words.size() != 2) failAt(name, line, "newmtl needs one material name");
            inMaterial = true;
            material = std::string(words[1]);
            return;
        }
        if (key == "Pr" && inMaterial) withRoughness.insert(material);
        const bool colour = key == "Kd" || key == "Ke" || key == "Ks" || key == "Ka" ||
                            key == "Tf" || key == "Kt";
        const bool scalar = key == "Ns" || key == "Ni" || key == "d" || key == "Tr" ||
                            key == "Pr" || key == "Pm" || key == "illum";
        if ((colour || scalar) && !inMaterial) {
            failAt(name, line, "'" + std::string(key) + "' before any newmtl");
        }
        if (colour) checkNumbers(name, line, words, 1, 3);
        if (scalar) checkNumbers(name, line, words, 1, 1);
    });
    return withRoughness;
}

// The text with every comment ('#' to the end of its line) removed, as forEachLine reads it.
std::string withoutComments(const std::string& text) {
    std::string kept;
    kept.reserve(text.size());
    size_t start = 0;
    while (start < text.size()) {
        size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        const std::string_view line(text.data() + start, end - start);
        kept.append(line.substr(0, line.find('#')));
        if (end < text.size()) kept += '\n';
        start = end + 1;
    }
    return kept;
}

bool isFinite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Builds the mesh from text that validateObj and validateMtl have accepted.
MeshData buildMesh(const std::string& objText, const std::string& objName,
                   const std::string& mtlText, const std::string& mtlName, const ObjScan& scan,
                   const std::set<std::string>& withRoughness, LoadReport* report) {
    tinyobj::ObjReaderConfig config;
    config.triangulate = true;
    config.vertex_color = false;
    tinyobj::ObjReader reader;
    // tinyobjloader reads '#' as a comment only at the start of a line; the checks above read it
    // anywhere. It must parse what was checked, or "f 1 2 3 # 5" reads a face the checks never saw
    // (a fuzzer finding: an index past the last vertex read out of bounds).
    if (!reader.ParseFromString(withoutComments(objText), withoutComments(mtlText), config)) {
        std::string error = reader.Error();
        while (!error.empty() && (error.back() == '\n' || error.back() == '\r')) error.pop_back();
        throw Error(objName + ": " + (error.empty() ? "cannot parse" : error));
    }
    // tinyobjloader reports a usemtl of an undefined material only as a warning; it is an error
    // here, since the faces would silently lose their material.
    if (const auto& warning = reader.Warning(); warning.find("material [") != std::string::npos) {
        const auto end = warning.find('\n');
        throw Error(objName + ": " + warning.substr(0, end) + " in " + mtlName);
    }

    MeshData mesh;
    const auto& attrib = reader.GetAttrib();
    mesh.positions.reserve(attrib.vertices.size() / 3);
    for (size_t i = 0; i + 2 < attrib.vertices.size(); i += 3) {
        mesh.positions.emplace_back(attrib.vertices[i], attrib.vertices[i + 1], attrib.vertices[i + 2]);
    }
    // tinyobjloader read these as 0; restore them as non-finite so that their triangles are dropped.
    for (size_t v : scan.nonFiniteVertices) {
        if (v < mesh.positions.size()) mesh.positions[v] = glm::vec3(std::numeric_limits<float>::quiet_NaN());
    }
    for (const auto& m : reader.GetMaterials()) {
        Material material;
        material.name = m.name;
        material.diffuse = {m.diffuse[0], m.diffuse[1], m.diffuse[2]};
        material.emission = {m.emission[0], m.emission[1], m.emission[2]};
        material.specular = {m.specular[0], m.specular[1], m.specular[2]};
        material.roughness = withRoughness.count(m.name) ? m.roughness
                                                         : roughnessFromShininess(m.shininess);
        if (!isFinite(material.diffuse) || !isFinite(material.emission) ||
            !isFinite(material.specular) || !std::isfinite(material.roughness) ||
            glm::min(glm::min(material.diffuse.x, material.diffuse.y), material.diffuse.z) < 0.0f ||
            glm::min(glm::min(material.emission.x, material.emission.y), material.emission.z) < 0.0f ||
            glm::min(glm::min(material.specular.x, material.specular.y), material.specular.z) < 0.0f) {
            throw Error(mtlName + ": material '" + m.name +
                        "' has a negative or non-finite Kd, Ke, Ks or Pr");
        }
        if (glm::max(glm::max(material.diffuse.x, material.diffuse.y), material.diffuse.z) > 1.0f) {
            throw Error(mtlName + ": material '" + m.name + "' has Kd above 1 (creates energy)");
        }
        if (glm::max(glm::max(material.specular.x, material.specular.y), material.specular.z) > 1.0f) {
            throw Error(mtlName + ": material '" + m.name + "' has Ks above 1 (creates energy)");
        }
        if (material.roughness < 0.0f || material.roughness > 1.0f) {
            throw Error(mtlName + ": material '" + m.name + "' has Pr outside 0..1");
        }
        mesh.materials.push_back(material);
    }
    // Faces without a material get a neutral grey; it is appended only when used.
    const auto defaultMaterial = static_cast<uint32_t>(mesh.materials.size());
    bool defaultUsed = false;

    size_t dropped = 0;
    for (const auto& shape : reader.GetShapes()) {
        const auto& indices = shape.mesh.indices;
        for (size_t f = 0; f < shape.mesh.num_face_vertices.size(); ++f) {
            const std::array<uint32_t, 3> tri{static_cast<uint32_t>(indices[3 * f].vertex_index),
                                              static_cast<uint32_t>(indices[3 * f + 1].vertex_index),
                                              static_cast<uint32_t>(indices[3 * f + 2].vertex_index)};
            // validateObj checked every index, so this guards only against tinyobjloader reading
            // a line differently from it.
            for (uint32_t index : tri) {
                if (index >= mesh.positions.size()) throw Error(objName + ": a face refers to a missing vertex");
            }
            const glm::vec3& a = mesh.positions[tri[0]];
            const glm::vec3& b = mesh.positions[tri[1]];
            const glm::vec3& c = mesh.positions[tri[2]];
            const glm::vec3 n = glm::cross(b - a, c - a);
            if (!isFinite(a) || !isFinite(b) || !isFinite(c) || !isFinite(n) ||
                !(glm::dot(n, n) > 0.0f)) {
                ++dropped;
                continue;
            }
            const int materialId = shape.mesh.material_ids[f];
            uint32_t material = defaultMaterial;
            if (materialId >= 0) {
                material = static_cast<uint32_t>(materialId);
            } else {
                defaultUsed = true;
            }
            mesh.triangles.push_back(tri);
            mesh.triangleMaterials.push_back(material);
        }
    }
    if (defaultUsed) mesh.materials.push_back({"(default)", glm::vec3(0.5f), glm::vec3(0.0f)});
    if (report) {
        report->faces = mesh.triangles.size();
        report->droppedTriangles = dropped;
        report->nonFiniteVertices = scan.nonFiniteVertices.size();
    }
    return mesh;
}

}  // namespace

MeshData parseObj(const std::string& objText, const std::string& objName,
                  const std::string& mtlText, const std::string& mtlName, LoadReport* report) {
    const ObjScan scan = validateObj(objText, objName);
    return buildMesh(objText, objName, mtlText, mtlName, scan, validateMtl(mtlText, mtlName), report);
}

std::vector<SceneFile> readObjScene(const std::filesystem::path& path) {
    std::vector<SceneFile> files{{path.filename().string(), readTextFile(path, "scene")}};
    for (const auto& library : validateObj(files.front().bytes, path.string()).libraries) {
        const bool read = std::any_of(files.begin(), files.end(),
                                      [&](const SceneFile& file) { return file.name == library; });
        if (read) continue;
        files.push_back({library, readTextFile(path.parent_path() / library,
                                               "material library (named by mtllib)")});
    }
    return files;
}

MeshData parseObjScene(const SceneBundle& bundle, LoadReport* report) {
    const SceneFile& obj = bundle.files.front();
    const std::string objName = bundle.pathOf(obj.name);
    const ObjScan scan = validateObj(obj.bytes, objName);
    // Each MTL file is validated on its own, so that a bad line is reported with its file and line;
    // tinyobjloader then reads them joined, as the OBJ's mtllib lines load them one after another.
    // A file's material lines all follow a newmtl of its own (validateMtl), so the materials that
    // give Pr in the joined text are those of the files together.
    std::string mtlText;
    std::string mtlName;
    std::set<std::string> withRoughness;
    for (const auto& library : scan.libraries) {
        const std::string name = bundle.pathOf(library);
        const SceneFile* mtl = bundle.find(library);
        if (!mtl) throw Error(name + ": material library (named by mtllib) not among the scene's files");
        withRoughness.merge(validateMtl(mtl->bytes, name));
        mtlText += mtl->bytes;
        mtlText += '\n';
        if (!mtlName.empty()) mtlName += ',';
        mtlName += name;
    }
    if (mtlName.empty()) mtlName = objName;
    return buildMesh(obj.bytes, objName, mtlText, mtlName, scan, withRoughness, report);
}

MeshData loadObjFile(const std::filesystem::path& path, LoadReport* report) {
    return parseObjScene(SceneBundle{path, readObjScene(path), std::nullopt, std::nullopt}, report);
}

}  // namespace strata
