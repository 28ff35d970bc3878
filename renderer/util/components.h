#pragma once
// A colour or extent reduced to one number (its largest, smallest or mean component) or to
// whether it is zero, and its components' magnitudes.
#include <cmath>
#include <glm/common.hpp>
#include <glm/vec3.hpp>

namespace strata {

inline float maxComponent(const glm::vec3& v) { return glm::max(glm::max(v.x, v.y), v.z); }
inline float minComponent(const glm::vec3& v) { return glm::min(glm::min(v.x, v.y), v.z); }
inline float meanComponent(const glm::vec3& v) { return (v.x + v.y + v.z) / 3.0f; }
inline bool isZero(const glm::vec3& v) { return v.x == 0.0f && v.y == 0.0f && v.z == 0.0f; }
// The magnitudes of v's components. glm::abs compiles to a branch on each sign (x >= 0 ? x : -x,
// which keeps -0), and hit points around the origin of the coordinates make those branches
// unpredictable; clearing the sign bit takes no branch.
inline glm::vec3 magnitudes(const glm::vec3& v) { return {std::fabs(v.x), std::fabs(v.y), std::fabs(v.z)}; }

}  // namespace strata
