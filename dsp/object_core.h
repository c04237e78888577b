// The part of an object's box the SAD stereo match reads, its core: the
// object's disparity is its core's (and, from the tiled depth's size on,
// the seed of its tiles' search, dsp/object_depth.h).
//
// Two shapes, both centred on the box:
// - square: the box less one seventh of its width and height a side (2 px
//   under 16 px, a fifth from 16 px to round_core_min_side). A round object
//   fills only pi/4 of its box; the corners are background at another depth
//   and pulled the disparity towards it (measured +1.5 % to +2 % depth at
//   2.2 m, background at 5 m). A core of side c is inside a disc of diameter
//   w when c <= w / sqrt(2): at a seventh c = 0.714 w, its corners on the
//   rim (0.02 % of it background; at an eighth 0.67 %, and a 62 px ball
//   spinning about x was 1.17 % far in one pair, 0.60 % at a seventh), its
//   mean surface 0.13 r nearer than the whole visible surface's (0.11 r at
//   an eighth; at a sixth 0.16 r, which took four 90 px balls past 1 %
//   near). Below 16 px a seventh rounds down to 1 px, which leaves the
//   corners of a small disc's core on the background: 2 px (the 10 px ball's
//   depth error 1.02 % in one pair with 1 px, 0.37 % with 2 px). From 16 px
//   to the round core's size, a fifth: a small ball's box is 1-3 px too
//   large or off (a pixel is 5-6 % of it), which put a seventh's corners on
//   the background: balls of 17-22 px were 1.01-1.29 % far at a pair
//   (0.54-0.88 % with a fifth), a 17 px one 70 % (5.3 %). A fifth on every
//   untiled ball failed 77 box cases of balls of 60 px or more at stop 80
//   (a core's surface nearer than the ball's).
// - round: the ellipse inscribed in the box less a tenth a side, for an
//   object of round_core_min_side to round_core_max_side px a side (under
//   the tiled depth's size its core's disparity is its depth). The
//   square's corners lie on the rim (0.505 of the width from the centre),
//   so a box 2-3 px too wide or off puts them on the background: balls of
//   38-55 px had their depth 1.01-1.45 % off at a pair (a 43 px ball, its
//   box 48 px wide and 3 px off its left side: 0.29 px of disparity far). The
//   ellipse stays 0.1 of the width inside the rim; its mean surface 0.15 r
//   nearer than the visible one's (the square's 0.13 r). Under 24 px it
//   has too few pixels (balls of 14 and 17 px went 0.9 and 0.2 % further
//   off); from 60 px the square's corners gave no far depth in the box
//   cases and the ellipse lost four of them (a 70 px ball spinning about y
//   over venus 0.56 -> 1.52 %, an 82 px one 0.94 -> 1.05 %, two going
//   away a side or a mean just past its bound).
// Costs: the round core's match is charged as its whole box's.
#pragma once

#include "dsp/image.h"
#include "dsp/object_depth.h"
#include "dsp/stereo_sad.h"

namespace dsp {

constexpr int round_core_min_side = 24;
constexpr int round_core_max_side = 60;
constexpr int max_round_core_rows = round_core_max_side;  // a round core's rows at most

struct object_core_pattern {
    box core;            // the pattern's box
    bool round = false;  // matched on the ellipse inscribed in `core` (the spans)
    int pixels = 0;      // the pixels matched
};

// `spans`: max_round_core_rows rows, the round core's (relative to
// `core`) when it is round.
object_core_pattern object_core(box object, const object_depth_params& surface, row_span* spans);

}  // namespace dsp
