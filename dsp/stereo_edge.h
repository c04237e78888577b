// Stereo matching by edges (paper step 5b): Sobel edges on both images are
// binarised; a horizontal epipolar line through the pattern cuts the edges
// into segments (runs between edge pixels); the sequence of segment lengths
// seen in the right image across the pattern is matched against the left
// image's segments; the horizontal shift of the matched segments is the
// disparity.
//
// Computes, on each of `lines` rows through the pattern (the centre row
// center_y2() / 2 and rows +-line_spacing, +-2 line_spacing, ... around it;
// rows outside the pattern are skipped):
//   1. Edge pixels: magnitude > edge_threshold. A run of adjacent edge pixels
//      is ONE segment boundary, placed at its magnitude-weighted centroid in
//      Q8 (a step edge lights two Sobel columns; their centroid is the step).
//      Runs are followed to their ends, so a boundary does not depend on the
//      window it is looked for in.
//      Right boundaries: centroids inside the pattern's columns. Left
//      boundaries: centroids inside the columns the shifted pattern can cover.
//   2. For each shift d: the right pattern's segments (consecutive right
//      boundaries b_i, lengths b_{i+1} - b_i) are laid onto the left line at
//      b_i + d. Matching the length sequence means every boundary lands on a
//      left boundary, so the score is the sum of |boundary position
//      differences|, each capped at edge_cap_px (a missing or extra edge costs
//      the cap instead of breaking the whole sequence), taken both ways:
//      right boundaries to their nearest left boundary, and left boundaries
//      inside the shifted pattern to their nearest right boundary (so a shift
//      onto a busier or emptier stretch of the left line also costs).
//   3. The scores of all lines are summed; the smallest total wins (ties: the
//      smallest d). Sub-pixel: the mean signed difference of the right
//      boundaries that land within 1 px of a left boundary at the best d,
//      clamped to +-0.5 px, refines disparity_q8.
// Result: sad = the best total score (Q8 px); positions = shifts x lines
//   scored; dy = 0 (the method works on the same rows in both images).
//   Invalid when the lines through the pattern hold fewer than two right
//   boundaries (no complete segment), or no left boundary matches at all.
// Assumes: both planes have the same height; the pattern lies inside the
//   right plane; magnitudes valid on the rows used. Limits (fixed stack
//   arrays, no allocation): at most edge_max_boundaries boundaries per line
//   (runs are >= 2 px apart, so a 512-px strip always fits; further ones are
//   ignored) and edge_max_shifts shifts (the range is cut at the top).
// Costs: per line, one pass over about w + (max_d - min_d) + 2 edge_cap_px
//   magnitudes (compare + accumulate; runs crossing the ends are followed),
//   then (max_d - min_d + 1) merges of the two boundary lists; see
//   dsp::cost::edge_match_cycles.
#pragma once

#include <cstdint>

#include "dsp/image.h"
#include "dsp/stereo_sad.h"

namespace dsp {

constexpr int edge_max_boundaries = 256;  // per line and image
constexpr int edge_max_shifts = 512;      // disparities scored

struct edge_params {
    uint8_t edge_threshold = 60;  // Sobel magnitude above which a pixel is an edge
    int min_disparity = 0;
    int max_disparity = 64;
    // Epipolar lines used: the pattern's centre row and rows around it. Rows
    // next to each other see nearly the same edges, so by default the lines
    // are spread over the pattern. Measured on Middlebury 15x15 patches
    // (tests/dsp/test_middlebury.cpp), share within 1 px on tsukuba / cones:
    // 3 adjacent rows 48 / 50%, 3 spread 53 / 55%, 7 spread 70 / 72%, all 15 rows 76 / 79%.
    int lines = 7;
    int line_spacing = 0;  // rows between lines; 0: max(1, pattern height / lines)
    int edge_cap_px = 3;   // a boundary farther than this from any partner costs this much
};

// right_edges / left_edges: Sobel magnitudes (dsp/sobel.h) of the two images,
// valid at least on the rows the pattern covers.
stereo_result stereo_match_edge(gray_cplane right_edges, gray_cplane left_edges, box pattern,
                                const edge_params& params);

}  // namespace dsp
