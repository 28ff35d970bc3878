#pragma once
// What the image shows where the camera sees no surface, apart from the light that leaves the
// scene. The environment (lights/environment.h) lights the scene and is what every reflected or
// refracted ray sees; the backdrop replaces it only for camera rays that leave the scene at once,
// the first ray of a path (ProgressiveRenderer applies it; the integrator reports which camera
// rays found a surface). A ray refracted through glass toward the camera is not a camera ray and
// sees the environment.
//
// The default (Automatic) follows the environment: a scene lit by the default sky shows a soft
// grey gradient, so that a white model, which reads exactly that sky's radiance 1, stands out
// against it; an environment the user or the scene description gives is seen as it is, so that
// measurements of a given sky (--env-color 1 1 1) keep their meaning.
#include <optional>
#include <string_view>
#include <glm/vec3.hpp>

namespace strata {

struct BackdropSetting {
    enum class Kind { Automatic, Environment, Gradient, Colour };
    Kind kind = Kind::Automatic;
    glm::vec3 colour{0.0f};  // Colour: linear radiance
    bool operator==(const BackdropSetting&) const = default;
};

// The command line's spelling: "env", "gradient", a grey "V" or a colour "R,G,B" (finite
// radiances >= 0); nullopt for anything else.
std::optional<BackdropSetting> parseBackdrop(std::string_view text);
// "env|gradient|V|R,G,B", for option help and messages.
inline constexpr const char* kBackdropSyntax = "env|gradient|V|R,G,B";

class Backdrop {
public:
    // The gradient's linear radiance at the image's top and bottom edges (grey).
    static constexpr float kGradientTop = 0.30f;
    static constexpr float kGradientBottom = 0.08f;

    // `setting` resolved for a scene that is (or is not) lit by the default sky.
    Backdrop(const BackdropSetting& setting, bool litByDefault);

    // Whether camera rays that miss show the environment: then nothing is replaced.
    bool showsEnvironment() const { return kind_ == BackdropSetting::Kind::Environment; }
    // The radiance a camera ray that misses shows, through image height `v` (0 at the top edge,
    // 1 at the bottom); only when !showsEnvironment().
    glm::vec3 radiance(float v) const;

private:
    BackdropSetting::Kind kind_;
    glm::vec3 colour_;
};

}  // namespace strata
