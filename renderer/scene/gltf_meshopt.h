#pragma once
// EXT_meshopt_compression (and KHR_meshopt_compression, its ratified name): a bufferView whose
// bytes are meshoptimizer-encoded in another buffer is decoded with libmeshoptimizer (vertex
// attributes, triangle indices or index sequences, then the octahedral, quaternion or
// exponential filter), and the view pointed at the decoded bytes, so that the rest of the loader
// reads it as it reads any bufferView (gltf_accessors.h checks what it reads).
#include <string>
#include <nlohmann/json.hpp>

#include "scene/gltf_model.h"

namespace strata {

// A compressed file's fallback buffers may have no URI and no data ("fallback": true); tinygltf
// refuses such a buffer, so each is given one byte of its own (a data: URI) before tinygltf
// reads the document. Returns whether `document` was changed.
bool giveMeshoptFallbacksData(nlohmann::json& document);

// Decodes every compressed bufferView of `model` in place. Throws strata::Error naming `path` and
// the bufferView whose extension is malformed or whose data does not decode.
void decodeMeshoptBufferViews(tinygltf::Model& model, const std::string& path);

}  // namespace strata
