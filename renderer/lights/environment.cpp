#include "lights/environment.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "io/exr_header.h"
#include "io/image_io.h"
#include "lights/environment_map_light.h"
#include "lights/uniform_environment_light.h"
#include "util/error.h"
#include "util/components.h"
#include "util/text_file.h"

namespace strata {
namespace {

// readEnvironmentMap's checks, on the image read from the file `name` stands for.
EnvironmentMapFile checkedMap(Image map, const std::string& name) {
    if (map.width != 2 * map.height) {
        throw Error(name + ": an environment map must be a latitude-longitude image twice as "
                    "wide as high, got " + std::to_string(map.width) + "x" + std::to_string(map.height));
    }
    const auto refuse = [&](size_t i, const char* what) {
        throw Error(name + ": texel (" + std::to_string(i % map.width) + ", " +
                    std::to_string(i / map.width) + ") is " + what + "; an environment map holds radiances");
    };
    double sum = 0.0;
    for (size_t i = 0; i < map.pixels.size(); ++i) {
        const glm::vec3& texel = map.pixels[i];
        if (!(std::isfinite(texel.x) && std::isfinite(texel.y) && std::isfinite(texel.z))) refuse(i, "not finite");
        sum += static_cast<double>(texel.x) + texel.y + texel.z;
    }
    const double floor = -kNegativeNoise * sum / (3.0 * static_cast<double>(map.pixels.size()));
    EnvironmentMapFile file;
    for (size_t i = 0; i < map.pixels.size(); ++i) {
        for (int c = 0; c < 3; ++c) {
            float& value = map.pixels[i][c];
            if (value >= 0.0f) continue;
            if (value < floor) refuse(i, "negative beyond lossy-compression noise");
            value = 0.0f;
            ++file.zeroedNegatives;
        }
    }
    file.map = std::make_shared<const EnvironmentMap>(std::move(map), name);
    return file;
}

// A map's texels as decoded from its file, within `budget`, and what they take of it.
struct DecodedMap {
    Image image;
    uint64_t bytes;
};

DecodedMap decodedMap(std::string_view bytes, const std::string& name, TextureBudget& budget) {
    const TextureSize size = readExrHeader(bytes, name);
    budget.reserve(size, name + ": the environment map");
    return {readExr(bytes, name), size.bytes()};
}

// The decoded map checked, and its sampling distribution built (EnvironmentMap).
EnvironmentMapFile mapOf(DecodedMap decoded, const std::string& name) {
    EnvironmentMapFile file = checkedMap(std::move(decoded.image), name);
    file.bytes = decoded.bytes;
    return file;
}

}  // namespace

Environment resolveEnvironment(const Environment& given, bool lightsOutshineSky) {
    Environment resolved = given;
    if (given.kind == Environment::Kind::Default) {
        resolved.kind = lightsOutshineSky ? Environment::Kind::None : Environment::Kind::Uniform;
        resolved.radiance = glm::vec3(kDefaultSkyRadiance);
    }
    if (resolved.kind == Environment::Kind::Uniform && !(maxComponent(resolved.radiance) > 0.0f)) {
        resolved.kind = Environment::Kind::None;
    }
    return resolved;
}

float maxRadiance(const Environment& environment) {
    switch (environment.kind) {
        case Environment::Kind::Uniform: return maxComponent(environment.radiance);
        case Environment::Kind::Map: return environment.map->maxRadiance();
        case Environment::Kind::Default:
        case Environment::Kind::None: break;
    }
    return 0.0f;
}

std::unique_ptr<Light> makeEnvironmentLight(const Environment& resolved, float sceneRadius) {
    switch (resolved.kind) {
        case Environment::Kind::Uniform:
            return std::make_unique<UniformEnvironmentLight>(resolved.radiance, sceneRadius);
        case Environment::Kind::Map:
            return std::make_unique<EnvironmentMapLight>(resolved.map, resolved.rotationDegrees, sceneRadius);
        case Environment::Kind::Default:
        case Environment::Kind::None: break;
    }
    return nullptr;
}

EnvironmentMapFile readEnvironmentMap(const std::filesystem::path& path, TextureBudget budget) {
    if (!std::filesystem::is_regular_file(path)) throw Error(path.string() + ": no such EXR file");
    return readEnvironmentMap(readTextFile(path, "EXR file"), path.string(), budget);  // the bytes taken
}

EnvironmentMapFile readEnvironmentMap(std::string_view bytes, const std::string& name, TextureBudget budget) {
    return mapOf(decodedMap(bytes, name, budget), name);
}

EnvironmentMapFile readEnvironmentMap(std::string&& bytes, const std::string& name, TextureBudget budget) {
    DecodedMap decoded = decodedMap(bytes, name, budget);
    std::string().swap(bytes);
    return mapOf(std::move(decoded), name);
}

}  // namespace strata
