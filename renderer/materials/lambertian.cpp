#include "materials/lambertian.h"

#include <algorithm>

namespace strata {

bool allLambertian(const std::vector<Material>& materials) {
    // The same test LayeredBsdf uses for "has a specular layer".
    return std::all_of(materials.begin(), materials.end(), [](const Material& m) {
        return m.specular.x == 0.0f && m.specular.y == 0.0f && m.specular.z == 0.0f;
    });
}

}  // namespace strata
