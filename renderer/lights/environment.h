#pragma once
// What a ray that leaves the scene sees, as a scene is given it (MeshData::environment), and the
// light at infinity it becomes: none, a uniform radiance (uniform_environment_light.h) or a
// latitude-longitude HDR map (environment_map_light.h).
//
// The default rule: a scene given no environment is lit by a uniform environment of radiance 1,
// under which a diffuse surface that sees only the sky shows its albedo (notes section 5.3),
// unless its own lights outshine that sky (scene_lights.h says when); then it stays dark outside.
#include <cstddef>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>
#include <glm/vec3.hpp>

#include "lights/environment_map.h"
#include "lights/light.h"
#include "textures/texture_budget.h"

namespace strata {

struct Environment {
    enum class Kind { Default, None, Uniform, Map };
    Kind kind = Kind::Default;                  // Default: by the rule above
    glm::vec3 radiance{1.0f};                   // Uniform: from every direction
    std::shared_ptr<const EnvironmentMap> map;  // Map: as readEnvironmentMap gives it
    float rotationDegrees = 0.0f;               // Map: turned about the up axis +y
};

// The radiance of the default environment.
inline constexpr float kDefaultSkyRadiance = 1.0f;

// The environment after the default rule, given whether the scene's own lights outshine the
// default sky; a black uniform environment becomes none.
Environment resolveEnvironment(const Environment& given, bool lightsOutshineSky);
// The largest radiance component the environment sends (for the truncation bound's Le_max).
float maxRadiance(const Environment& environment);
// The light of a resolved environment, or nullptr for none. `sceneRadius` is the radius of the
// scene's bounding sphere, which the light's power needs (light.h).
std::unique_ptr<Light> makeEnvironmentLight(const Environment& resolved, float sceneRadius);

// Lossily compressed EXRs (DWAA/DWAB, as Blender's bundled maps are) ring slightly below 0 beside
// bright texels, down to about 3% of the map's mean radiance in the maps measured: components down
// to this fraction of the mean, negated, are that noise.
inline constexpr float kNegativeNoise = 0.05f;

// A map as read, its sampling distribution built, with the count of slightly negative texel
// components read as 0.
struct EnvironmentMapFile {
    std::shared_ptr<const EnvironmentMap> map;
    size_t zeroedNegatives = 0;
    uint64_t bytes = 0;  // its decoded texels, as the texture budget counts them
};
// Reads a latitude-longitude environment map: an EXR twice as wide as high whose texels are
// finite and >= 0, lossy-compression noise read as 0. Throws strata::Error naming the file for
// any other image: not 2:1, a texel more negative than that noise, or one not finite; and,
// before its texels are allocated, for one that would take `budget` over its limit (its texels
// count with the scene's textures, TextureBudget::reserve).
EnvironmentMapFile readEnvironmentMap(const std::filesystem::path& path,
                                      TextureBudget budget = TextureBudget());
// The same from the EXR file's bytes, as a scene bundle carries them; `name` stands for the file.
EnvironmentMapFile readEnvironmentMap(std::string_view bytes, const std::string& name,
                                      TextureBudget budget = TextureBudget());
// The same, taking the bytes: they are freed once decoded, before the sampling distribution is
// built, so that the file (as large as the map) and the distribution are never held at once.
EnvironmentMapFile readEnvironmentMap(std::string&& bytes, const std::string& name,
                                      TextureBudget budget = TextureBudget());

}  // namespace strata
