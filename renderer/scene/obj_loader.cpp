#include "scene/obj_loader.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <span>
#include <string_view>
#include <utility>
#include <vector>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <tiny_obj_loader.h>

#include "util/components.h"
#include "util/error.h"
#include "geometry/polygon_triangulation.h"
#include "geometry/smoothing_groups.h"
#include "materials/metallic_roughness.h"
#include "materials/microfacet.h"
#include "materials/normal_map.h"
#include "scene/mtl_texture_statement.h"
#include "scene/scene_textures.h"
#include "scene/uv_placement.h"
#include "util/printable.h"
#include "util/text_file.h"

namespace strata {
namespace {

// What faces get when no material of the MTL files applies: the grey most tools use.
constexpr float kDefaultAlbedo = 0.8f;
const char* const kDefaultMaterialNote = "using grey Kd 0.8";

// What separates a line's words.
bool isWordSeparator(char c) { return c == ' ' || c == '\t' || c == '\r'; }

// The line's words, into `words` (cleared first: forEachLine keeps one vector for every line).
void splitWords(std::string_view line, std::vector<std::string_view>& words) {
    words.clear();
    size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && isWordSeparator(line[i])) ++i;
        size_t j = i;
        while (j < line.size() && !isWordSeparator(line[j])) ++j;
        if (j > i) words.push_back(line.substr(i, j - i));
        i = j;
    }
}

