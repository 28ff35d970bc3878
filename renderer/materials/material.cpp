#include "materials/material.h"

#include "util/components.h"

namespace strata {

glm::vec3 Material::emissionAt(glm::vec2 uv) const {
    if (cutOut(uv)) return glm::vec3(0.0f);
    return textures.emission ? emission * glm::vec3(textures.emission->lookup(uv)) : emission;
}

float Material::maxEmission() const {
    const glm::vec3 e = textures.emission ? emission * glm::vec3(textures.emission->max()) : emission;
    return maxComponent(e);
}

glm::vec3 Material::meanEmission() const {
    return textures.emission ? emission * glm::vec3(textures.emission->mean()) : emission;
}

}  // namespace strata
