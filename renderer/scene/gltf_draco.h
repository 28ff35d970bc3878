#pragma once
// KHR_draco_mesh_compression: a primitive whose geometry is Draco-encoded in its extension's
// bufferView is decoded with libdraco into buffers of its own, and the primitive's indices and
// compressed attributes' accessors are pointed at them, so that the rest of the loader reads it as
// it reads any primitive (gltf_accessors.h checks what it reads).
#include <string>
#include <nlohmann/json.hpp>

#include "scene/gltf_model.h"

namespace strata {

// tinygltf refuses a primitive's indices accessor without a bufferView, which a Draco-compressed
// primitive's has; each such accessor is given its primitive's Draco bufferView before tinygltf
// reads the document (the decoding replaces it). Returns whether `document` was changed.
bool giveDracoIndicesAView(nlohmann::json& document);

// Decodes every Draco-compressed primitive of `model` in place. Throws strata::Error naming `path`
// and the primitive whose extension is malformed or whose data does not decode.
void decodeDracoPrimitives(tinygltf::Model& model, const std::string& path);

}  // namespace strata
