// The disparity of a large object's visible surface as a whole (issue 17:
// depth within 1 % of the visible surface's mean depth for an object up to
// half the image wide).
//
// One SAD match of the object's core (dsp/controller_stereo.cpp object_core) sees a
// surface whose depth varies across the match: on a sphere 320 px wide at
// 1.4 m the visible surface spans 1.12-1.40 m, and the core's single
// disparity was 0.8-1.3 % nearer than the surface's mean depth. So a large
// object is cut into tiles (up to tiles_per_side x tiles_per_side over the
// whole box, each at least min_tile_side px), each tile is matched on its
// own in a narrow range around the core's disparity, and the depths of the
// tiles that matched the object are averaged:
//
//   spread = d_core * side / (2 f) + 2 px: the disparity span of an object
//            as deep as it is wide (a sphere: f B r / Z^2 with r = side Z / 2f),
//            plus the sub-pixel margin; d_core without the rig's principal
//            offset (disparity - (cx_left - cx_right)).
//   tile i:  stereo_match_sad in [d_core - spread, d_core + spread] (clipped
//            to the depth range's search); its minimum must lie strictly
//            inside that range and the left image (a tile of background has
//            its true minimum far outside the object's range) ...
//   gate:    ... and its SAD at most gate_median_factor x the median of those
//            tiles' SADs + gate_floor_per_pixel x the tile's area (a tile of
//            background can still find a false minimum inside the range, at
//            a SAD far above the object's tiles').
//   result:  the disparity of the kept tiles' mean depth, Z ~ 1 / (d - offset):
//            offset + sum n_i / sum n_i / (d_i - offset), n_i the tile's
//            pixels matched (its area unless outlined, below), each term
//            2^32 / (d_i - offset) in Q8 (relative rounding below 1e-5).
// Each kept tile counts once, so the mean weighs the surface by image area
// as the visible-surface mean does; a tile on the outline is kept when the
// object dominates its texture. On a sphere (numerical integral, 8 x 8 and
// 10 x 10 tiles): the tiles at least half on the disc give +0.08 % and
// +0.05 % of the visible mean, all tiles touching it +1.4 % and +0.9 %, the
// tiles wholly on it -3.4 % and -2.3 %: the outline's tiles decide it.
// tiles_per_side and the gate were chosen among 8, 12, 16 tiles and factors
// 2 and 4 on the host runs of tests/dsp/test_object_size.cpp (noise-free
// renders), then checked on sizes and co-simulated runs not used to choose.
// Tiled from 80 px (five tiles of 16 px a side, 21 of them on the disc):
// below that the core's one match on a smooth, spinning ball reads a flat
// SAD curve, and a pixel of core box moved it 0.3-1.4 px (85-100 px balls
// going away over teddy, 1.2-6.1 % far). From 64 px (four a side, 12 on
// the disc) the mean was noisier: a box case went past 1 %.
//
// Outlined (TRACK's box, the object's outline within a pixel or two): each
// tile is matched on its pixels inside the box's inscribed ellipse less
// outline_inset px a side only (stereo_match_sad_masked), its SAD scaled to
// a whole tile's for the gate, and its depth weighed by those pixels; a tile
// under a quarter on the ellipse is not searched. Without it an outline tile
// is mostly background by contrast over a cluttered photograph (a smooth,
// shaded ball), and its minimum leaned to the background side of the range:
// 100-130 px balls over the photographs were 1.0-1.8 % farther than their
// visible surface (at most 0.44 % with it). A detection's box (one pair's
// thin differences) may hold a part of the object only: not outlined, as
// before (a 240 px ball's first box, 43 px short, gave -1.04 % outlined).
// Assumes a round object: one that fills its box's ellipse (the ball).
//
// Assumes: object inside `right`; the core's match valid.
// Costs: per tile a SAD search of its positions plus the sub-pixel step;
//   the gate's sort and one 64-bit division per kept tile and one for the
//   mean: dsp::cost::sad_search_cycles, subpixel_cycles, surface_mean_cycles;
//   outlined, an ellipse span per row and a division per tile inside the
//   range: surface_outline_cycles.
#pragma once

#include <cstdint>

#include "dsp/image.h"
#include "dsp/stereo_sad.h"
#include "dsp/triangulate.h"

namespace dsp {

struct object_depth_params {
    int min_object_side = 80;  // tiled when the box's width or height is this or more
    int tiles_per_side = 16;   // at most 16
    int min_tile_side = 16;
    int gate_median_factor = 4;    // a tile's SAD at most this x the median tile's
    int gate_floor_per_pixel = 4;  // ... plus this a pixel
    int min_tiles = 4;             // fewer tiles kept: the core's disparity stands
    int outline_inset = 2;         // px: the outline's ellipse is the box's less this a side
    // The tiles' sub-pixel fit: the V through the integer SADs. Their mean
    // averages the fits' errors; the half-pixel step is the core's
    // (docs/firmware.md, "A sub-pixel step at half pixels").
    subpixel_fit tile_fit = subpixel_fit::equiangular;
};

struct object_depth_result {
    bool tiled = false;  // the box was cut into tiles (else the core's disparity stands)
    bool valid = false;  // at least min_tiles tiles matched; disparity_q8 is theirs
    int32_t disparity_q8 = 0;
    int tiles = 0;       // tiles searched
    int inside = 0;      // tiles whose minimum lay inside the range (the gate's input)
    int matched = 0;     // tiles kept
    int positions = 0;   // SAD positions over all tiles (for the cost model)
    int tile_width = 0;  // one tile's size (the grid's remainder is left out)
    int tile_height = 0;
    int columns = 0;  // the grid
    int rows = 0;
};

// The disparity span, px, of an object `side` px wide as deep as it is wide
// around the core's disparity (spread, above), plus two pixels of sub-pixel
// margin.
int surface_spread_px(int32_t core_q8, int side, const camera_rig& rig);

// Whether `object` is large enough to be tiled.
bool object_is_tiled(box object, const object_depth_params& params);

// core_q8: the core's disparity (Q8); search: the depth range's SAD search
// (its min/max disparity bound every tile's range).
object_depth_result match_object_surface(gray_cplane right, gray_cplane left, box object,
                                         int32_t core_q8, const stereo_params& search,
                                         const camera_rig& rig, const object_depth_params& params,
                                         bool outlined);

}  // namespace dsp
