// Where a box that may be a part of its object (a detection's, until a
// silhouette of its size confirms it: box_may_be_part) takes object(t-1)'s
// extent, both frame differences' common part, as it is (TRACK's
// follow_object, dsp/controller_track.cpp). The three-frame AND of a slow
// spinning ball holds where its texture changed most (a detection 67 x 34
// px of a 110 px ball, 88 px wide of 140), while both differences hold the
// whole ball; that of a large ball moving along an axis leaves a sliver (a
// 35 x 11 px detection of a 160 px ball thrown up).
#pragma once

#include "dsp/image.h"
#include "dsp/triangulate.h"

namespace dsp {

// What the two frame differences gave around the last box.
struct difference_extents {
    box before;    // Dif(t-2,t-1)'s extent
    box after;     // Dif(t-1,t)'s extent
    box previous;  // object(t-1): the two extents' common box
};

// The axes on which a part's box takes the common part.
struct part_growth {
    bool x = false, y = false;
    bool round_read = false;  // the common part tested for a sphere's shape (is_round)
};

// Nothing unless `may_be_part` (later in a track, at a bounce, the common
// part holds the ball and where it was and will be), and neither axis where
// Dif(t-1,t) is a part of the object (`part_x`, `part_y`: is_part).
// - Per axis where the object is slow on that axis (both differences'
//   edges on it within key_frame::min_shift px of each other; the other
//   axis's edges may move: a throw rising 8 px a frame grows on x), the
//   common part holds the last box `last` on it and is over an eighth
//   (at least 2 px) larger. Not per axis for a fast object: a throw's first
//   common part is over an eighth larger than its detection.
// - On both axes at any speed where the common part holds the box on both,
//   is over an eighth larger on one, is clear of the image border
//   (`previous_at_border`) and has a sphere's shape (dsp/round_box.h,
//   is_round): object(t-1) whole.
part_growth grow_part(const difference_extents& extents, box last, bool may_be_part, bool part_x,
                      bool part_y, bool previous_at_border, const camera_rig& rig);

}  // namespace dsp
