#pragma once
// The cosine and sine of an angle given in turns (1 turn = 2 pi), the form in which samplers hold
// an azimuth (phi = 2 pi u). The angle is split into the nearest quarter turn and a remainder of
// at most an eighth of a turn, whose cosine and sine are short Taylor polynomials; the quarter
// turn only swaps and negates them, chosen without a branch (a sampled azimuth's quadrant is
// random). The split is exact, so the results are within 2e-7 of the exact values and the sine of
// a small angle keeps its relative precision (tests/util/test_turns.cpp), where the C library's
// sincosf is a call that first reduces its argument modulo 2 pi.
#include <glm/vec2.hpp>

namespace strata {

// (cos 2 pi t, sin 2 pi t) for t in [0, 1].
inline glm::vec2 cosSinOfTurns(float turns) {
    const float quarters = 4.0f * turns;
    const int quarter = static_cast<int>(quarters + 0.5f);
    // The remainder, |x| <= pi/4: the angle is quarter pi/2 + x.
    const float x = (quarters - static_cast<float>(quarter)) * 1.57079632679489662f;
    const float x2 = x * x;
    // Taylor series to x^9 and x^8: the first terms left out are under 3e-8 on |x| <= pi/4.
    const float s =
        x * (1.0f - x2 * (1.0f / 6.0f) *
                        (1.0f - x2 * (1.0f / 20.0f) * (1.0f - x2 * (1.0f / 42.0f) * (1.0f - x2 * (1.0f / 72.0f)))));
    const float c =
        1.0f - x2 * 0.5f * (1.0f - x2 * (1.0f / 12.0f) * (1.0f - x2 * (1.0f / 30.0f) * (1.0f - x2 * (1.0f / 56.0f))));
    // Each quarter turn maps (cos, sin) to (-sin, cos).
    const int q = quarter & 3;
    const float a = (q & 1) ? s : c;
    const float b = (q & 1) ? c : s;
    return {(q == 1 || q == 2) ? -a : a, q >= 2 ? -b : b};
}

}  // namespace strata
