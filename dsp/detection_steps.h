// An object's motion read from its detections' outline, where the SAD
// pattern reads it still.
//
// DETECT keys an object whose SAD pattern moved at most key_frame::max_step
// px (dsp/controller_detect.cpp, start_track): one pair's thin differences
// may hold a part of a slow object only. The pattern reads the texture
// inside the detection's box, and the static background in its corners:
// a ball whose texture turns against its path, or whose box's corners hold
// a cluttered background, matches where it was. Such a ball at 3-6 px a
// frame was keyed, its key lost or still within min_shift px a few pairs
// later, and keyed again from the next detection, pair after pair (a 110 px
// ball going away at 2-3 px a frame over tsukuba, spinning 1 rev/s about y:
// never started in 24 frames; a 140 px one at 5 px a frame over teddy:
// started at its 20th frame). Its detections' edges step with it: the
// leading edge 3-5 px in every pair, the other edge along. A slow
// object's thin differences give boxes whose edges jump with the parts
// detected (a piece 100 px high, then 40 px), or grow on one side as more
// of it differs, not a box moving the same way pair after pair.
// Costs: dsp::cost::detection_steps_profile, charged by the controller.
#pragma once

#include <cstdint>

#include "dsp/image.h"

namespace dsp {

class detection_steps {
  public:
    // Consecutive pairs whose detections' edge must step alike.
    static constexpr int pairs = 3;

    void clear() { m_count = 0; }
    // This pair's detection (frame_index: the pair's). A pair between
    // without a detection, or a track, restarts the steps.
    void push(box detected, uint32_t frame_index);
    // One edge of the last detections moved at least min_step px the same
    // way in each of the last `pairs` pairs, and the opposite edge at least
    // 1 px a pair that way over them: the box moved, not grew.
    bool edge_keeps_stepping(int min_step) const;

  private:
    box m_boxes[pairs + 1];  // oldest first
    int m_count = 0;
    uint32_t m_last_index = 0;
};

}  // namespace dsp
