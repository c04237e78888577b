#include "dsp/part_growth.h"

#include "dsp/controller_impl.h"
#include "dsp/key_frame.h"
#include "dsp/round_box.h"

namespace dsp {

using namespace controller_parts;

part_growth grow_part(const difference_extents& extents, box last, bool may_be_part, bool part_x,
                      bool part_y, bool previous_at_border, const camera_rig& rig) {
    const box& before = extents.before;
    const box& after = extents.after;
    const int tolerance_x = max_int(2, last.width / 8), tolerance_y = max_int(2, last.height / 8);
    const span common_x = x_span(extents.previous), common_y = y_span(extents.previous);
    const bool holds_x = covers(common_x, x_span(last)), holds_y = covers(common_y, y_span(last));
    const int slow = key_frame::min_shift;
    const bool slow_x = may_be_part && near_size(before.x, after.x, slow) &&
                        near_size(before.right(), after.right(), slow);
    const bool slow_y = may_be_part && near_size(before.y, after.y, slow) &&
                        near_size(before.bottom(), after.bottom(), slow);
    const bool larger =
        common_x.size > last.width + tolerance_x || common_y.size > last.height + tolerance_y;
    part_growth g;
    g.round_read =
        may_be_part && !part_x && !part_y && holds_x && holds_y && larger && !previous_at_border;
    const bool round = g.round_read && is_round(extents.previous, rig);
    g.x = round || (slow_x && !part_x && holds_x && common_x.size > last.width + tolerance_x);
    g.y = round || (slow_y && !part_y && holds_y && common_y.size > last.height + tolerance_y);
    return g;
}

}  // namespace dsp
