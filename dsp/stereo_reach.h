// How far an object reaches past its box's sides (and, turned by a
// quarter, past its top and bottom), read from the stereo pair rather than
// from the differences.
//
// A side of an object that does not move in the image is outlined by no
// difference: a ball coming nearer while it moves right grows at its left
// as fast as it goes right, so its left rim stands still (held-out round
// 25's 120 px ball over kodim19: 0.2-0.3 px a frame; its box 23-31 px
// narrow for its whole run), and a trailing rim the colour of what it
// passes fades from both differences (round 26's 100 px ball over teddy's
// dark box, 13 px short). The stereo pair still outlines it: the object
// stands nearer than what is behind it, so a tile of the object matches
// in the left image at the object's disparity, a tile of background at
// its own (round 25 at frame 12: 8 x 16 px tiles left of the box matched
// at 43-46 px on the ball, 19 px on the background, the rim's tile at 43).
//
// Computes, per side, tiles of tile_width x band_height px on the box's
// centre rows (a round object's widest chord), read in the image whose
// camera sees past that side: left of the object the right image (matched
// at x + d in the left), right of it the left image (at x - d in the
// right; there the right camera's background is hidden by the object for
// d_object - d_background px, and matches nowhere). The first tile starts
// `spread` px inside the box's side (the right side's at x + d_object in
// the left image), each next one `step` px further out, as long as a tile
// is the object's:
//   SAD(d) over the search's disparities (the tile inside both images),
//   the tile's: min over |d - d_object| <= spread  <  clear_num / clear_den
//               x min over the other disparities,
//   and at most gate_factor x the object's SAD a pixel + gate_floor_per_pixel
//   a pixel of the tile
// (a flat tile of background matches about equally everywhere, and is not
// taken). Where a tile is not, and the next one is not either (past an
// object's end the background goes on; one tile between two of the
// object's is a flat patch), the object ends between the first of them
// and the last tile that was: each column of the two is read at the last
// one's best disparity (the object's, the rim's) and at its own best
// elsewhere (what is behind, its SAD at most the gate), and the end is
// the split with the least SAD, the columns nearer the box the object's
// (past an end a row's SAD as the object's weighed x clear_den, as
// background x clear_num, as clearly as a tile must be, so that a row of
// flat background stays background).
// (A tile part object, part background is taken by whichever has the
// stronger texture, so its middle misses the end by up to half a tile.)
// The right side's end is brought back to the right image at the rim's
// disparity. The reach is from the box's side, 0 to max_reach px; no tile
// the object's: 0; every tile to the bound the object's, its end not met:
// 0 (asked at a wrong disparity, the background's, the background's tiles
// match there, and the side went out by its whole bound, half the box);
// the image's edge met: the object ends there.
// The object nearer than its background by more than `spread` is checked
// where a side reaches out: the first tile past the probe's bound (beyond
// where the object can reach) must not be the object's, else the
// background beside it lies within the object's disparity span, matches
// as the object does, and the side's reach is 0. A ball at the wall it
// was thrown at (at the wall's disparity) read the wall's tiles as its
// own up to a flat patch two tiles wide, which ended the run: widened
// 25-43 px on both axes at its bounce (70-74 px balls).
// d_object is the object's integer disparity (its core's), spread its
// disparity span (object_depth.h).
// Assumes: a rectified pair (the tile's rows only); a background as near
//   beside the object as on the far tile (one within the span nearer the
//   object only still matches as the object: a ball 0.5 m before a wall
//   was widened 17-50 px to a flat patch of it; the patch's next tile, the
//   object's again, carries the reach on to its bound, where it moves
//   nothing).
// Costs: per tile a SAD search (dsp::cost::sad_search_cycles), the far
//   tile's among them; per split its columns read at two disparities
//   (charged as a SAD search of split_columns x band_height at 2
//   positions).
#pragma once

#include "dsp/image.h"
#include "dsp/stereo_sad.h"

