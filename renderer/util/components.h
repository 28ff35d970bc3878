#pragma once
// A colour or extent reduced to one number (its largest, smallest or mean component) or to
// whether it is zero.
#include <glm/common.hpp>
#include <glm/vec3.hpp>

namespace strata {

inline float maxComponent(const glm::vec3& v) { return glm::max(glm::max(v.x, v.y), v.z); }
inline float minComponent(const glm::vec3& v) { return glm::min(glm::min(v.x, v.y), v.z); }
inline float meanComponent(const glm::vec3& v) { return (v.x + v.y + v.z) / 3.0f; }
inline bool isZero(const glm::vec3& v) { return v.x == 0.0f && v.y == 0.0f && v.z == 0.0f; }

}  // namespace strata
