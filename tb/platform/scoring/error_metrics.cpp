#include "tb/platform/scoring/error_metrics.h"

#include <cmath>

namespace platform {

namespace {

// Not scored where the ball reaches past the background plane: the images
// then hold only part of it, or none, and its ellipse is not what they show.
bool ball_in_right_view(const frame_record& record) {
    return record.has_truth && record.truth.right.valid && !record.truth.right.pixel_box.empty() &&
           record.truth.in_front_of_background;
}

}  // namespace

frame_errors score_frame(const frame_record& record) {
    frame_errors e;
    const stereosim_result& out = record.out;
    if (!ball_in_right_view(record)) return e;
    const scene::ball_truth& truth = record.truth;

    if (out.has_object) {
        e.box_scored = true;
        // The centre of the box's pixels: (2x + w - 1) / 2.
        const stereosim_box& b = out.box_right;
        e.box_centre_dx_px = 0.5 * (2 * b.x + b.w - 1) - truth.right.ellipse_centre.x;
        e.box_centre_dy_px = 0.5 * (2 * b.y + b.h - 1) - truth.right.ellipse_centre.y;
        e.box_centre_err_px = std::hypot(e.box_centre_dx_px, e.box_centre_dy_px);
    }
    if (out.has_point && record.truth_has_point) {
        e.point_scored = true;
        e.est_mm[0] = out.x_um / 1000.0;
        e.est_mm[1] = out.y_um / 1000.0;
        e.est_mm[2] = out.z_um / 1000.0;
        e.centre_mm[0] = truth.centre_m.x * 1000.0;
        e.centre_mm[1] = truth.centre_m.y * 1000.0;
        e.centre_mm[2] = truth.centre_m.z * 1000.0;
        e.visible_z_mm = truth.visible_mean_depth_m * 1000.0;
        e.err_x_mm = e.est_mm[0] - e.centre_mm[0];
        e.err_y_mm = e.est_mm[1] - e.centre_mm[1];
        e.err_z_mm = e.est_mm[2] - e.visible_z_mm;
        e.depth_err_pct = 100.0 * e.err_z_mm / e.visible_z_mm;
        e.disparity_px = out.disparity_q8 / 256.0;
        e.disparity_err_px = e.disparity_px - truth.disparity_visible_px;
    }
    return e;
}

run_summary summarize(const std::vector<frame_record>& records, int first_motion_frame) {
    run_summary s;
    s.frames = static_cast<int>(records.size());
    s.first_motion_frame = first_motion_frame;
    double sum_x2 = 0.0, sum_y2 = 0.0, sum_z2 = 0.0, sum_box = 0.0;
    for (const frame_record& record : records) {
        const stereosim_result& out = record.out;
        if (out.detected && s.detection_frame < 0) s.detection_frame = record.index;
        if (out.has_object) ++s.tracked_frames;
        uint64_t pair_cycles = 0;
        for (uint32_t i = 0; i < STEREOSIM_FW_MAX_STAGES; ++i) {
            s.stage_cycles_total[i] += out.stage_cycles[i];
            if (out.stage_cycles[i] > s.stage_cycles_max[i])
                s.stage_cycles_max[i] = out.stage_cycles[i];
            pair_cycles += out.stage_cycles[i];
        }
        if (pair_cycles > s.pair_cycles_max) s.pair_cycles_max = pair_cycles;

        const frame_errors e = score_frame(record);
        if (e.box_scored) {
            ++s.box_scored_frames;
            sum_box += e.box_centre_err_px;
            if (e.box_centre_err_px > s.max_box_centre_err_px)
                s.max_box_centre_err_px = e.box_centre_err_px;
        }
        if (e.point_scored) {
            ++s.point_scored_frames;
            sum_x2 += e.err_x_mm * e.err_x_mm;
            sum_y2 += e.err_y_mm * e.err_y_mm;
            sum_z2 += e.err_z_mm * e.err_z_mm;
            const double abs_pct = std::fabs(e.depth_err_pct);
            if (abs_pct <= 2.0) ++s.depth_within_2pct;
            if (abs_pct > s.max_abs_depth_err_pct) s.max_abs_depth_err_pct = abs_pct;
        }
    }
    if (s.point_scored_frames > 0) {
        const double n = s.point_scored_frames;
        s.rmse_x_mm = std::sqrt(sum_x2 / n);
        s.rmse_y_mm = std::sqrt(sum_y2 / n);
        s.rmse_z_mm = std::sqrt(sum_z2 / n);
    }
    if (s.box_scored_frames > 0) s.mean_box_centre_err_px = sum_box / s.box_scored_frames;
    return s;
}

}  // namespace platform
