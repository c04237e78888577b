// Scoring the firmware's per-frame output against the scene's ground truth
// (docs/design-brief.md, "Default rig"): X and Y against the ball's CENTRE, depth
// against the mean depth of the ball's VISIBLE SURFACE in the right image
// (stereo sees the surface, ~2/3 r nearer than the centre). The box centre is
// scored against the centre of the ball's image ellipse (its area centroid).
#pragma once

#include <cstdint>
#include <vector>

#include "tb/platform/scoring/frame_record.h"

namespace platform {

struct frame_errors {
    bool box_scored = false;         // the firmware had a box and the ball was in view
    double box_centre_err_px = 0.0;  // |box centre - ellipse centre|, right image
    double box_centre_dx_px = 0.0, box_centre_dy_px = 0.0;

    bool point_scored = false;              // the firmware gave a 3D point and the ball was in view
    double est_mm[3] = {};                  // X, Y, Z estimated, right camera frame
    double centre_mm[3] = {};               // true ball centre
    double visible_z_mm = 0.0;              // true mean depth of the visible surface
    double err_x_mm = 0.0, err_y_mm = 0.0;  // against the centre
    double err_z_mm = 0.0;                  // against the visible surface
    double depth_err_pct = 0.0;             // 100 * err_z / visible_z
    double disparity_px = 0.0;              // the disparity the point came from
    double disparity_err_px = 0.0;          // against the visible-surface disparity
};

frame_errors score_frame(const frame_record& record);

struct run_summary {
    int frames = 0;
    int first_motion_frame = -1;  // given by the caller (scene truth)
    int detection_frame = -1;     // first pair with a detection
    int tracked_frames = 0;       // pairs with an object box
    int box_scored_frames = 0;
    int point_scored_frames = 0;
    int depth_within_2pct = 0;  // scored points with |depth error| <= 2 %
    double rmse_x_mm = 0.0, rmse_y_mm = 0.0,
           rmse_z_mm = 0.0;  // over scored points
    double max_abs_depth_err_pct = 0.0;
    double mean_box_centre_err_px = 0.0, max_box_centre_err_px = 0.0;
    // Per stage the firmware may declare (its descriptor names them).
    uint64_t stage_cycles_total[STEREOSIM_FW_MAX_STAGES] = {};  // summed over all pairs
    uint64_t stage_cycles_max[STEREOSIM_FW_MAX_STAGES] = {};    // largest single pair
    uint64_t pair_cycles_max = 0;                               // largest pair, all stages
};

run_summary summarize(const std::vector<frame_record>& records, int first_motion_frame);

// Cycles to milliseconds at a CPU clock (the C6416 runs at 600 MHz by
// default, docs/hardware-facts.md section 1).
inline double cycles_to_ms(uint64_t cycles, double cpu_hz = 600e6) {
    return 1e3 * static_cast<double>(cycles) / cpu_hz;
}

}  // namespace platform