namespace dsp {

struct stereo_reach_params {
    int tile_width = 8;
    int band_height = 16;
    int step = 4;
    int clear_num = 3;             // a tile is the object's when its minimum there is
    int clear_den = 4;             // under clear_num / clear_den of the best elsewhere
    int gate_factor = 4;           // ... and at most this x the object's SAD a pixel
    int gate_floor_per_pixel = 4;  // ... plus this (object_depth.h's gate)
};

struct stereo_reach {
    int left = 0;           // px the object reaches past the box's left side
    int right = 0;          // ... past its right side
    int up = 0;             // ... past its top (reach_past_ends)
    int down = 0;           // ... past its bottom
    int tiles = 0;          // tiles searched
    int positions = 0;      // SAD positions over all tiles (for the cost model)
    int split_columns = 0;  // lines read where the object's end was split
};

// The object's stereo match: its integer disparity, its disparity span
// (object_depth.h's spread) and its SAD a pixel (Q8, 256 = 1 grey level).
struct object_match {
    int disparity = 0;
    int spread = 2;
    uint32_t sad_per_pixel_q8 = 0;
};

stereo_reach reach_past_sides(gray_cplane right, gray_cplane left, box object,
                              const object_match& match, int max_reach, const stereo_params& search,
                              const stereo_reach_params& params);

// The same past the box's top and bottom: tiles of band_height columns
// (the box's centre columns, a round object's widest chord) x tile_width
// rows, stepped outwards by rows, both read in the right image (matched at
// x + d in the left): along a column neither camera sees past the object
// more than the other. A falling ball's shaded lower rim, the colour of
// what it passes, fades from both differences as a trailing rim does
// (held-out round 22's 60 px throw over venus: its box 3-6 px above the
// ball while it falls; at pair 20, tiles on its centre columns down to the
// ball's lower rim matched at 39-40 px, the ball's 38.6, venus's at 19).
stereo_reach reach_past_ends(gray_cplane right, gray_cplane left, box object,
                             const object_match& match, int max_reach, const stereo_params& search,
                             const stereo_reach_params& params);

// How far the object stops short of the box's sides (short_of_sides) and
// of its top and bottom (short_of_ends), in left, right, up and down: the
// mirror of the reach. A ball going away leaves its box's trailing side
// where it was larger, and no rule moved a side in (held-out round 30's
// 120 px ball over cones: its box 4-13 px too wide). Tiles of the same
// size, in the same image as the reach past that side, are read inwards
// from `step` px outside the side (a tile from the side in would take in
// the object where the box is less than a tile too large, and be over the
// gate) while they are clearly background: their best match outside the
// object's disparity span under clear_num / clear_den of their best within
// it, and within the gate. The object then starts between the last of
// them and the first that is not, split as an end is with the roles turned
// (the lines nearer the side at the background's disparity, the others at
// the next tile's, if it is the object's, else the object's). The right
// side's start, found in the left image, is brought back to the right
// image at the disparity of the tile just inside it: a round object's rim
// stands farther than its core (a 320 px ball's right rim at 71 px where
// its core matched at 80: brought back at 80, 9 px too many were taken
// off). 0 to max_trim px; the first tile not background: 0. Asked at a
// wrong disparity the object's own tiles match clearly elsewhere, so a
// side is moved in only where the object is met: a tile not background
// within max_trim + a tile, and at the right side (whose probe starts at
// the disparity asked) its rim's tile not clearly matched elsewhere; else
// 0 (unguarded, a box inside the object was moved in by its whole bound,
// a quarter of it). A box under three bands (48 px) either way is not
// read: a band on a smaller round object's centre rows runs off it at
// every side.
// Costs: as the reach's, and the right rim's tile.
stereo_reach short_of_sides(gray_cplane right, gray_cplane left, box object,
                            const object_match& match, int max_trim, const stereo_params& search,
                            const stereo_reach_params& params);
stereo_reach short_of_ends(gray_cplane right, gray_cplane left, box object,
                           const object_match& match, int max_trim, const stereo_params& search,
                           const stereo_reach_params& params);

}  // namespace dsp
