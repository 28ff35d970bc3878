#include "materials/normal_map.h"

#include <cmath>
#include <glm/geometric.hpp>

namespace strata {

std::optional<SurfaceTangents> surfaceTangents(const std::array<glm::vec3, 3>& p,
                                               const std::array<glm::vec2, 3>& uv) {
    const glm::vec3 e1 = p[1] - p[0];
    const glm::vec3 e2 = p[2] - p[0];
    const glm::vec2 d1 = uv[1] - uv[0];
    const glm::vec2 d2 = uv[2] - uv[0];
    const float determinant = d1.x * d2.y - d1.y * d2.x;
    if (!(std::abs(determinant) > 0.0f)) return std::nullopt;
    const SurfaceTangents t{(e1 * d2.y - e2 * d1.y) / determinant, (e2 * d1.x - e1 * d2.x) / determinant};
    const float lengths = glm::dot(t.dpdu, t.dpdu) * glm::dot(t.dpdv, t.dpdv);
    if (!(lengths > 0.0f) || !std::isfinite(lengths)) return std::nullopt;
    return t;
}

glm::vec3 mappedNormal(const Texture& map, float scale, glm::vec2 uv, const glm::vec3& normal,
                       const SurfaceTangents& tangents) {
    const glm::vec3 texel(map.lookup(uv));
    const glm::vec3 local(scale * (2.0f * texel.x - 1.0f), scale * (2.0f * texel.y - 1.0f), 2.0f * texel.z - 1.0f);
    // The flat texel (0.5, 0.5, 1) leaves the normal as it is, bit for bit.
    if (local.x == 0.0f && local.y == 0.0f && local.z > 0.0f) return normal;
    const glm::vec3 t = tangents.dpdu - glm::dot(tangents.dpdu, normal) * normal;
    const float tLength = glm::length(t);
    if (!(tLength > 0.0f)) return normal;
    const glm::vec3 tangent = t / tLength;
    glm::vec3 bitangent = glm::cross(normal, tangent);
    if (glm::dot(bitangent, tangents.dpdv) < 0.0f) bitangent = -bitangent;  // mirrored UVs
    const glm::vec3 mapped = local.x * tangent + local.y * bitangent + local.z * normal;
    const float length = glm::length(mapped);
    return length > 1e-6f && std::isfinite(length) ? mapped / length : normal;
}

}  // namespace strata

namespace strata {

bool looksLikeNormalMap(const Texture& image) {
    const glm::vec4 mean = image.mean();
    if (image.channels() < 3 || !(mean.b >= 0.6f && mean.b > mean.r + 0.1f && mean.b > mean.g + 0.1f)) {
        return false;
    }
    double length = 0.0;
    for (int y = 0; y < image.height(); ++y) {
        for (int x = 0; x < image.width(); ++x) {
            length += glm::length(2.0f * glm::vec3(image.texel(x, y)) - 1.0f);
        }
    }
    length /= static_cast<double>(image.width()) * image.height();
    return std::abs(length - 1.0) <= 0.2;
}

}  // namespace strata
