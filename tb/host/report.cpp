#include "tb/host/report.h"

#include <cerrno>
#include <cstring>

#include "dsp/kernel_costs.h"

namespace host {

namespace {

const char* const table_header =
    "frame state  box(x,y,w,h)        disp_px   "
    "est_X_mm  est_Y_mm  est_Z_mm   true_X_mm "
    "true_Y_mm true_Z_mm vis_Z_mm  depth_err_%";

}  // namespace

void print_frame_table(std::FILE* out, const std::vector<frame_record>& records) {
    std::fprintf(out, "%s\n", table_header);
    for (const frame_record& record : records) {
        const dsp::frame_output& o = record.out;
        const frame_errors e = score_frame(record);
        std::fprintf(out, "%5d %-6s ", record.index, dsp::tracker_state_name(o.state));
        if (o.has_object) {
            char box_text[32];
            std::snprintf(box_text, sizeof box_text, "%d,%d,%d,%d", o.box_right.x, o.box_right.y,
                          o.box_right.width, o.box_right.height);
            std::fprintf(out, "%-19s ", box_text);
        } else {
            std::fprintf(out, "%-19s ", "-");
        }
        if (o.has_point) {
            std::fprintf(out, "%7.2f %9.1f %9.1f %9.1f ", o.disparity_q8 / 256.0,
                         o.point.x / 1000.0, o.point.y / 1000.0, o.point.z / 1000.0);
        } else {
            std::fprintf(out, "%7s %9s %9s %9s ", "-", "-", "-", "-");
        }
        if (record.has_truth) {
            std::fprintf(out, "%10.1f %9.1f %9.1f %8.1f ", record.truth.centre_m.x * 1000.0,
                         record.truth.centre_m.y * 1000.0, record.truth.centre_m.z * 1000.0,
                         record.truth.visible_mean_depth_m * 1000.0);
        } else {
            std::fprintf(out, "%10s %9s %9s %8s ", "-", "-", "-", "-");
        }
        if (e.point_scored) {
            std::fprintf(out, "%+9.2f\n", e.depth_err_pct);
        } else {
            std::fprintf(out, "%9s\n", "-");
        }
    }
}

void print_summary(std::FILE* out, const run_summary& s, double cpu_hz) {
    std::fprintf(out, "frames: %d, first motion at frame %d, detection at frame %d\n", s.frames,
                 s.first_motion_frame, s.detection_frame);
    std::fprintf(out, "tracked frames: %d, scored 3D points: %d, depth within 2%%: %d of %d\n",
                 s.tracked_frames, s.point_scored_frames, s.depth_within_2pct,
                 s.point_scored_frames);
    std::fprintf(out,
                 "RMSE x %.1f mm, y %.1f mm (vs centre), z %.1f mm (vs visible surface); "
                 "max |depth error| %.2f%%\n",
                 s.rmse_x_mm, s.rmse_y_mm, s.rmse_z_mm, s.max_abs_depth_err_pct);
    std::fprintf(out, "box centre error vs ball image centre: mean %.2f px, max %.2f px\n",
                 s.mean_box_centre_err_px, s.max_box_centre_err_px);
    std::fprintf(out,
                 "modelled cycles per stage (cost model %s, CPU %.0f MHz), mean and max per "
                 "pair:\n",
                 dsp::cost::model().id(), cpu_hz / 1e6);
    const double pairs = s.frames > 0 ? s.frames : 1;
    for (int i = 0; i < dsp::stage_count; ++i) {
        const double mean_cycles = s.stage_cycles_total[i] / pairs;
        std::fprintf(out, "  %-11s mean %9.0f cycles %7.3f ms   max %9llu cycles %7.3f ms\n",
                     dsp::stage_name(static_cast<dsp::stage>(i)), mean_cycles,
                     1e3 * mean_cycles / cpu_hz,
                     static_cast<unsigned long long>(s.stage_cycles_max[i]),
                     cycles_to_ms(s.stage_cycles_max[i], cpu_hz));
    }
    std::fprintf(out, "  largest pair, all stages: %llu cycles = %.3f ms\n",
                 static_cast<unsigned long long>(s.pair_cycles_max),
                 cycles_to_ms(s.pair_cycles_max, cpu_hz));
}

bool write_frames_csv(const std::string& path, const std::vector<frame_record>& records,
                      std::string* error) {
    const std::string temp = path + ".tmp";
    std::FILE* f = std::fopen(temp.c_str(), "w");
    if (!f) {
        if (error) *error = "cannot write " + temp + ": " + std::strerror(errno);
        return false;
    }
    std::fprintf(f,
                 "frame,time_s,state,detected,has_object,box_x,box_y,box_w,box_h,left_box_"
                 "x,"
                 "left_box_y,sad_valid,sad_disparity_px,edge_valid,edge_disparity_px,"
                 "disparity_px,has_point,est_x_mm,est_y_mm,est_z_mm,true_x_mm,true_y_mm,"
                 "true_z_mm,visible_z_mm,true_disparity_px,true_image_x,true_image_y,"
                 "box_centre_err_px,depth_err_pct");
    for (int i = 0; i < dsp::stage_count; ++i)
        std::fprintf(f, ",cycles_%s", dsp::stage_name(static_cast<dsp::stage>(i)));
    std::fprintf(f, "\n");
    for (const frame_record& r : records) {
        const dsp::frame_output& o = r.out;
        const frame_errors e = score_frame(r);
        std::fprintf(f, "%d,%.6f,%s,%d,%d,%d,%d,%d,%d,%d,%d,%d,%.4f,%d,%.4f,%.4f,%d,", r.index,
                     r.time_s, dsp::tracker_state_name(o.state), o.detected ? 1 : 0,
                     o.has_object ? 1 : 0, o.box_right.x, o.box_right.y, o.box_right.width,
                     o.box_right.height, o.box_left.x, o.box_left.y, o.sad_match.valid ? 1 : 0,
                     o.sad_match.disparity_q8 / 256.0, o.edge_match.valid ? 1 : 0,
                     o.edge_match.disparity_q8 / 256.0, o.disparity_q8 / 256.0,
                     o.has_point ? 1 : 0);
        if (o.has_point) {
            std::fprintf(f, "%.3f,%.3f,%.3f,", o.point.x / 1000.0, o.point.y / 1000.0,
                         o.point.z / 1000.0);
        } else {
            std::fprintf(f, ",,,");
        }
        if (r.has_truth) {
            std::fprintf(f, "%.3f,%.3f,%.3f,%.3f,%.4f,%.3f,%.3f,", r.truth.centre_m.x * 1000.0,
                         r.truth.centre_m.y * 1000.0, r.truth.centre_m.z * 1000.0,
                         r.truth.visible_mean_depth_m * 1000.0, r.truth.disparity_visible_px,
                         r.truth.right.ellipse_centre.x, r.truth.right.ellipse_centre.y);
        } else {
            std::fprintf(f, ",,,,,,,");
        }
        if (e.box_scored) {
            std::fprintf(f, "%.3f,", e.box_centre_err_px);
        } else {
            std::fprintf(f, ",");
        }
        if (e.point_scored) std::fprintf(f, "%.4f", e.depth_err_pct);
        for (int i = 0; i < dsp::stage_count; ++i)
            std::fprintf(f, ",%llu", static_cast<unsigned long long>(o.stage_cycles[i]));
        std::fprintf(f, "\n");
    }
    const bool write_ok = std::ferror(f) == 0;
    const bool close_ok = std::fclose(f) == 0;
    if (!write_ok || !close_ok) {
        if (error) *error = "error writing " + temp;
        std::remove(temp.c_str());
        return false;
    }
    if (std::rename(temp.c_str(), path.c_str()) != 0) {
        if (error) *error = "cannot rename " + temp + " to " + path + ": " + std::strerror(errno);
        std::remove(temp.c_str());
        return false;
    }
    return true;
}

}  // namespace host
