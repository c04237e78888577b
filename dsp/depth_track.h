// The object's depth along its track. One pair's stereo match on a small or
// partly framed object can miss by far more than its noise: a 21 px ball
// at 2.3 m read 2.09 % far at one pair with its neighbours within 0.2 %
// (its core's corner on the background, the box 2.4 px off). A moving
// ball's depth is smooth in time. So the depths of the track's last
// `history` pairs are fitted; a pair whose depth departs from the fit's
// next value by more than gate_per_mille of it is taken as a mismatch, and
// the fit's value is reported instead.
//
// - Depth, not disparity, is fitted: a ball going away at 1 depth a second
//   has a depth linear in time, while its disparity bends by 0.12 % a pair
//   at the start, which an 8-pair line extrapolates 0.9 % off (15 times
//   the curvature): past the gate on every pair.
// - A line, or a quadratic where its curvature stands out of the noise
//   (the F test of its term over the quadratic's residuals, 1 % level):
//   a ball swung round a circle has a depth that turns smoothly, 0.1 % a
//   pair squared at 2 m, which an 8-pair line extrapolates 0.76 % off. The
//   quadratic's next value has 1.9 times the noise's variance where the
//   line's has 0.6, and it follows a mismatch building over two pairs into
//   the second: noise is no curvature.
// - The gate, 0.6 % of the depth: the per-pair depth noise of the box
//   cases (tests/dsp/test_box_on_motion.cpp) is 0.1 % (median of the
//   pair-to-pair differences / 0.6745 / sqrt 2, 10721 pairs); with the
//   line's next value's own, 0.6 % is 4.7 sigma, the quadratic's 3.5.
// - A bounce is no mismatch: a ball thrown at the wall behind it that
//   turns within a pair is found between the fit's next value and one step
//   behind its last (restitution at most 1), which a line would miss by up
//   to two steps (3.7 % at 3 m/s, 2.3 m away). Such a depth is reported as
//   measured and the fit starts again from it, only where the ball goes
//   away by more than half the gate a pair (a slower one's step is noise).
//   A mismatch that falls there, behind a fast ball going away, is taken
//   for a bounce. Not for a ball coming nearer: what turns it (a hand, a
//   bat) is not in the scene, and the box cases' throws towards the rig
//   had mismatches behind them (0.45 -> 0.93 % when it was).
// - Never two pairs in a row: a depth that turns another way (a ball
//   coming nearer, turned) costs one pair; the next is taken as measured
//   and the fit made through it. Two in a row (measured with a bounce
//   taken both ways) passed one more open case and failed three passing
//   ones: a throw, a circle and a ball swung round.
// - Only where the track's depths lie on their fit, each within the gate
//   of it: a detection's depth read on a part of the object (7.7 % near)
//   tilted the line through the next 8 pairs, and two good depths were
//   replaced (a passing box case went 0.53 -> 1.75 %).
// - The history restarts with each track and after a pair without a
//   disparity: the fit is the one object's, pair after pair.
// Chosen on the depths the box cases reported with the gate off (a script
// over their per-pair figures): 8 pairs and 0.6 % changed no pass to a
// fail there; 4 pairs failed 9 (the line's noise), 0.5 % passed 2 fewer.
// The bounce and the curvature were added for the box cases whose depth
// turns (DepthTurns), which the line failed.
//
// Costs: the depth's division, the three sums over the history, the two
// residual sums of the F test, each pair against the fit, the fit's next
// value (a division) and its gate; a division back to a disparity when that
// value is reported: cost::depth_track_profile.
#pragma once

#include <cstdint>

namespace dsp {

struct depth_track_params {
    int history = 8;         // pairs fitted (at most depth_track::capacity, at least 4)
    int gate_per_mille = 6;  // a depth further than this from the fit's is a mismatch
    int curvature_f = 16;    // F(1, history - 3)'s 1 % point: 16.26 for 8 pairs
};

struct depth_gate_result {
    int64_t disparity_q8 = 0;  // the disparity to report (Q8, with the principal offset)
    int fitted = 0;            // pairs the fit was made on (0: too few, not fitted)
    bool replaced = false;     // the fit's value stands for the measured one
    bool turned = false;       // off the fit as a bounce puts it: measured, the fit restarts
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
