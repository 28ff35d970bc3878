#pragma once
#include <glm/vec3.hpp>

namespace strata {

struct Ray {
    glm::vec3 origin;
    glm::vec3 direction;  // unit length
};

}  // namespace strata
