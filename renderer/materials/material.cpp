#include "materials/material.h"

#include <utility>
#include <vector>

#include "util/components.h"

namespace strata {

void MaterialTextures::blendBy(float opacityFactor, std::shared_ptr<const Texture> texture, int channel) {
    coverageChannel = texture ? channel : 0;
    coverage = texture ? std::move(texture) : std::make_shared<const Texture>(1, 1, 1, std::vector<float>{1.0f});
    blended = true;
    opacity = opacityFactor;
}

glm::vec3 Material::emissionAt(glm::vec2 uv) const {
    if (cutOut(uv)) return glm::vec3(0.0f);
    return textures.emission ? emission * glm::vec3(textures.emission->lookup(uv)) : emission;
}

float Material::maxEmission() const {
    const glm::vec3 e = textures.emission ? emission * glm::vec3(textures.emission->max()) : emission;
    return maxComponent(e);
}

glm::vec3 Material::meanEmission() const {
    const glm::vec3 e = textures.emission ? emission * glm::vec3(textures.emission->mean()) : emission;
    return textures.blended ? e * (textures.coverage->mean()[textures.coverageChannel] * textures.opacity) : e;
}

}  // namespace strata
