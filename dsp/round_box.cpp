#include "dsp/round_box.h"

#include "dsp/int_bounds.h"
#include "dsp/size_at_depth.h"

namespace dsp {

namespace {

// sqrt(f^2 + offset^2) in Q8 px: the sphere's extent along an axis whose
// centre is `offset_q8` from the principal point, per unit of its extent on
// the axis (times f).
int64_t extent_scale_q8(int64_t focal_q8, int64_t offset_q8) {
    return isqrt64(focal_q8 * focal_q8 + offset_q8 * offset_q8);
}

// `side` px scaled by to / from, rounded to the nearest pixel.
int scaled(int side, int64_t to, int64_t from) {
    return static_cast<int>((2 * int64_t{side} * to + from) / (2 * from));
}

bool falls_short(int side, int shape) {
    return side + max_int(2, shape / 8) < shape;
}

// The height a sphere's image as wide as `b` has at b's place, and the
// width one as high has.
struct sphere_shape {
    int height = 0, width = 0;
};

sphere_shape shape_at(box b, const camera_rig& rig) {
    const int64_t f = rig.focal_px_q8();
    const int64_t wide = extent_scale_q8(f, int64_t{b.center_x2()} * 128 - rig.cx_right_q8);
    const int64_t high = extent_scale_q8(f, int64_t{b.center_y2()} * 128 - rig.cy_right_q8);
    return {scaled(b.width, high, wide), scaled(b.height, wide, high)};
}

}  // namespace

bool is_round(box b, const camera_rig& rig) {
    const sphere_shape shape = shape_at(b, rig);
    return !b.empty() && !falls_short(b.height, shape.height) && !falls_short(b.width, shape.width);
}

drawn_out_axis drawn_out(box b, const camera_rig& rig) {
    if (b.empty()) return drawn_out_axis::neither;
    const sphere_shape shape = shape_at(b, rig);
    if (falls_short(b.width, shape.width)) return drawn_out_axis::height;
    if (falls_short(b.height, shape.height)) return drawn_out_axis::width;
    return drawn_out_axis::neither;
}

box rounded_box(box b, int image_width, int image_height, const camera_rig& rig) {
    if (b.empty() || b.x <= 0 || b.y <= 0 || b.right() >= image_width || b.bottom() >= image_height)
        return b;
    const sphere_shape shape = shape_at(b, rig);
    box grown = b;
    if (falls_short(b.height, shape.height)) {
        grown = resized_about_centre(b, b.width, shape.height);
    } else if (falls_short(b.width, shape.width)) {
        grown = resized_about_centre(b, shape.width, b.height);
    } else {
        return b;
    }
    if (grown.x < 0 || grown.y < 0 || grown.right() > image_width || grown.bottom() > image_height)
        return b;
    return grown;
}

}  // namespace dsp
