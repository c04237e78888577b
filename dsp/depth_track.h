// The object's depth along its track. One pair's stereo match on a small or
// partly framed object can miss by far more than its noise: a 21 px ball
// at 2.3 m read 2.09 % far at one pair with its neighbours within 0.2 %
// (its core's corner on the background, the box 2.4 px off). A moving
// ball's depth is smooth in time: at a constant velocity it is a line (a
// throw's gravity bends its height, not its depth). So the depths of the
// track's last `history` pairs are fitted with a line; a pair whose depth
// departs from the line's next value by more than gate_per_mille of it is
// taken as a mismatch, and the line's value is reported instead.
//
// - Depth, not disparity, is fitted: a ball going away at 1 depth a second
//   has a depth linear in time, while its disparity bends by 0.12 % a pair
//   at the start, which an 8-pair line extrapolates 0.9 % off (15 times
//   the curvature): past the gate on every pair.
// - The gate, 0.6 % of the depth: the per-pair depth noise of the box
//   cases (tests/dsp/test_box_on_motion.cpp) is 0.1 % (median of the
//   pair-to-pair differences / 0.6745 / sqrt 2, 10721 pairs), and an 8-pair
//   line's next value adds 0.78 of it in variance: 0.6 % is 4.7 sigma.
// - Never two pairs in a row: a depth that really turns (a ball bouncing
//   back off a wall) is not a line, and costs one pair; the next is taken as
//   measured and the line refitted through it.
// - Only where the track's depths lie on their line, each within the gate
//   of it: a detection's depth read on a part of the object (7.7 % near)
//   tilted the line through the next 8 pairs, and two good depths were
//   replaced (a passing box case went 0.53 -> 1.75 %).
// - The history restarts with each track and after a pair without a
//   disparity: the line is the one object's, pair after pair.
// Chosen on the depths the box cases reported with the gate off (a script
// over their per-pair figures): 8 pairs and 0.6 % changed no pass to a
// fail there; 4 pairs failed 9 (the line's noise), 0.5 % passed 2 fewer.
// Then run on all 497 box cases: 479 -> 486 pass, none lost.
//
// Costs: the depth's division, the two sums over the history, each pair
// against the line, the line's next value (a division) and its gate; a
// division back to a disparity when that value is reported:
// cost::depth_track_profile.
#pragma once

#include <cstdint>

namespace dsp {

struct depth_track_params {
    int history = 8;         // pairs fitted (at most depth_track::capacity, at least 2)
    int gate_per_mille = 6;  // a depth further than this from the line's is a mismatch
};

struct depth_gate_result {
    int64_t disparity_q8 = 0;  // the disparity to report (Q8, with the principal offset)
    int fitted = 0;            // pairs the line was fitted on (0: too few, not fitted)
    bool replaced = false;     // the line's value stands for the measured one
};

class depth_track {
  public:
    static constexpr int capacity = 16;

    void clear() { m_count = 0, m_replaced_last = false; }
    int count() const { return m_count; }

    // A pair's measured disparity (Q8) gated against the track's line;
    // offset_q8: the rig's principal offset (the disparity at infinity).
    depth_gate_result gate(int64_t disparity_q8, int64_t offset_q8,
                           const depth_track_params& params);

  private:
    void push(uint32_t depth);

    // 2^32 / (d - offset), d in Q8: proportional to depth; oldest first.
    uint32_t m_depth[capacity] = {};
    int m_count = 0;
    bool m_replaced_last = false;
};

}  // namespace dsp
