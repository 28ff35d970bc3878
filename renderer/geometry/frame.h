#pragma once
// An orthonormal frame around a unit normal: local +z is the normal. The tangents come from
// Duff et al., "Building an Orthonormal Basis, Revisited" (JCGT 2017): branchless, continuous
// except across n.z = 0's sign flip, and with no singularity at n = -z. The 24 strata are defined
// in this local frame, so the frame must be a fixed function of the normal (it is).
#include <glm/vec3.hpp>

namespace strata {

struct Frame {
    glm::vec3 tangent;
    glm::vec3 bitangent;
    glm::vec3 normal;

    static Frame fromNormal(const glm::vec3& n);

    glm::vec3 toWorld(const glm::vec3& local) const {
        return tangent * local.x + bitangent * local.y + normal * local.z;
    }
    glm::vec3 toLocal(const glm::vec3& world) const;
};

}  // namespace strata
