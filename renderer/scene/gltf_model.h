#pragma once
// What every part of the glTF loader (gltf_loader.h) reads and reports to: the model as tinygltf
// parsed it, the file as messages name it, the images' encoded bytes, and the warnings, each
// noted once. A failure is one strata::Error line naming the file.
#include <algorithm>
#include <string>
#include <vector>

// tinygltf configured alike in every file of the loader, since its inline code depends on it:
// no image writing, no file access of its own (files come through callbacks, gltf_loader.cpp).
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_FS
#include <fstream>  // tinygltf's writer needs it even with TINYGLTF_NO_FS, and does not include it then
#include <tiny_gltf.h>

#include "util/error.h"

namespace strata {

struct GltfModel {
    const tinygltf::Model& model;
    std::string path;
    // Encoded bytes by image index, as the file holds them (empty: not read, e.g. a missing file).
    const std::vector<std::string>& images;
    std::vector<std::string> warnings;

    [[noreturn]] void fail(const std::string& message) const { throw Error(path + ": " + message); }

    void warnOnce(const std::string& message) {
        const std::string line = path + ": " + message;
        if (std::find(warnings.begin(), warnings.end(), line) == warnings.end()) warnings.push_back(line);
    }

    // list[index], or a failure naming `what` and the index when there is no such element.
    template <typename T>
    const T& element(const std::vector<T>& list, int index, const std::string& what) const {
        if (index < 0 || static_cast<size_t>(index) >= list.size()) {
            fail(what + " " + std::to_string(index) + " does not exist (there are " + std::to_string(list.size()) + ")");
        }
        return list[static_cast<size_t>(index)];
    }
};

}  // namespace strata
