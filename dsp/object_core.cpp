#include "dsp/object_core.h"

namespace dsp {

namespace {

int square_trim(int side) {
    return side < 16 ? 2 : side < round_core_min_side ? side / 5 : side / 7;
}

bool core_is_round(box object, const object_depth_params& surface) {
    return !object_is_tiled(object, surface) && object.width >= round_core_min_side &&
           object.height >= round_core_min_side && object.width < round_core_max_side &&
           object.height < round_core_max_side;
}

box trimmed(box object, int trim_x, int trim_y) {
    return box{object.x + trim_x, object.y + trim_y, object.width - 2 * trim_x,
               object.height - 2 * trim_y};
}

}  // namespace

object_core_pattern object_core(box object, const object_depth_params& surface, row_span* spans) {
    object_core_pattern p;
    if (!core_is_round(object, surface)) {
        p.core = trimmed(object, square_trim(object.width), square_trim(object.height));
        p.pixels = p.core.width * p.core.height;
        return p;
    }
    p.round = true;
    p.core = trimmed(object, object.width / 10, object.height / 10);
    for (int y = 0; y < p.core.height; ++y) {
        const row_span row = ellipse_row(p.core, p.core.y + y);
        spans[y].begin = row.begin - p.core.x;
        spans[y].end = row.end - p.core.x;
        p.pixels += spans[y].end - spans[y].begin;
    }
    return p;
}

}  // namespace dsp
