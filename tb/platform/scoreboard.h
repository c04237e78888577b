// The scoreboard of a platform run (docs/platform.md), built after the run
// from what the observers recorded:
//   - per OE start: the sensors' timing truth (were its first frames in
//     step?) against the card's first verdict after it (FRAME_READY or
//     SYNC_ERROR);
//   - per pair the card forwarded (its FRAME_READY): the sensor frames it
//     holds (by timing), their truth (in step?), whether the firmware used
//     it, and only after the verdict covering its last line;
//   - data path integrity: each captured pair's raw frames in DSP memory
//     against the sensors' active pixels (platform_top::captured);
//   - the firmware's 3D output against the scene's ground truth of exactly
//     the images it saw: box centre vs the ball's image centre, X / Y vs the
//     ball centre, depth vs the visible-surface depth (tb/platform/scoring/error_metrics).
#pragma once

#include <cstdint>
#include <vector>

#include "tb/platform/platform.h"
#include "tb/platform/scoring/error_metrics.h"
#include "tb/platform/scoring/frame_record.h"

namespace platform {

enum class card_verdict : uint8_t { none, frame_ready, sync_error };
const char* card_verdict_name(card_verdict v);

struct start_check {
    simtime::ticks oe_rise = 0;
    int64_t frame[2] = {-1, -1};  // first frame of each sensor after this start
    bool truth_in_step = false;
    card_verdict card = card_verdict::none;
    simtime::ticks verdict_tick = -1;
    bool agree() const {
        return card != card_verdict::none && truth_in_step == (card == card_verdict::frame_ready);
    }
};

struct pair_check {
    uint32_t pair = 0;  // 1-based: the n-th FRAME_READY = PAIRS_OK n
    simtime::ticks ready = 0;
    int64_t frame[2] = {-1, -1};  // sensor truth indices (the frames that ended last before it)
    uint64_t scene_frame = 0;     // of the right frame
    bool truth_in_step = false;
    simtime::ticks first_active = 0, last_active = 0;  // earliest first / latest last active pixel
    bool captured = false;                             // EDMA'd into a pair buffer (not drained)
    bool rejected = false;                             // the firmware saw a cause in its verdict
    bool processed = false;                            // the pipeline ran on it
    simtime::ticks result_tick = 0;
    bool used_after_verdict = false;  // result after FRAME_READY, FRAME_READY after its last pixel
    double latency_ms = 0.0;          // first active pixel -> 3D output
    platform::frame_record record;    // the firmware's output with the scene's truth
    platform::frame_errors errors;
};

struct scoreboard_report {
    std::vector<start_check> starts;
    std::vector<pair_check> pairs;
    int oe_restarts = 0;               // OE rises after the first
    int64_t first_in_step_frame = -1;  // left truth index of the first forwarded pair
    simtime::ticks first_in_step_ready = -1;
    int starts_agreeing = 0;
    int forwarded_out_of_step = 0;  // forwarded pairs the truth says were out of step
    int used_before_verdict = 0;    // processed pairs that break the rule
    int used_out_of_step = 0;
    // The firmware's own verdicts: its sync_error reports against the card's
    // SYNC_ERROR pulses, its in_step report against the first forwarded pair.
    int firmware_sync_errors = 0;
    int card_sync_errors = 0;
    int64_t firmware_in_step_pair = -1;

    // Data path integrity over the captured pairs.
    int integrity_checked = 0;
    int integrity_equal = 0;  // both frames' checksums equal the sensors'

    // Tracking and 3D (scene frames).
    int first_motion_frame = -1;
    int detection_frame = -1;
    int frames_after_detection = 0;  // processed pairs after the detection pair
    int box_within_3px = 0;
    int depth_scored_1_3m = 0;  // points with a visible-surface depth in [1, 3] m
    int depth_within_2pct = 0;  // ... of which within 2 %
    double max_box_err_px = 0.0;
    double max_depth_err_pct = 0.0;
    platform::run_summary summary;  // over every processed pair
    double latency_ms_min = 0.0, latency_ms_max = 0.0;
};

scoreboard_report score(const platform_top& top);

}  // namespace platform
