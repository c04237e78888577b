// Stereo matching by SAD direct matching (paper step 5a): the pattern taken
// from the RIGHT image is searched in the LEFT image along the same rows
// +-row_slack rows (parallel optical axes), at horizontal shifts
// d in [min_disparity, max_disparity]: left position (x + d, y + dy).
// A scene point at right-image column x appears at left column x + d, d >= 0
// (Middlebury's convention: left (x, y) matches right (x - d, y)).
//
// Computes: SAD(d, dy) = sum_ij |left(x + d + i, y + dy + j) - right(x + i, y + j)|
//   for every (d, dy) whose box lies wholly inside the left image (positions
//   that would leave it are skipped, not padded). The minimum wins; ties go
//   to the smallest |dy|, then the smallest d, then the negative dy.
// Sub-pixel refinement at the best row, from SAD(d-1), SAD(d), SAD(d+1),
//   in integer arithmetic as Q8 (1/256 px), rounded to nearest, in [-0.5, 0.5]:
//   - half_pel (default): the equiangular V below, fitted at a half-pixel
//     step through the least of SAD(d - 1/2), SAD(d), SAD(d + 1/2) and its
//     neighbours (the half-pixel SADs exact: sum |2 right - (left(x + d) +
//     left(x + d +- 1))| against the integer SADs doubled). Where the two
//     views differ by more than a shift (a texture spot at a ball's limb
//     seen by one camera) the SAD curve is lopsided and the V through
//     points a pixel apart misses its minimum by up to 0.4 px; half a
//     pixel apart, by less (docs/firmware.md, "A sub-pixel step at half
//     pixels"). Two more passes over the pattern.
//   - equiangular: two lines of equal and opposite slope through
//     the three points (the steeper side sets the slope):
//       offset = (S(d-1) - S(d+1)) / (2 (max(S(d-1), S(d+1)) - S(d)))
//     Near its minimum SAD grows linearly with the shift (a V, not a
//     parabola), so this fit is unbiased where the parabola is not (Shimizu & Okutomi,
//     "Significance and attributes of subpixel estimation on area-based matching", 2003).
//   - parabola (the textbook fit, kept for comparison):
//       offset = (S(d-1) - S(d+1)) / (2 (S(d-1) - 2 S(d) + S(d+1)))
//     pulls the estimate towards the integer: measured -0.095 px at a true
//     +0.25 px on a smooth texture (tests/dsp/test_stereo_sad.cpp).
//   When d-1 or d+1 was not evaluated (edge of the disparity range or of the
//   image) or the three SADs are flat, the offset is 0. The two neighbours
//   come from the search itself: the equiangular and parabola fits compute
//   no extra SAD.
// Assumes: the pattern box lies inside the right image (else: invalid);
//   pattern width * height * 255 < 2^32 (any pattern up to 16 M pixels).
// Costs: positions * width * height absolute differences (one SUBABS4 per
//   4 pixels on the C64x), plus one division for the sub-pixel step and,
//   half_pel, its two passes; see dsp::cost::sad_search_cycles,
//   dsp::cost::subpixel_cycles and dsp::cost::half_pel_profile.
#pragma once

#include <cstdint>

#include "dsp/image.h"

namespace dsp {

// half_pel: the SADs a half pixel either side of the minimum are read too
// (the left image's two neighbouring columns summed, against the pattern
// doubled: exact), and the V is fitted at that step (docs/firmware.md, "A
// sub-pixel step at half pixels").
enum class subpixel_fit : uint8_t { equiangular, parabola, half_pel };

struct stereo_params {
    int min_disparity = 0;
    int max_disparity = 64;
    int row_slack = 1;  // +-rows searched (pattern height plus two rows)
    bool subpixel = true;
    subpixel_fit fit = subpixel_fit::half_pel;
};

struct stereo_result {
    bool valid = false;
    int disparity = 0;         // integer minimum
    int dy = 0;                // row offset of the minimum
    int32_t disparity_q8 = 0;  // refined disparity, Q8 (256 = 1 px)
    uint32_t sad = 0;          // matching cost of the minimum (SAD, or the edge score)
    int positions = 0;         // positions evaluated (for the cost model)
};

// pattern: the box in `right`. The search is clipped to the left image.
// Invalid when the box is empty, not inside `right`, or no position fits in `left`.
stereo_result stereo_match_sad(gray_cplane right, gray_cplane left, box pattern,
                               const stereo_params& params);

// One row of a masked pattern: its columns [begin, end) relative to the box
// (begin == end: no pixel on that row).
struct row_span {
    int begin = 0;
    int end = 0;
};

// The columns [begin, end) of row y (absolute) whose pixel centres lie in
// the ellipse inscribed in `object`; begin == end: none.
row_span ellipse_row(box object, int y);

// As stereo_match_sad, with the SAD summed over each row's span only
// (`spans` holds pattern.height rows): a pattern that is part object, part
// background matches on the object's pixels alone. Positions and ties as
// above; costs at most the whole box's.
stereo_result stereo_match_sad_masked(gray_cplane right, gray_cplane left, box pattern,
                                      const row_span* spans, const stereo_params& params);

// A stereo minimum on an end of the disparity range actually searched is no
// minimum: the true one may lie beyond. The upper end is max_disparity or,
// nearer the right border, the largest disparity that keeps the box inside
// the left image; there the object may have left the left view. The
// controller's range has disparity_margin_px beyond the depth range at each
// end, so an object inside the depth range never has its minimum there; a
// large object's tiles (object_depth.h) are held to the same rule. Measured on a ball
// leaving the view: depth errors of +10 % to +195 % without this rule (the
// minima at 35 px, the border, and at 13 px, the far end).
bool at_range_end(const stereo_result& match, box pattern, int min_disparity, int max_disparity,
                  int image_width);

// The parabola offset in Q8 from three SADs around a minimum (s0 <= s_m, s0 <= s_p),
// rounded to nearest and clamped to [-128, 128]; 0 when the three are flat.
int32_t subpixel_offset_q8(uint32_t s_minus, uint32_t s0, uint32_t s_plus);

// The equiangular (V) offset in Q8 from the same three SADs, rounded to
// nearest and clamped to [-128, 128]; 0 when the three are flat.
int32_t subpixel_offset_equiangular_q8(uint32_t s_minus, uint32_t s0, uint32_t s_plus);

// The half-pixel offset in Q8 from five doubled SADs a half pixel apart,
// the minimum's in the middle: the V through the least of the middle three
// and its neighbours, clamped to [-128, 128].
int32_t subpixel_offset_half_pel_q8(const uint32_t doubled[5]);

}  // namespace dsp
