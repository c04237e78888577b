// An object's image size from the depth the stereo stages measured: a ball's
// diameter in pixels is f D / Z, so proportional to its disparity less the
// principal points' offset. The size rules of TRACK (dsp/box_refit.h,
// dsp/extent_window.h) keep the last box's size where the differences
// measure it short, since there a rim was missed (a shaded side under the
// threshold); a ball going away from the rig shrinks alike on every side
// and was held at its first size (150 px at 2.6 m, 1.45 times as far 20
// pairs later: its box 144 x 147 px on a ball of 99 px, 23 px off). So the
// last box is carried to the last pair's disparity before the rules compare
// sizes with it, and a key's box from the key's pair's to the last pair's.
#pragma once

#include <cstdint>

#include "dsp/box_refit.h"
#include "dsp/image.h"

namespace dsp {

// `b` resized about its centre by to_q8 / from_q8 (disparities less the
// principal points' offset, Q8), each side rounded to the nearest pixel;
// `b` itself where either is unknown (<= 0) or the ratio changes the size by
// under 1 % (within a disparity's noise: the depth of every box case that
// passes errs by 0.83 % at most).
box at_disparity(box b, int64_t from_q8, int64_t to_q8);

// `b` as `width` x `height` about its centre.
box resized_about_centre(box b, int width, int height);

// True where a pair's disparity is over an eighth from the last pair's: not
// the object's depth (a wrong match; a ball going away at 1 depth a second
// changes it by 2.5 % a pair).
bool disparity_jumped(int64_t from_q8, int64_t to_q8);

// Whether a box the track kept at its size (`kept`, the size it had at
// `sized_q8`) still stands for that depth after a pair that measured
// `now_q8`, with `silhouette` (object(t-1)'s extent) read: where the object
// went away, its silhouette smaller on both axes and the disparity not
// jumped. The rules do not take a size the differences measure short (a
// missed rim), so going away only the depth shrinks the box, and a fall
// under at_disparity's 1 % each pair, restarted from each pair's depth,
// never moved a side: a 33 px ball thrown at the wall was held at 34 x 33 px
// for 20 pairs while it shrank to 27 px. Kept, the fall adds up until it
// does. Coming nearer, the silhouette grows the box.
bool size_still_stands(box kept, box silhouette, int64_t sized_q8, int64_t now_q8);

// The window's extents (dsp/extent_window.h: `extents[k]`, read when the
// track's disparity was `depth_q8[k]`) as an object of `size` px at `now_q8`
// would have made them, for window_axis, which takes one size over the
// window: each narrowed about its centre by how much larger the object was
// then, size (depth_q8[k] / now_q8 - 1), where that is 1 % or more. On an
// 80 px ball going away at 25 px a pair the fit with the extents as read
// stood 3-5 px ahead of it. An object that was smaller (coming nearer) is
// left as read: a difference reads inside the object, so an older, smaller
// extent only loosens the fit's bounds, while one widened may pass a rim
// (a 100 px ball coming nearer over teddy: 2.89 / 5.62 -> 4.02 / 8.80 px).
void extents_at_depth(const span* extents, const int64_t* depth_q8, int count, int size,
                      int64_t now_q8, span* out);

// A key's object on one axis at the depth now, from Dif(key, t)'s extent
// read less the key's displacement `shift` (keyed_axis: `read`). That
// difference holds the object where the key was and where it is, so where
// it moved further than it grew or shrank on a side, its leading end is
// the object's now and its trailing end the key's object's: read as it
// was, a 40 px ball coming nearer at 2 px a pair was 7 px narrow after 6
// pairs. Its size now is the key's (`key_size`) times now_q8 / key_q8, kept
// at that leading end. Not the reading less the displacement (the mean of
// the two sizes): a shrinking ball's pattern reads its displacement short
// (16 px of 24 on a 60 px ball going away), which left its box 7 px wide.
// Where it grew or shrank more than it moved, both ends of the extent are
// the object's now (grown) or the key's (shrunk): the extent, or the key's
// object at the depth now, moved. Where it shrank inside the key's box,
// the key's pattern does not read its displacement either, on a texture
// that shrinks (a 60 px ball going away over aloe went 4 px down in 15
// pairs, the pattern read 0 to -1 px, and the box rode 4-6 px above it);
// the silhouette `outline` (track_object's box; null if none) sees the
// whole rim move as it shrinks, and the object at the depth is centred on
// it where the outline is that size (within 2 px or an eighth) and inside
// the key's box (its centre at most half the shrink, + 1 px, from where the
// displacement read puts it). `read` itself where the ratio is under 1 % or
// either disparity unknown.
span keyed_span_at_depth(span read, int shift, int key_size, int64_t key_q8, int64_t now_q8,
                         const span* outline);

}  // namespace dsp
