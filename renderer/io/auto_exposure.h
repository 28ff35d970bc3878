#pragma once
// The exposure a display starts from when none is given. It is taken once, from the first image
// (the first pass of `strata render`, the viewer's first whole image), and kept, so that the
// picture does not pump as it converges.
//
// It is the exposure that maps the image's log-average luminance to the key 0.18 (middle grey),
// as Reinhard et al.'s photographic tone reproduction (2002) and cameras' auto-exposure do,
// unless that would burn out the image's bright part: then the exposure that puts the luminance
// of the brightest tenth of the image at kHighlightLimit. A log-average is ruled by the dark part
// of an image of high contrast, a stage lit by a few spots say (most of the frame far dimmer
// than the pools of light, which it would expose to white); the brightest tenth is a part of the
// picture, not a lamp seen in a corner of it, which the display's curve may burn out.
//
// Both run over blocks of kExposureBlock x kExposureBlock pixels, each by its mean luminance,
// weighted by its pixel count: a block's mean of even one path per pixel is a fair estimate, where
// the logarithm of single noisy samples would drag the average down (a sample of zero has no
// logarithm at all). Blocks that are black (nothing there, or no light found yet) are left out.
#include "io/image_io.h"

namespace strata {

inline constexpr double kExposureKey = 0.18;
inline constexpr int kExposureBlock = 8;
// The share of the blocks' pixels that counts as the image's bright part, and the scaled
// luminance it may reach: the default display curve (io/tonemap.h, ACES) shows 1 at 0.80 of
// white, where it still has contrast; it is within 3% of white from 4 on.
inline constexpr double kHighlightShare = 0.1;
inline constexpr double kHighlightLimit = 1.0;
// The exposure stays in [-kExposureLimit, kExposureLimit] stops.
inline constexpr float kExposureLimit = 24.0f;

// In stops; 0 for an image with no block above black.
float autoExposure(const Image& image);

}  // namespace strata
