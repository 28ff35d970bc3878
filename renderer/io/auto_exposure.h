#pragma once
// The exposure a display starts from when none is given: the one that maps the image's
// log-average luminance to the key 0.18 (middle grey), as Reinhard et al.'s photographic tone
// reproduction (2002) and cameras' auto-exposure do. It is taken once, from the first image (the
// first pass of `strata render`, the viewer's first whole image), and kept, so that the picture
// does not pump as it converges.
//
// The log-average runs over blocks of kExposureBlock x kExposureBlock pixels, each by its mean
// luminance, weighted by its pixel count: a block's mean of even one path per pixel is a fair
// estimate, where the logarithm of single noisy samples would drag the average down (a sample of
// zero has no logarithm at all). Blocks that are black (nothing there, or no light found yet)
// are left out.
#include "io/image_io.h"

namespace strata {

inline constexpr double kExposureKey = 0.18;
inline constexpr int kExposureBlock = 8;
// The exposure stays in [-kExposureLimit, kExposureLimit] stops.
inline constexpr float kExposureLimit = 24.0f;

// In stops; 0 for an image with no block above black.
float autoExposure(const Image& image);

}  // namespace strata
