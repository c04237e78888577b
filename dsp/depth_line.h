// A pair's depth no motion of the ball explains: a wrong stereo match.
// Between two pairs (24.5 ms) a thrown ball's depth leaves the line through
// its last two by its acceleration alone: a bounce off the wall behind at
// 4 m/s, 0.75 back, is 0.17 m, 3.8 % of the 4.5 m there; a throw's gravity
// bends its height, not its depth. A pair whose depth departs from that line
// by more than a sixteenth (6.25 %) is reported at the line's value: the
// box cases' wrong matches, traced, read 8-56 % off at one pair, their
// neighbours within 1 %. Unlike the fitted line tried before (a 0.6 % gate
// over 8 pairs, which replaced good depths of balls swung round; since
// removed, docs/firmware.md "The measured depth"), only a depth no ball can
// reach is replaced.
#pragma once

#include <cstdint>

namespace dsp {

class depth_line {
  public:
    // A new track, or a pair without a point: the line starts again.
    void clear();

    // The depth (micrometres, > 0) to report for the triangulated
    // `measured_um`: the line's next value where the last three pairs lie on
    // a line (the middle one within 1/128 of its neighbours' mean) and
    // `measured_um` departs from it by more than a sixteenth; `measured_um`
    // otherwise. Never two pairs in a row: a depth off the line after a
    // replaced one is taken, and the line starts again from it. `*replaced`
    // says which. No divide: the caller has the depth from triangulation and
    // computes a disparity only for a replaced one.
    int32_t reported(int32_t measured_um, bool* replaced);

  private:
    static constexpr int history = 3;
    int64_t depth[history] = {};  // micrometres, the last pairs', oldest first
    int count = 0;
    bool last_replaced = false;
    void push(int64_t d);
};

}  // namespace dsp
