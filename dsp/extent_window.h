// A fast object's box from the frame differences of its last pairs, not
// from the current pair's alone. Each Dif(t-1,t) extent is read inside the
// object's, never outside it: a rim whose grey is within the threshold of
// the background behind it is missed (a ball's shaded side over a dark
// background: 3-14 px of 40-80 px balls at 25-30 px per frame over teddy), and
// nothing outside object(t-1) and object(t) differs. So the current
// extent's leading edge may stand short of object(t)'s, and a box placed
// from it stands behind the ball; while the same rim read a pair or two
// earlier, or the trailing rim read now, still bounds where the ball is.
//
// window_axis fits a velocity to the last extents, and its change from pair
// to pair where every edge shows one (a ball turning on a circle), each rim
// a one-sided bound, and places object(t) inside every bound.
#pragma once

#include <cstdint>

#include "dsp/box_refit.h"

namespace dsp {

// Dif(t-1,t)'s extents on both axes over the last pairs of one track,
// newest first.
struct extent_window {
    static constexpr int capacity = 4;
    span x[capacity], y[capacity];
    int64_t depth_q8[capacity] = {};  // the disparity the track last measured, at each (0 none)
    int count = 0;

    void clear() { count = 0; }
    void push(span new_x, span new_y, int64_t disparity_q8 = 0);
    // Extents read with no disparity (0) take `disparity_q8`.
    void give_depth(int64_t disparity_q8);
};

// The object's motion per pair on one axis as the window reads it: the
// median of both edges' steps between consecutive extents (newest first,
// towards the axis's end positive), in half pixels. A rim the differences
// miss moves its own edge only, so the median holds while the current
// extent's reach past object(t-1) reads no motion (a 140 px ball at 6 px
// per frame over teddy: its leading edge 26-35 px short, the extent's reach
// 0). 0 with fewer than three extents, or where an extent is under half
// `size` (pieces of a slowly turning texture, not the object's outline).
int window_step2(const span* extents, int count, int size);

// A slower object's leading rim missed more from pair to pair (a receding
// ball's shaded side entering a dark background: over teddy the leading
// edge of a 90 px ball stood while the ball moved 3.7 px a pair, and the
// median of both edges' steps read 1.5 px): its trailing edge stepped at
// least 3 px every pair of the window the way it moves (more than a slow
// object moves: key_frame::max_step; at 2 px a 150 px ball passing at 1.5
// px a frame was read so, its extent once 4 px short) and stands within
// 4 px of the last box's, and the leading edge's steps lag the trailing
// edge's by 1 px a pair or more. Each is the object's motion in the same
// pair, the leading edge's a pair earlier in the window, plus the object's
// growth, read from the disparities (`depth_q8`, 0 none): a slow ball going
// away, a ball whose speed changes (a throw near its apex) or a texture
// piece does not lag so. Returns the trailing edge's mean step in half
// pixels (towards the axis's end positive), 0 where the rim does not fade
// or with fewer than three extents. Not a spinning ball's texture either
// (its pieces cross the ball 2-8 px a pair, inside the last box), nor a
// leading edge that moves while the trailing one stands (it is object(t)'s
// own).
int fading_rim_step2(const span* extents, const int64_t* depth_q8, int count, span last);

// object(t), `size` wide, from Dif(t-1,t)'s extent `now` whose trailing
// edge (object(t-1)'s) moves step2 half pixels a pair: that edge one step on.
span from_trailing_edge(span now, int step2, int size);

// object(t)'s extent on one axis, `size` wide, from the window's extents
// on that axis (`extents[k]`: Dif(t-1-k, t-k)'s) and the last box `last`.
// With the velocity v (px per pair) in the last pair, changing by a every
// pair, the extent k pairs back spans object(t-k-1) and object(t-k), which
// stood b_k = k v - a k (k - 1) / 2 behind object(t) and moved v_k = v - k a;
// so with object(t) at s:
//   s <= start_k + b_k + max(v_k, 0)          (its start reads inside)
//   s >= end_k - size + b_k + min(v_k, 0)     (its end reads inside)
// a is read from a full window: the median of both edges' second
// differences where all of them change the same way by 1 px or more and
// the median by over 1 px (less is the extents' rounding), else 0. On a
// 44 px ball circling at 20 px a frame, one velocity over the window was
// the ball's speed a pair or two back, and put the box 5-7 px past the
// ball. v is searched in half pixels within 8 px of the median step of the
// extents' edges plus a: the one whose bounds cross least is taken (among
// equals, the one nearest that). object(t) is the last box moved by v, held
// inside the bounds (midway where they cross: the size or the velocity
// changed). Where one side's bounds agree within 1 px over the window and
// the other side's spread over 2 px, that side read the rim in every pair:
// object(t) is placed on its bound (a 40 px ball over teddy: its shaded
// bottom read 2-7 px short in five of seven pairs, its top alike in every
// pair; moved by v, the box kept the lag it had). False, and nothing
// written, with fewer than three extents.
bool window_axis(const span* extents, int count, int size, span last, span* object);

}  // namespace dsp
