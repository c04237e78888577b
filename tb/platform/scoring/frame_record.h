// One processed stereo pair beside the scene's truth, and the first frame
// that moves, what the platform and the tests' host runs both score with.
// The pair's output is the firmware ABI's result: what any firmware reports.
#pragma once

#include "model/scene/sequence.h"
#include "stereosim/firmware.h"

namespace platform {

// One processed pair: the firmware's output and the truth of the scene's
// first ball (has_truth is false for a scene with no ball), or of a
// replay's object (truth_has_point false when its truth CSV gives only the
// pixel: then only the box centre is scored).
struct frame_record {
    int index = 0;
    double time_s = 0.0;
    stereosim_result out{};
    bool has_truth = false;
    bool truth_has_point = true;
    scene::ball_truth truth;
};

// The first frame whose ball centre differs from the previous frame's, or
// -1 if the ball never moves within [0, frames).
int first_motion_frame(const scene::sequence& sequence, int frames);

}  // namespace platform
