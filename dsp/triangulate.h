// Depth and 3D position from disparity (paper step 6), fixed point.
//
//   D = s f / (l + r),  X = D x / f,  Y = D y / f,  Z = D
//
// l and r are the distances of the image points from the left and right
// optical axes on the sensor plane. With columns measured in pixels,
// l + r = pitch * ((x_left - cx_left) - (x_right - cx_right))
//       = pitch * (d - (cx_left - cx_right)), d = x_left - x_right,
// and f / pitch is the focal length in pixels, so D = s * f_px / (d - dcx).
// x, y are the right image point's offsets from the right principal point.
// The result is in the RIGHT camera's frame: X right, Y down, Z forward, in
// micrometres. The left camera sits at X = -s (parallel axes, rectified rows).
//
// Computes (all Q8 pixel quantities, so the Q8 scales cancel):
//   den = disparity_q8 - (cx_left_q8 - cx_right_q8)
//   Z = s * f_px_q8 / den
//   X = s * (x_right_q8 - cx_right_q8) / den     (= Z x / f, one rounding only)
//   Y = s * (y_right_q8 - cy_right_q8) / den
// each a 64-bit product and one 64-bit division rounded to nearest.
// Accuracy: relative depth error ~ 1 / (512 * disparity_px) from the Q8
//   disparity, plus 1 um rounding; f_px_q8 is rounded to 1/256 px.
// Assumes: baseline_um > 0, pixel_pitch_nm > 0.
// Costs: three 64-bit divisions (software on the C64x), once per frame; see
//   dsp::cost::triangulate_cycles.
#pragma once

#include <cstdint>

namespace dsp {

struct camera_rig {
    int32_t baseline_um = 120000;    // s: 120 mm (docs/design-brief.md default rig)
    int32_t focal_length_um = 6000;  // 6 mm lenses
    int32_t pixel_pitch_nm = 7600;   // 7.6 um, the OV7620's (docs/hardware-facts.md section 6)
    int32_t cx_left_q8 = 320 * 256 - 128;  // principal points, Q8 px: image centre of
    int32_t cy_left_q8 = 240 * 256 - 128;  // a 640x480 image is (319.5, 239.5)
    int32_t cx_right_q8 = 320 * 256 - 128;
    int32_t cy_right_q8 = 240 * 256 - 128;

    // Focal length in pixels, Q8, rounded: f / pitch (789.47 px = 202105 for the default rig).
    int64_t focal_px_q8() const;
    // The principal points' offset, Q8 px: the disparity of a point at infinity.
    int64_t principal_offset_q8() const { return int64_t{cx_left_q8} - cx_right_q8; }
};

struct point3_um {
    int32_t x = 0, y = 0, z = 0;
};

// false (and *out untouched) when the disparity does not give a point in
// front of the rig (disparity_q8 <= cx_left_q8 - cx_right_q8), or when a
// coordinate would not fit in 32-bit micrometres (beyond ~2.1 km).
bool triangulate(const camera_rig& rig, int32_t x_right_q8, int32_t y_right_q8,
                 int32_t disparity_q8, point3_um* out);

// The disparity (Q8 px, rounded) of a point at depth_um > 0: s f_px / D plus
// the principal points' offset, the inverse of triangulate's depth. One
// 64-bit division (and f_px's).
int64_t disparity_q8_at_depth(const camera_rig& rig, int64_t depth_um);

}  // namespace dsp
