#include "dsp/triangulate.h"

#include <cstdint>

namespace dsp {

namespace {

// Signed division rounded to nearest (halves away from zero); den > 0.
int64_t divide_rounded(int64_t num, int64_t den) {
    return num >= 0 ? (num + den / 2) / den : -((-num + den / 2) / den);
}

bool fits_int32(int64_t v) {
    return v >= INT32_MIN && v <= INT32_MAX;
}

}  // namespace

int64_t camera_rig::focal_px_q8() const {
    // um -> nm so both lengths share a unit; Q8 for the fraction of a pixel.
    return divide_rounded(static_cast<int64_t>(focal_length_um) * 1000 * 256, pixel_pitch_nm);
}

bool triangulate(const camera_rig& rig, int32_t x_right_q8, int32_t y_right_q8,
                 int32_t disparity_q8, point3_um* out) {
    // l + r in Q8 pixels: the disparity less the principal points' offset.
    const int64_t den = static_cast<int64_t>(disparity_q8) - rig.principal_offset_q8();
    if (den <= 0) return false;

    const int64_t s = rig.baseline_um;
    const int64_t z = divide_rounded(s * rig.focal_px_q8(), den);
    const int64_t x = divide_rounded(s * (static_cast<int64_t>(x_right_q8) - rig.cx_right_q8), den);
    const int64_t y = divide_rounded(s * (static_cast<int64_t>(y_right_q8) - rig.cy_right_q8), den);
    if (!fits_int32(x) || !fits_int32(y) || !fits_int32(z)) return false;

    out->x = static_cast<int32_t>(x);
    out->y = static_cast<int32_t>(y);
    out->z = static_cast<int32_t>(z);
    return true;
}

int64_t disparity_q8_at_depth(const camera_rig& rig, int64_t depth_um) {
    return divide_rounded(static_cast<int64_t>(rig.baseline_um) * rig.focal_px_q8(), depth_um) +
           rig.principal_offset_q8();
}

}  // namespace dsp