// A statement's words after its keyword as one name, the spaces around it trimmed: "usemtl Hard
// Shiny Plastic" names "Hard Shiny Plastic", as assimp and Blender read it.
std::string restOfLine(const std::vector<std::string_view>& words) {
    if (words.size() < 2) return {};
    const char* end = words.back().data() + words.back().size();
    return std::string(words[1].data(), end);
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

// The value of a word classifyNumber accepted (Finite or NonFinite), rounded to a 32-bit float.
double floatOf(std::string_view word) {
    if (word.front() == '+') word.remove_prefix(1);
    double value = 0.0;
    std::from_chars(word.data(), word.data() + word.size(), value);
    return static_cast<float>(value);
}

// A face corner's indices: v, v/vt, v//vn or v/vt/vn, each a non-zero (possibly negative)
// integer; an absent vt or vn is 0. Empty when the word is not a face corner.
std::optional<std::array<long, 3>> faceCorner(std::string_view word) {
    std::array<long, 3> indices{0, 0, 0};
    size_t part = 0;
    size_t start = 0;
    for (size_t i = 0; i <= word.size(); ++i) {
        if (i < word.size() && word[i] != '/') continue;
        if (part == indices.size()) return std::nullopt;
        const std::string_view text = word.substr(start, i - start);
        if (part == 0 || !text.empty()) {
            const auto result = std::from_chars(text.data(), text.data() + text.size(), indices[part]);
            if (result.ec != std::errc() || result.ptr != text.data() + text.size() || indices[part] == 0) {
                return std::nullopt;
            }
        }
        ++part;
        start = i + 1;
    }
    return indices;
}

[[noreturn]] void failAt(const std::string& name, size_t line, const std::string& message) {
    throw Error(name + ":" + std::to_string(line) + ": " + message);
}

// UTF-16 text after its byte-order mark (big-endian or little-endian) as UTF-8; an unpaired
// surrogate becomes U+FFFD, as decoders replace what they cannot decode.
std::string utf8OfUtf16(std::string_view bytes, bool bigEndian, const std::string& name) {
    if (bytes.size() % 2 != 0) throw Error(name + ": UTF-16 text of an odd number of bytes");
    const auto unit = [&](size_t i) {
        const auto hi = static_cast<unsigned char>(bytes[bigEndian ? i : i + 1]);
        const auto lo = static_cast<unsigned char>(bytes[bigEndian ? i + 1 : i]);
        return static_cast<uint32_t>(hi << 8 | lo);
    };
    std::string text;
    text.reserve(bytes.size() / 2);
    for (size_t i = 0; i < bytes.size(); i += 2) {
        uint32_t c = unit(i);
        if (c >= 0xD800 && c < 0xDC00 && i + 2 < bytes.size() && unit(i + 2) >= 0xDC00 && unit(i + 2) < 0xE000) {
            c = 0x10000 + ((c - 0xD800) << 10) + (unit(i + 2) - 0xDC00);
            i += 2;
        } else if (c >= 0xD800 && c < 0xE000) {
            c = 0xFFFD;
        }
        if (c < 0x80) {
            text += static_cast<char>(c);
        } else if (c < 0x800) {
            text += {static_cast<char>(0xC0 | c >> 6), static_cast<char>(0x80 | (c & 0x3F))};
        } else if (c < 0x10000) {
            text += {static_cast<char>(0xE0 | c >> 12), static_cast<char>(0x80 | (c >> 6 & 0x3F)),
                     static_cast<char>(0x80 | (c & 0x3F))};
        } else {
            text += {static_cast<char>(0xF0 | c >> 18), static_cast<char>(0x80 | (c >> 12 & 0x3F)),
                     static_cast<char>(0x80 | (c >> 6 & 0x3F)), static_cast<char>(0x80 | (c & 0x3F))};
        }
    }
    return text;
}

// The file as UTF-8 text without its byte-order mark: UTF-16 with one (which some Windows tools
// write, as assimp's box_UTF16BE.obj is) decoded into `decoded`, else the file itself.
std::string_view utf8TextOf(const std::string& file, const std::string& name, std::string& decoded) {
    const std::string_view view(file);
    if (view.substr(0, 2) == "\xFE\xFF" || view.substr(0, 2) == "\xFF\xFE") {
        decoded = utf8OfUtf16(view.substr(2), view[0] == '\xFE', name);
        return decoded;
    }
    return view.substr(0, 3) == "\xEF\xBB\xBF" ? view.substr(3) : view;
}

// Whether the line's first word is `key` (splitWords' words, without splitting the line).
bool startsWithWord(std::string_view line, std::string_view key) {
    size_t first = 0;
    while (first < line.size() && isWordSeparator(line[first])) ++first;
    if (line.substr(first, key.size()) != key) return false;
    const size_t after = first + key.size();
    return after == line.size() || isWordSeparator(line[after]);
}

// visit(line number, words) for every line with words, or only for those whose first word is
// `onlyKey` when one is given (the others are not split).
template <typename Visit>
void forEachLine(const std::string& file, const std::string& name, Visit visit, std::string_view onlyKey = {}) {
    std::string decoded;
    const std::string_view text = utf8TextOf(file, name, decoded);
    size_t lineNumber = 0;
    size_t start = 0;
    std::vector<std::string_view> words;
    while (start <= text.size()) {
        size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        ++lineNumber;
        std::string_view line = text.substr(start, end - start);
        start = end + 1;
        if (const auto hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
        if (!onlyKey.empty() && !startsWithWord(line, onlyKey)) continue;
        splitWords(line, words);
        if (!words.empty()) visit(lineNumber, words);
    }
}

// Checks the count and the values of a line's numbers. Returns whether they are all finite;
// a non-finite one is an error unless `allowNonFinite`.
bool checkNumbers(const std::string& name, size_t line, const std::vector<std::string_view>& words,
                  size_t minCount, size_t maxCount, bool allowNonFinite = false) {
    const size_t count = words.size() - 1;
    if (count < minCount || count > maxCount) {
        failAt(name, line, quote(words[0]) + " takes " + std::to_string(minCount) +
                               (maxCount > minCount ? " to " + std::to_string(maxCount) : "") +
                               " numbers, got " + std::to_string(count));
    }
    bool finite = true;
    for (size_t i = 1; i < words.size(); ++i) {
        const std::string_view word = words[i];
        switch (classifyNumber(word)) {
            case NumberKind::Finite: break;
            case NumberKind::NonFinite:
                if (!allowNonFinite) failAt(name, line, quote(word) + " is not a finite number");
                finite = false;
                break;
            case NumberKind::OutOfRange:
                failAt(name, line, quote(word) + " is out of range for a 32-bit float");
            case NumberKind::Invalid: failAt(name, line, quote(word) + " is not a number");
        }
    }
    return finite;
}

// Checks a face corner's index into the `count` v, vt or vn lines read so far (a negative one
// counts back from the last).
void checkIndex(const std::string& name, size_t line, long index, size_t count, const char* what,
                const char* plural) {
    const long resolved = index > 0 ? index : static_cast<long>(count) + 1 + index;
    if (resolved < 1 || resolved > static_cast<long>(count)) {
        failAt(name, line, std::string(what) + " index " + std::to_string(index) + " is out of range (" +
                               std::to_string(count) + " " + plural + " so far)");
    }
}

// A vn line's direction at unit length (normalised in double, so that no float over- or
// underflows), or NaN when it has none: zero or not finite.
glm::vec3 unitNormal(const std::vector<std::string_view>& words) {
    const glm::dvec3 n(floatOf(words[1]), floatOf(words[2]), floatOf(words[3]));
    const double length = glm::length(n);
    if (!(length > 0.0) || !std::isfinite(length)) return glm::vec3(std::numeric_limits<float>::quiet_NaN());
    return glm::vec3(n / length);
}

struct NamedLine {
    std::string name;
    size_t line = 0;
};

struct ObjScan {
    std::vector<NamedLine> libraries;       // mtllib file names and their lines
    std::vector<size_t> nonFiniteVertices;  // 0-based indices of vertices with a nan/inf coordinate
    // Every vn in order, at unit length, NaN for one without a direction; tinyobjloader would read
    // "nan" as 0, so its own normals cannot tell.
    std::vector<glm::vec3> normals;
    size_t firstUnusableNormalLine = 0;  // the first vn without a direction; 0: none
    // Every vertex's colour (`v x y z r g b`, or `v x y z w r g b`), clamped to [0, 1], white for a
    // vertex without; empty until a v line has one.
    std::vector<glm::vec3> colours;
    size_t firstClampedColourLine = 0;  // the first colour outside [0, 1]; 0: none
    uint64_t triangles = 0;              // the faces' once triangulated (n - 2 each)
    uint64_t faces = 0;
    // Faces of more than 255 corners, which tinyobjloader counts in a byte: (which face, corners).
    std::vector<std::pair<uint64_t, uint32_t>> wideFaces;
    size_t vertices = 0;
    bool hasLines = false;               // l statements
    std::vector<std::string> warnings;
};

// Records the colour of `vertex`, the last three numbers of its v line (white where one is not
// finite: the vertex is then left out with its faces, as one with a non-finite coordinate).
void addVertexColour(ObjScan& scan, size_t vertex, size_t line, const std::vector<std::string_view>& words) {
    scan.colours.resize(vertex, glm::vec3(1.0f));
    const size_t r = words.size() - 3;
    glm::vec3 colour(floatOf(words[r]), floatOf(words[r + 1]), floatOf(words[r + 2]));
    if (!std::isfinite(colour.x + colour.y + colour.z)) colour = glm::vec3(1.0f);
    const glm::vec3 clamped = glm::clamp(colour, 0.0f, 1.0f);
    if (clamped != colour && scan.firstClampedColourLine == 0) scan.firstClampedColourLine = line;
    scan.colours.push_back(clamped);
}

// The file names of an mtllib line, each with the line.
void addLibraries(std::vector<NamedLine>& libraries, size_t line, const std::vector<std::string_view>& words) {
    for (size_t i = 1; i < words.size(); ++i) libraries.push_back({std::string(words[i]), line});
}

ObjScan validateObj(const std::string& text, const std::string& name) {
    ObjScan scan;
    size_t vertices = 0;
    size_t textureCoordinates = 0;
    forEachLine(text, name, [&](size_t line, const std::vector<std::string_view>& words) {
        const std::string_view key = words[0];
        if (key == "v") {
            // x y z [w], or x y z [w] r g b
            if (!checkNumbers(name, line, words, 3, 7, true)) scan.nonFiniteVertices.push_back(vertices);
            if (words.size() >= 7) addVertexColour(scan, vertices, line, words);
            ++vertices;
        } else if (key == "vn") {
            checkNumbers(name, line, words, 3, 3, true);
            scan.normals.push_back(unitNormal(words));
            if (std::isnan(scan.normals.back().x) && scan.firstUnusableNormalLine == 0) {
                scan.firstUnusableNormalLine = line;
            }
        } else if (key == "vt") {
            checkNumbers(name, line, words, 1, 3);
            ++textureCoordinates;
        } else if (key == "f") {
            if (words.size() < 4) failAt(name, line, "a face needs at least 3 vertices");
            scan.triangles += words.size() - 3;
            if (words.size() - 1 > UINT8_MAX) {
                scan.wideFaces.emplace_back(scan.faces, static_cast<uint32_t>(words.size() - 1));
            }
            ++scan.faces;
            for (size_t i = 1; i < words.size(); ++i) {
                const auto corner = faceCorner(words[i]);
                if (!corner) failAt(name, line, quote(words[i]) + " is not a face vertex");
                checkIndex(name, line, (*corner)[0], vertices, "vertex", "vertices");
                if ((*corner)[1] != 0) {
                    checkIndex(name, line, (*corner)[1], textureCoordinates, "texture coordinate",
                               "texture coordinates");
                }
                if ((*corner)[2] != 0) {
                    checkIndex(name, line, (*corner)[2], scan.normals.size(), "normal", "normals");
                }
            }
        } else if (key == "l") {
            scan.hasLines = true;
        } else if (key == "mtllib") {
            if (words.size() < 2) {
                scan.warnings.push_back(name + ":" + std::to_string(line) + ": mtllib names no file");
            }
            addLibraries(scan.libraries, line, words);
        }
    });
    scan.vertices = vertices;
    return scan;
}

// The OBJ's mtllib files as validateObj finds them, the rest of the file unchecked: all that
// reading the scene's files needs (parsing checks the whole file).
std::vector<NamedLine> materialLibraries(const std::string& text, const std::string& name) {
    std::vector<NamedLine> libraries;
    forEachLine(
        text, name,
        [&](size_t line, const std::vector<std::string_view>& words) { addLibraries(libraries, line, words); },
        "mtllib");
    return libraries;
}

// A file of vertices (a point cloud, p statements) or lines but no face has nothing to render:
// refused by what it holds rather than as a scene without triangles.
void refuseWithoutFaces(const ObjScan& scan, const std::string& name) {
    if (scan.triangles > 0 || scan.vertices == 0) return;
    throw Error(name + ": the file holds only " + (scan.hasLines ? "lines" : "points") + " (" +
                std::to_string(scan.vertices) + " vertices, no faces); Strata renders faces");
}

// Appends a line as the checks read it: its words, without the comment.
void appendLine(std::string& text, const std::vector<std::string_view>& words) {
    for (const std::string_view word : words) (text += word) += ' ';
    text.back() = '\n';
}

struct MtlMaterial {
    std::string name;  // the whole rest of its newmtl line
    std::string file;  // as messages name it
    size_t line = 0;   // of its newmtl
    // Whether it gives a roughness Pr (else it comes from Ns: tinyobjloader reads an absent Pr as
    // 0, which cannot be told from an explicit 0).
    bool hasRoughness = false;
    bool hasEmission = false;  // whether it has a Ke line
    bool hasIor = false;       // an Ni line (tinyobjloader reads an absent one as 1)
    bool hasFilter = false;    // a Tf line
    bool hasSpecular = false;  // a Ks line
    bool hasMetallic = false;  // a Pm line: the metallic-roughness model (materialOf)
    bool writtenByBlender = false;  // in an MTL that Blender wrote (materialOf)
    size_t sheenLine = 0;      // a Ps line, which is not read (materialOf)
    size_t unreadFilterLine = 0;  // a Tf in CIE XYZ or spectral form, which is not read
    struct TextureLine {
        std::string key;
        MtlTextureStatement statement;
        size_t line;
    };
    std::vector<TextureLine> textures;

    bool hasTexture(std::string_view key) const {
        return std::any_of(textures.begin(), textures.end(), [&](const TextureLine& t) { return t.key == key; });
    }
    // Whether Kd is a base colour of glTF's metallic-roughness model (materialOf).
    bool isMetallicRoughness() const { return writtenByBlender || hasMetallic || hasTexture("map_Pm"); }
};

// The MTL text as tinyobjloader is to read it, built by scanMtl: each newmtl names its material
// by its place among all the materials ("m0", "m1", ...), a name tinyobjloader reads whole and
// which a usemtl can refer to however the material is named.
std::string materialToken(size_t index) { return "m" + std::to_string(index); }

// Whether Blender's exporter wrote an MTL: its first line says so ("# Blender 3.4.1 MTL File:
// 'None'", "# Blender MTL File: 'scene.blend'" before 3.2), read as forEachLine reads the file.
bool isWrittenByBlender(const std::string& file, const std::string& name) {
    std::string decoded;
    const std::string_view text = utf8TextOf(file, name, decoded);
    const std::string_view line = text.substr(0, text.find('\n'));
    return line.starts_with("# Blender ") && line.find(" MTL File") != std::string_view::npos;
}

// Checks an MTL file line by line and appends its materials to `materials` and its text, as
// tinyobjloader is to read it, to `tinyobjText`. Only the statements whose values the renderer
// uses are checked; the others (Ka outside Blender's files, ...) pass as they are. The texture
// statements Strata reads (mtl_texture_statement.h) are kept with their material instead, and
// one that names no file is a warning.
void scanMtl(const std::string& text, const std::string& name, std::vector<MtlMaterial>& materials,
             std::string& tinyobjText, std::vector<std::string>& warnings) {
    const size_t first = materials.size();
    const bool blender = isWrittenByBlender(text, name);
    forEachLine(text, name, [&](size_t line, const std::vector<std::string_view>& words) {
        const std::string_view key = words[0];
        if (key == "newmtl") {
            tinyobjText += "newmtl " + materialToken(materials.size()) + "\n";
            MtlMaterial& material = materials.emplace_back();
            material.name = restOfLine(words);
            material.file = name;
            material.line = line;
            material.writtenByBlender = blender;
            return;
        }
        const bool colour = key == "Kd" || key == "Ke" || key == "Ks" || key == "Tf" || (blender && key == "Ka");
        const bool scalar = key == "Ns" || key == "Pr" || key == "Ni" || key == "illum" || key == "Pm" ||
                            key == "Ps" || key == "Pc" || key == "Pcr";
        const bool texture = isMtlTextureKey(key);
        if ((colour || scalar || texture) && materials.size() == first) {
            failAt(name, line, quote(key) + " before any newmtl");
        }
        if (texture) {
            const auto statement = parseMtlTextureStatement(words);
            if (!statement) {
                warnings.push_back(name + ":" + std::to_string(line) + ": " + std::string(key) +
                                   " names no file; ignored");
            } else {
                materials.back().textures.push_back({std::string(key), *statement, line});
            }
            return;
        }
        if (key == "Tf" && words.size() > 1 && (words[1] == "xyz" || words[1] == "spectral")) {
            materials.back().unreadFilterLine = line;
            return;
        }
        // The dissolve (applyOpacity); "d -halo" (a dissolve that depends on the angle) is read
        // as a plain d.
        if ((key == "d" || key == "Tr") && materials.size() > first) {
            std::vector<std::string_view> value = words;
            if (key == "d" && value.size() > 1 && value[1] == "-halo") {
                warnings.push_back(name + ":" + std::to_string(line) + ": d -halo is read as a plain d");
                value.erase(value.begin() + 1);
            }
            checkNumbers(name, line, value, 1, 1);
            appendLine(tinyobjText, value);
            return;
        }
        if (colour) checkNumbers(name, line, words, 1, 3);
        if (scalar) checkNumbers(name, line, words, 1, 1);
        if (key == "Pr") materials.back().hasRoughness = true;
        if (key == "Ke") materials.back().hasEmission = true;
        if (key == "Ni") materials.back().hasIor = true;
        if (key == "Tf") materials.back().hasFilter = true;
        if (key == "Ks") materials.back().hasSpecular = true;
        if (key == "Pm") materials.back().hasMetallic = true;
        if (key == "Ps") materials.back().sheenLine = line;
        appendLine(tinyobjText, words);
    });
}

// The number 1, 2, ... of the smoothing group that `s WORD` names, or 0 for none; `groups` holds
// the numbers given so far. Numbers are told apart by value: "s 01" is "s 1".
size_t smoothingGroupNumber(std::string_view word, std::map<std::string, size_t>& groups) {
    unsigned long long value = 0;
    const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
    const bool number = error == std::errc() && end == word.data() + word.size();
    if (word == "off" || (number && value == 0)) return 0;
    const std::string key = number ? std::to_string(value) : "word " + std::string(word);
    return groups.try_emplace(key, groups.size() + 1).first->second;
}

// The OBJ as tinyobjloader is to read it: only the statements the checks read, as they read them.
// Comments go, since tinyobjloader reads '#' as a comment only at the start of a line ("f 1 2 3
// # 5" would read a face the checks never saw, a fuzzer finding: an index past the last vertex
// read out of bounds). One mtllib comes first, so that every material is known to every usemtl,
// and each usemtl names its material by token (its first definition), or none when no MTL
// defines it: those faces get the default material and a warning, once per name. Smoothing
// groups are renumbered 1, 2, ... in order of appearance ("off" and 0 are none): a group named by
// a word, or by a number tinyobjloader's int would overflow, is a group all the same.
std::string objForTinyobj(const std::string& text, const std::string& name,
                          const std::vector<MtlMaterial>& materials, std::vector<std::string>& warnings) {
    std::map<std::string, size_t> smoothingGroups;
    std::map<std::string, size_t> byName;
    for (size_t i = 0; i < materials.size(); ++i) byName.emplace(materials[i].name, i);
    std::set<std::string> undefined;
    std::string kept = materials.empty() ? "" : "mtllib materials.mtl\n";
    kept.reserve(kept.size() + text.size());  // about what is kept, so it is not copied as it grows
    forEachLine(text, name, [&](size_t line, const std::vector<std::string_view>& words) {
        const std::string_view key = words[0];
        if (key == "usemtl") {
            // An empty name is no material, even when an MTL has a newmtl without a name.
            const std::string material = restOfLine(words);
            const auto found = material.empty() ? byName.end() : byName.find(material);
            if (found != byName.end()) {
                kept += "usemtl " + materialToken(found->second) + "\n";
                return;
            }
            kept += "usemtl\n";
            if (!undefined.insert(material).second) return;
            const std::string at = name + ":" + std::to_string(line) + ": ";
            warnings.push_back(at + (material.empty() ? "usemtl names no material"
                                                      : "material " + quote(material) + " is not defined") +
                               "; " + kDefaultMaterialNote);
        } else if (key == "v" || key == "vn" || key == "vt" || key == "f") {
            appendLine(kept, words);
        } else if (key == "s" && words.size() > 1) {
            kept += "s " + std::to_string(smoothingGroupNumber(words[1], smoothingGroups)) + "\n";
        }
    });
    return kept;
}

bool isFinite(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// A number of the PBR extension that must lie in [0, 1]; throws strata::Error naming it.
float unitValue(float value, const char* key, const std::string& at) {
    if (!(value >= 0.0f && value <= 1.0f)) throw Error(at + " has " + key + " outside 0..1");
    return value;
}

// Kd and Ks of a material of the metallic-roughness model from base colour Kd (materialOf).
void applyMetallicRoughness(Material& material, const tinyobj::material_t& m, const MtlMaterial& source,
                            const std::string& at) {
    MetallicRoughness model;
    model.baseColor = material.diffuse;
    if (source.hasMetallic) {
        model.metallic = unitValue(m.metallic, "Pm", at);
    } else if (source.hasTexture("map_Pm")) {
        model.metallic = 1.0f;
    } else {  // Blender's (materialOf)
        model.metallic = m.illum == 3 ? unitValue((m.ambient[0] + m.ambient[1] + m.ambient[2]) / 3.0f, "Ka", at) : 0.0f;
    }
    model.specularColour = source.hasSpecular ? glm::min(0.08f * material.specular, glm::vec3(1.0f)) : glm::vec3(0.04f);
    const LayeredReflectance r = fromMetallicRoughness(model.baseColor, model.metallic, model.dielectricF0());
    material.diffuse = r.diffuse;
    material.specular = r.specular;
    // Kept for the textures to vary; buildMesh drops it from a material without any.
    material.metallicRoughness = model;
}

// The clear coat (Pc, Pcr) of an opaque material (materialOf).
void applyClearCoat(Material& material, const tinyobj::material_t& m, const std::string& at) {
    material.clearcoat = unitValue(m.clearcoat_thickness, "Pc", at);
    material.clearcoatRoughness = unitValue(m.clearcoat_roughness, "Pcr", at);
}

// The renderer's material of an MTL material as tinyobjloader read it; throws strata::Error
// naming its newmtl line for values that are not physical. The illumination models that ask for
// ray-traced refraction or reflection (MTL specification, "illum"):
//   illum 4, 6, 7   a dielectric of index Ni (1.5 when absent), transmission filter Tf (1 1 1
//                   when absent) and roughness Pr (0, smooth, when absent; GGX alpha = Pr^2);
//                   its Kd and Ks are not used (its reflection is the interface's Fresnel);
//   illum 3, 5      with Ks, and Pr 0 (or no Pr and Ns >= 10000): a perfect mirror of F0 = Ks
//                   (with Kd as well: a smooth Ks coat over Kd).
// Every other illum is the layered material of Kd, Ks and Pr (or Ns). An MTL that Blender wrote
// (isWrittenByBlender) describes its Principled BSDF (since 2.8; Blender Internal's before), and
// is read as Blender's importer reads it: Kd a base colour of glTF's metallic-roughness model,
// metallic Ka for illum 3 (else 0), the dielectric's F0 0.08 Ks and the roughness
// 1 - sqrt(Ns / 1000) unless Pr is given (exporters 2.8 to 3.1 wrote Ns = 900 (1 - r)^2, 3.2 on
// 1000 (1 - r)^2: the default 0.5 reads 0.53 from the former). The
// statements of MTL's PBR extension (Clara.io's, which Blender writes when asked and assimp
// reads) apply to every file:
//   Pm, map_Pm  metallic: Kd is then a base colour and the material glTF's metallic-roughness one
//               (metallic_roughness.h), whose dielectric F0 is 0.08 Ks (Blender writes its
//               Principled BSDF's Specular as Ks, and reads it back so), or 0.04 without a Ks;
//               map_Pm alone takes Pm = 1;
//   map_Pr      times Pr; alone it takes Pr = 1;
//   Pc, Pcr     a clear coat of that weight and roughness, as glTF's KHR_materials_clearcoat
//               (which Blender's glTF exporter writes from the same Clearcoat; its Cycles
//               renders a quarter of that coat, as Disney's principled BRDF does).
// Ps, a sheen, is not read (a warning): Blender writes its Principled BSDF's Disney sheen, a
// weight without the roughness of the sheen Strata renders (KHR_materials_sheen's).
Material materialOf(const tinyobj::material_t& m, const MtlMaterial& source) {
    Material material;
    material.name = source.name;
    material.diffuse = {m.diffuse[0], m.diffuse[1], m.diffuse[2]};
    material.emission = {m.emission[0], m.emission[1], m.emission[2]};
    material.specular = {m.specular[0], m.specular[1], m.specular[2]};
    material.roughness = source.hasRoughness              ? m.roughness
                         : source.hasTexture("map_Pr") ? 1.0f
                         : source.writtenByBlender     ? 1.0f - std::sqrt(std::clamp(m.shininess / 1000.0f, 0.0f, 1.0f))
                                                       : roughnessFromShininess(m.shininess);
    const std::string at =
        source.file + ":" + std::to_string(source.line) + ": material " + quote(source.name);
    if (!isFinite(material.diffuse) || !isFinite(material.emission) || !isFinite(material.specular) ||
        !std::isfinite(material.roughness) || minComponent(material.diffuse) < 0.0f ||
        minComponent(material.emission) < 0.0f || minComponent(material.specular) < 0.0f) {
        throw Error(at + " has a negative or non-finite Kd, Ke, Ks or Pr");
    }
    if (maxComponent(material.diffuse) > 1.0f) {
        throw Error(at + " has Kd above 1 (creates energy)");
    }
    if (maxComponent(material.specular) > 1.0f) {
        throw Error(at + " has Ks above 1 (creates energy)");
    }
    if (material.roughness < 0.0f || material.roughness > 1.0f) throw Error(at + " has Pr outside 0..1");
    if (m.illum == 4 || m.illum == 6 || m.illum == 7) {
        material.transmission = 1.0f;
        material.diffuse = glm::vec3(0.0f);
        material.specular = glm::vec3(0.0f);
        material.ior = source.hasIor ? m.ior : 1.5f;
        if (source.hasFilter) material.transmissionFilter = {m.transmittance[0], m.transmittance[1], m.transmittance[2]};
        material.roughness = source.hasRoughness ? m.roughness : 0.0f;
        if (!(material.ior > 0.0f) || !std::isfinite(material.ior)) {
            throw Error(at + " (illum " + std::to_string(m.illum) + ", a dielectric) has an Ni that is not a positive number");
        }
        const glm::vec3& tf = material.transmissionFilter;
        if (!isFinite(tf) || minComponent(tf) < 0.0f || maxComponent(tf) > 1.0f) {
            throw Error(at + " has a Tf outside 0..1");
        }
    } else if (source.isMetallicRoughness()) {
        applyMetallicRoughness(material, m, source, at);
    } else if ((m.illum == 3 || m.illum == 5) && maxComponent(material.specular) > 0.0f &&
               (source.hasRoughness ? m.roughness == 0.0f : m.shininess >= 10000.0f)) {
        material.roughness = 0.0f;
    }
    if (material.transmission == 0.0f) applyClearCoat(material, m, at);
    return material;
}

// d, the dissolve (1 - Tr where there is no d), times map_d where there is one: the material's
// opacity (material.h). The MTL specification multiplies the two; Blender's importer connects
// map_d's alpha to its Principled BSDF's alpha in place of d, which agree where d is 1, as it
// nearly always is beside a map_d. d is not applied to a dielectric, whose transparency is its
// illum.
void applyOpacity(Material& material, const tinyobj::material_t& m, const MtlMaterial& source,
                  std::vector<std::string>& warnings) {
    const std::string at = source.file + ":" + std::to_string(source.line) + ": material " + quote(source.name);
    if (!(m.dissolve >= 0.0f)) throw Error(at + " has a d (or Tr) outside 0..1");
    const float dissolve = material.transmission > 0.0f ? 1.0f : std::min(m.dissolve, 1.0f);
    const bool mapped = material.textures.coverage != nullptr;
    if (!(dissolve < 1.0f) && !mapped) return;
    if (dissolve == 0.0f) warnings.push_back(at + ": d 0 (or Tr 1) makes it wholly transparent");
    material.textures.blendBy(dissolve, material.textures.coverage, material.textures.coverageChannel);
}

// The channel a texture statement's -imfchan r, g or b names, else `otherwise`.
int channelOf(const MtlTextureStatement& statement, int otherwise) {
    if (statement.channel == 'r') return 0;
    if (statement.channel == 'g') return 1;
    if (statement.channel == 'b') return 2;
    return otherwise;
}

// The textures of an MTL material's texture statements, decoded from the bundle (textures are
// named relative to the MTL's folder, `source.file` being its bundle name `mtlName`).
//   map_Kd  RGB times Kd, as the MTL specification says (Blender's importer replaces Kd instead;
//           with the usual Kd 0.8 or 1 of exporters the two differ by that factor);
//   map_Ke  RGB times Ke; a material with map_Ke and no Ke line takes Ke = 1;
//   map_Pr, map_Pm  roughness and metallic (materialOf): the channel -imfchan names, else the
//           first;
//   map_d   coverage, an opacity times d (applyOpacity): the channel -imfchan names, else the
//           image's alpha, else its first channel;
//   norm    a tangent-space normal map, -bm scaling its x and y;
//   map_Bump, bump  the same when the image's values are a normal map's (looksLikeNormalMap);
//           a height map is not rendered (a warning).
// The material's textures share one placement (-s and -o, uv_placement.h), the first used
// texture's, with a warning for one that differs; -clamp on clamps a texture to its edges; other
// options are skipped (warnings). Returns the placement.
UvPlacement addTextures(Material& material, const MtlMaterial& source, const std::string& mtlName,
                        SceneTextures& textures, std::vector<std::string>& warnings) {
    UvPlacement placement;
    std::string placedBy;  // the key whose placement the material's textures share
    for (const auto& [key, statement, line] : source.textures) {
        const std::string at = source.file + ":" + std::to_string(line) + ": " + key;
        if (!statement.unknownOption.empty()) {
            warnings.push_back(at + ": unknown option " + quote(statement.unknownOption) + " skipped");
        }
        const std::string file = textureFileName(mtlName, statement.file);
        const bool colour = key == "map_Kd" || key == "map_Ke";
        auto texture = textures.file(file, colour ? TextureEncoding::Colour : TextureEncoding::Data, at);
        if (!texture) continue;
        if (statement.clamp) {
            texture = std::make_shared<const Texture>(
                texture->sampled({TextureWrap::ClampToEdge, TextureWrap::ClampToEdge, false}));
        }
        if (key == "map_Kd") {
            material.textures.colour = texture;
        } else if (key == "map_Ke") {
            if (!source.hasEmission) material.emission = glm::vec3(1.0f);
            material.textures.emission = texture;
        } else if (key == "map_Pr") {
            material.textures.roughness = texture;
            material.textures.roughnessChannel = channelOf(statement, 0);
        } else if (key == "map_Pm") {
            material.textures.metallic = texture;
            material.textures.metallicChannel = channelOf(statement, 0);
        } else if (key == "map_d") {
            const int channels = texture->channels();
            material.textures.coverage = texture;
            material.textures.coverageChannel = channelOf(statement, channels == 2 || channels == 4 ? 3 : 0);
        } else if (key == "norm" || looksLikeNormalMap(*texture)) {
            material.textures.normal = texture;
            material.textures.normalScale = statement.bumpMultiplier;
        } else {
            warnings.push_back(at + ": " + quote(statement.file) +
                               " holds heights, not normals; bump mapping is not rendered, ignored");
            continue;
        }
        const UvPlacement own{statement.scale, statement.offset};
        if (placedBy.empty()) {
            placement = own;
            placedBy = key;
        } else if (own != placement) {
            warnings.push_back(at + ": its -o and -s differ from " + placedBy +
                               "'s, whose placement the material's textures share");
        }
    }
    return placement;
}

// Builds the mesh from the OBJ that validateObj accepted and the MTL files scanMtl accepted
// (`materials`, `mtlText`); `warnings` are those found so far.
MeshData buildMesh(const SceneBundle& bundle, const std::string& objText, const std::string& objName,
                   const ObjScan& scan, const std::vector<MtlMaterial>& materials,
                   const std::vector<std::string>& mtlNames, const std::string& mtlText,
                   std::vector<std::string> warnings, LoadReport* report, const SceneBudget& budget) {
    tinyobj::ObjReaderConfig config;
    // Faces as the file has them: tinyobjloader's own split covers a concave face's notches.
    config.triangulate = false;
    config.vertex_color = false;
    tinyobj::ObjReader reader;
    if (!reader.ParseFromString(objForTinyobj(objText, objName, materials, warnings), mtlText, config)) {
        std::string error = reader.Error();
        while (!error.empty() && (error.back() == '\n' || error.back() == '\r')) error.pop_back();
        throw Error(objName + ": " + (error.empty() ? "cannot parse" : error));
    }
    // The guards below catch only tinyobjloader reading its text differently from the checks.
    if (reader.GetMaterials().size() != materials.size()) {
        throw Error(objName + ": the material libraries were read inconsistently");
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
    SceneTextures textures(bundle, warnings, TextureBudget(budget.textureBytes, budget.textureBytesSpent));
    std::vector<UvPlacement> placements;  // per material
    for (size_t i = 0; i < materials.size(); ++i) {
        mesh.materials.push_back(materialOf(reader.GetMaterials()[i], materials[i]));
        if (materials[i].unreadFilterLine > 0 && mesh.materials.back().transmission > 0.0f) {
            warnings.push_back(materials[i].file + ":" + std::to_string(materials[i].unreadFilterLine) +
                               ": Tf in CIE XYZ or spectral form is not read; the filter is 1 1 1");
        }
        if (materials[i].sheenLine > 0 && reader.GetMaterials()[i].sheen != 0.0f) {
            warnings.push_back(materials[i].file + ":" + std::to_string(materials[i].sheenLine) +
                               ": Ps (a sheen) is not read");
        }
        Material& material = mesh.materials.back();
        placements.push_back(addTextures(material, materials[i], mtlNames[i], textures, warnings));
        applyOpacity(material, reader.GetMaterials()[i], materials[i], warnings);
        // Only a texture reads the metallic-roughness model at each hit (material.h).
        if (!material.hasReflectanceTextures()) material.metallicRoughness.reset();
    }
    // vt u v as they are (texture.h's convention is OBJ's); the w of 3D texture coordinates
    // is not read.
    for (size_t i = 0; i + 1 < attrib.texcoords.size(); i += 2) {
        mesh.uvs.emplace_back(attrib.texcoords[i], attrib.texcoords[i + 1]);
    }
    bool anyUvs = false;
    // Faces without a material get the default; it is appended only when used.
    const auto defaultMaterial = static_cast<uint32_t>(mesh.materials.size());
    bool defaultUsed = false;
    // The vn lines with a direction, renumbered; a corner on one without is kUnusable.
    constexpr uint32_t kUnusable = UINT32_MAX;
    std::vector<uint32_t> normalIndex;
    for (const glm::vec3& n : scan.normals) {
        normalIndex.push_back(std::isnan(n.x) ? kUnusable : static_cast<uint32_t>(mesh.normals.size()));
        if (!std::isnan(n.x)) mesh.normals.push_back(n);
    }
    bool anySmooth = false;
    size_t flatForUnusableNormals = 0;
    // Triangles of faces in a smoothing group but without vn, by index into mesh.triangles: their
    // normals come from their group's faces once all are read.
    std::vector<SmoothTriangle> groupTriangles;
    std::vector<size_t> groupTriangleIndex;

    size_t dropped = 0;
    TriangulationBudget triangulation{kTriangulationVisits};
    size_t fannedFaces = 0;
    std::vector<glm::vec3> facePositions;
    std::vector<std::array<uint32_t, 3>> faceTriangles;
    uint64_t faceInFile = 0;
    auto wideFace = scan.wideFaces.begin();
    for (const auto& shape : reader.GetShapes()) {
        const auto& indices = shape.mesh.indices;
        size_t firstCorner = 0;
        for (size_t f = 0; f < shape.mesh.num_face_vertices.size(); ++f, ++faceInFile) {
            size_t corners = shape.mesh.num_face_vertices[f];
            if (wideFace != scan.wideFaces.end() && wideFace->first == faceInFile) corners = (wideFace++)->second;
            if (corners > indices.size() - firstCorner) throw Error(objName + ": the faces were read inconsistently");
            const std::span<const tinyobj::index_t> face(indices.data() + firstCorner, corners);
            firstCorner += corners;
            facePositions.clear();
            for (const tinyobj::index_t& corner : face) {
                if (corner.vertex_index < 0 || static_cast<size_t>(corner.vertex_index) >= mesh.positions.size()) {
                    throw Error(objName + ": a face refers to a missing vertex");
                }
                facePositions.push_back(mesh.positions[static_cast<size_t>(corner.vertex_index)]);
            }
            faceTriangles.clear();
            if (!triangulatePolygon(facePositions, triangulation, faceTriangles)) ++fannedFaces;
            for (const std::array<uint32_t, 3>& cornersOfTriangle : faceTriangles) {
                std::array<uint32_t, 3> tri;
                std::array<uint32_t, 3> normals = kNoNormals;  // stays so on corners without vn
                std::array<uint32_t, 3> uvs = kNoUvs;
                bool cornersHaveNormals = true;
                bool cornersHaveUvs = true;
                for (size_t k = 0; k < 3; ++k) {
                    const tinyobj::index_t& corner = face[cornersOfTriangle[k]];
                    tri[k] = static_cast<uint32_t>(corner.vertex_index);
                    cornersHaveUvs = cornersHaveUvs && corner.texcoord_index >= 0 &&
                                     static_cast<size_t>(corner.texcoord_index) < mesh.uvs.size();
                    if (cornersHaveUvs) uvs[k] = static_cast<uint32_t>(corner.texcoord_index);
                    cornersHaveNormals = cornersHaveNormals && corner.normal_index >= 0;
                    if (corner.normal_index < 0) continue;
                    const auto normal = static_cast<size_t>(corner.normal_index);
                    if (normal >= normalIndex.size()) {
                        throw Error(objName + ": a face refers to a missing normal");
                    }
                    normals[k] = normalIndex[normal];
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
                // A face without vn on every corner is flat unless in a smoothing group (its normals
                // then come from the group), as is one on a normal without a direction.
                const bool usable = std::none_of(normals.begin(), normals.end(),
                                                 [&](uint32_t i) { return i == kUnusable; });
                flatForUnusableNormals += cornersHaveNormals && !usable;
                const bool smooth = cornersHaveNormals && usable;
                anySmooth = anySmooth || smooth;
                const uint32_t group = shape.mesh.smoothing_group_ids[f];
                if (!cornersHaveNormals && group != 0) {
                    groupTriangles.push_back({tri, group});
                    groupTriangleIndex.push_back(mesh.triangles.size());
                }
                mesh.triangleNormals.push_back(smooth ? normals : kNoNormals);
                // A face without vt on every corner has no texture coordinates.
                mesh.triangleUvs.push_back(cornersHaveUvs ? uvs : kNoUvs);
                anyUvs = anyUvs || cornersHaveUvs;

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
    }
    if (fannedFaces > 0) {
        warnings.push_back(objName + ": " + std::to_string(fannedFaces) +
                           (fannedFaces == 1 ? " concave face was split as a fan, over its notches"
                                             : " concave faces were split as fans, over their notches") +
                           ": the file's polygons took longer to triangulate than the loader allows");
    }
    if (defaultUsed) mesh.materials.push_back({"default", glm::vec3(kDefaultAlbedo), glm::vec3(0.0f)});
    if (!groupTriangles.empty()) {
        const GroupNormals group = smoothingGroupNormals(mesh.positions, groupTriangles);
        const auto first = static_cast<uint32_t>(mesh.normals.size());
        mesh.normals.insert(mesh.normals.end(), group.normals.begin(), group.normals.end());
        for (size_t t = 0; t < groupTriangles.size(); ++t) {
            if (group.corners[t] == kNoNormals) continue;
            for (size_t k = 0; k < 3; ++k) mesh.triangleNormals[groupTriangleIndex[t]][k] = first + group.corners[t][k];
            anySmooth = true;
        }
    }
    // No triangle is smooth: the mesh says so by having no normals at all (mesh.h).
    refuseWithoutFaces(scan, objName);
    if (!anySmooth) {
        mesh.normals.clear();
        mesh.triangleNormals.clear();
    }
    placeUvs(mesh, placements);
    if (!anyUvs) {
        mesh.uvs.clear();
        mesh.triangleUvs.clear();
    }
    // A vertex colour is the vertex's, so a triangle's colours are its vertices'.
    if (!scan.colours.empty()) {
        mesh.colours = scan.colours;
        mesh.colours.resize(mesh.positions.size(), glm::vec3(1.0f));
        mesh.triangleColours = mesh.triangles;
    }
    if (scan.firstClampedColourLine > 0) {
        warnings.push_back(objName + ":" + std::to_string(scan.firstClampedColourLine) +
                           ": vertex colours outside 0..1 are clamped to it (OBJ colours are fractions, not bytes)");
    }
    if (flatForUnusableNormals > 0) {
        warnings.push_back(objName + ":" + std::to_string(scan.firstUnusableNormalLine) +
                           ": vn is zero or not finite; " + std::to_string(flatForUnusableNormals) +
                           (flatForUnusableNormals == 1 ? " triangle using such a normal is"
                                                        : " triangles using such normals are") +
                           " shaded flat");
    }
    if (report) {
        report->faces = mesh.triangles.size();
        report->droppedTriangles = dropped;
        report->nonFiniteVertices = scan.nonFiniteVertices.size();
        report->textureBytes = textures.budget().used() - budget.textureBytesSpent;
        report->warnings = std::move(warnings);
    }
    return mesh;
}

}  // namespace

MeshData parseObj(const std::string& objText, const std::string& objName,
                  const std::string& mtlText, const std::string& mtlName, LoadReport* report) {
    const ObjScan scan = validateObj(objText, objName);
    std::vector<MtlMaterial> materials;
    std::string tinyobjMtl;
    std::vector<std::string> warnings = scan.warnings;
    // Checked in any case, so that a test of MTL lines needs no OBJ to load them.
    scanMtl(mtlText, mtlName, materials, tinyobjMtl, warnings);
    if (scan.libraries.empty()) {
        materials.clear();
        tinyobjMtl.clear();
    }
    // No files besides: the textures the MTL names are missing (warnings).
    const SceneBundle bundle{objName, {}, std::nullopt, std::nullopt};
    const std::vector<std::string> mtlNames(materials.size(), mtlName);
    return buildMesh(bundle, objText, objName, scan, materials, mtlNames, tinyobjMtl, std::move(warnings), report,
                     SceneBudget{});
}

std::vector<SceneFile> readObjScene(const std::filesystem::path& path, SceneFolder& folder) {
    std::vector<SceneFile> files{{path.filename().string(), readTextFile(path, "scene")}};
    const auto known = [&](const std::string& name) {
        return std::any_of(files.begin(), files.end(), [&](const SceneFile& file) { return file.name == name; });
    };
    const std::string objName = printable(path.string());
    for (const auto& library : materialLibraries(files.front().bytes, objName)) {
        if (known(library.name)) continue;
        // A missing library is left out: parsing warns and gives its faces the default material.
        auto bytes = folder.read(library.name, objName + ":" + std::to_string(library.line) + ": mtllib");
        if (!bytes) continue;
        files.push_back({library.name, std::move(*bytes)});
        // Its textures, relative to its folder; a missing one is left out (parsing warns).
        std::vector<MtlMaterial> materials;
        std::string unused;
        std::vector<std::string> warnings;
        const std::string mtlName = printable((path.parent_path() / library.name).string());
        scanMtl(files.back().bytes, mtlName, materials, unused, warnings);
        for (const MtlMaterial& material : materials) {
            for (const auto& [key, statement, line] : material.textures) {
                const std::string name = textureFileName(library.name, statement.file);
                if (known(name)) continue;
                auto texture = folder.read(name, mtlName + ":" + std::to_string(line) + ": " + key);
                if (texture) files.push_back({name, std::move(*texture)});
            }
        }
    }
    return files;
}

MeshData parseObjScene(const SceneBundle& bundle, LoadReport* report, const SceneBudget& budget) {
    const SceneFile& obj = bundle.files.front();
    const std::string objName = bundle.pathOf(obj.name);
    const ObjScan scan = validateObj(obj.bytes, objName);
    checkTriangleBudget(objName, {scan.triangles, 0, scan.triangles}, budget);
    std::vector<std::string> warnings = scan.warnings;
    // Each MTL file is checked on its own, so that a bad line is reported with its file and line;
    // tinyobjloader then reads them joined, as the OBJ's mtllib lines load them one after another.
    std::vector<MtlMaterial> materials;
    std::vector<std::string> mtlNames;  // the bundle name of each material's MTL file
    std::string tinyobjMtl;
    std::set<std::string> scanned;
    for (const auto& library : scan.libraries) {
        if (!scanned.insert(library.name).second) continue;
        const SceneFile* mtl = bundle.find(library.name);
        if (!mtl) {
            warnings.push_back(objName + ":" + std::to_string(library.line) + ": material library " +
                               quote(library.name) + " is missing; its materials are not defined");
            continue;
        }
        scanMtl(mtl->bytes, bundle.pathOf(library.name), materials, tinyobjMtl, warnings);
        mtlNames.resize(materials.size(), library.name);
    }
    return buildMesh(bundle, obj.bytes, objName, scan, materials, mtlNames, tinyobjMtl, std::move(warnings), report,
                     budget);
}

MeshData loadObjFile(const std::filesystem::path& path, LoadReport* report) {
    SceneFolder folder(path, {});
    return parseObjScene(SceneBundle{path, readObjScene(path, folder), std::nullopt, std::nullopt}, report);
}

}  // namespace strata
