#include "tb/app/cli/run_report.h"
#include "tb/app/cli/firmware_identity.h"

#include "model/scene/replay.h"

#include <algorithm>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <set>

#include "tb/app/cli/config_keys.h"
#include "tb/app/cli/firmware_keys.h"
#include "tb/platform/firmware_board.h"
#include "tb/platform/island/island.h"
#include "tb/platform/report.h"

namespace cli {

namespace {

using nlohmann::json;

// Reports carry 6 decimals (ms: 1 ns; mm: 1 nm): enough for any figure here,
// and short enough to read.
double round6(double v) {
    return std::round(v * 1e6) / 1e6;
}

double ticks_to_ms(simtime::ticks t) {
    return static_cast<double>(t) / (static_cast<double>(simtime::ticks_per_ns) * 1e6);
}

json box_json(const stereosim_box& b) {
    if (b.w <= 0 || b.h <= 0) return nullptr;
    return json{{"x", b.x}, {"y", b.y}, {"width", b.w}, {"height", b.h}};
}

// Per stage of the firmware's, by its names.
json stage_ms_json(const double* ms, const std::vector<std::string>& stages) {
    json out = json::object();
    for (size_t s = 0; s < stages.size(); ++s) out[stages[s]] = round6(ms[s]);
    return out;
}

std::string hex64(uint64_t v) {
    char text[20];
    std::snprintf(text, sizeof text, "%016" PRIx64, v);
    return text;
}

// The period index holding a tick.
int period_of(simtime::ticks tick, simtime::ticks period) {
    return static_cast<int>(tick / period);
}

// The pair that became ready in the period (and its index in score.pairs), or null.
const platform::pair_check* pair_ready_in(const platform::period_budget& period,
                                          const platform::scoreboard_report& score, size_t* index) {
    for (size_t i = 0; i < score.pairs.size(); ++i) {
        if (score.pairs[i].ready >= period.begin && score.pairs[i].ready < period.end) {
            *index = i;
            return &score.pairs[i];
        }
    }
    return nullptr;
}

// The card's verdicts in the period, the truth of its pair.
json period_sync_json(const platform::period_budget& period, const platform::platform_top& top,
                      const platform::scoreboard_report& score, const platform::pair_check* pair) {
    const platform::island& isl = top.cycle_island();
    auto rises_in = [&](const std::vector<simtime::ticks>& rises) {
        int n = 0;
        for (simtime::ticks t : rises) n += t >= period.begin && t < period.end;
        return n;
    };
    const int ready = rises_in(isl.irq_rises(0));
    const int sync_errors = rises_in(isl.irq_rises(1));
    int oe_restarts = 0;
    for (size_t s = 1; s < score.starts.size(); ++s)
        oe_restarts +=
            score.starts[s].oe_rise >= period.begin && score.starts[s].oe_rise < period.end;
    json sync;
    sync["card"] = sync_errors > 0 ? "sync_error" : ready > 0 ? "frame_ready" : "none";
    sync["oe_restarts"] = oe_restarts;
    sync["pair"] = pair ? json(pair->pair) : json(nullptr);
    sync["in_step"] = pair ? json(pair->truth_in_step) : json(nullptr);
    return sync;
}

json period_budget_json(const platform::period_budget& period,
                        const platform::budget_report& budget,
                        const std::set<int>& over_budget_periods) {
    json b;
    b["judged"] = period.judged;
    b["over_budget"] = over_budget_periods.count(period.index) > 0;
    b["cpu_busy_ms"] = round6(period.cpu_busy_ms);
    b["emif_busy_ms"] = round6(period.emif_busy_ms);
    b["slack_ms"] = round6(budget.period_ms - std::max(period.cpu_busy_ms, period.emif_busy_ms));
    b["fifo_peak_words"] = {{"left", period.fifo_peak_words[0]},
                            {"right", period.fifo_peak_words[1]}};
    b["overflow"] = period.overflow;
    b["drops"] = period.drops;
    return b;
}

json pair_summary_json(const platform::pair_check& pair, const platform::pair_budget& pb) {
    return {{"number", pair.pair},
            {"scene_frame", pair.scene_frame},
            {"captured", pair.captured},
            {"processed", pair.processed},
            {"capture_ms", round6(pb.capture_ms)},
            {"processing_ms", pair.processed ? json(round6(pb.processing_ms)) : json(nullptr)},
            {"latency_ms", pair.processed ? json(round6(pair.latency_ms)) : json(nullptr)}};
}

// The object's truth: its point (null where a replay's truth CSV gives only
// the pixel) and its pixel in the right image (the ellipse centre of a
// rendered ball).
json truth_json(const platform::frame_record& record) {
    const scene::ball_truth& t = record.truth;
    const auto mm = [&](double m) {
        return record.truth_has_point ? json(round6(m * 1000.0)) : json(nullptr);
    };
    return {{"x", mm(t.centre_m.x)},
            {"y", mm(t.centre_m.y)},
            {"z", mm(t.centre_m.z)},
            {"z_visible", mm(t.visible_mean_depth_m)},
            {"u_right_px", round6(t.right.ellipse_centre.x)},
            {"v_right_px", round6(t.right.ellipse_centre.y)}};
}

json errors_json(const platform::frame_errors& e) {
    return {{"x_mm", e.point_scored ? json(round6(e.err_x_mm)) : json(nullptr)},
            {"y_mm", e.point_scored ? json(round6(e.err_y_mm)) : json(nullptr)},
            {"z_mm", e.point_scored ? json(round6(e.err_z_mm)) : json(nullptr)},
            {"depth_pct", e.point_scored ? json(round6(e.depth_err_pct)) : json(nullptr)},
            {"disparity_px", e.point_scored ? json(round6(e.disparity_err_px)) : json(nullptr)},
            {"box_centre_px", e.box_scored ? json(round6(e.box_centre_err_px)) : json(nullptr)}};
}

// The pair forwarded in the period and what the firmware made of it: null
// fields without a pair, or for what the firmware did not produce.
void add_pair_fields(json& row, const platform::platform_top& top,
                     const platform::budget_report& budget, const platform::pair_check* pair,
                     const platform::pair_budget* pb) {
    row["pair"] = pair ? pair_summary_json(*pair, *pb) : json(nullptr);
    for (const char* key : {"stage_ms", "tracker_state", "box_right", "box_left", "disparity_px",
                            "estimate", "truth", "errors"})
        row[key] = nullptr;
    if (!pair || !pair->processed) return;
    const stereosim_result& out = pair->record.out;
    row["stage_ms"] = stage_ms_json(pb->stage_ms, budget.stage_names);
    row["tracker_state"] = top.events().state_name(static_cast<int>(out.state));
    if (out.has_object) {
        row["box_right"] = box_json(out.box_right);
        row["box_left"] = box_json(out.box_left);
    }
    if (out.has_point) {
        row["disparity_px"] = round6(out.disparity_q8 / 256.0);
        row["estimate"] = {{"x", round6(out.x_um / 1000.0)},
                           {"y", round6(out.y_um / 1000.0)},
                           {"z", round6(out.z_um / 1000.0)}};
    }
    if (pair->record.has_truth) row["truth"] = truth_json(pair->record);
    row["errors"] = errors_json(pair->errors);
}

json frame_row(const platform::period_budget& period, const platform::platform_top& top,
               const platform::scoreboard_report& score, const platform::budget_report& budget,
               const std::set<int>& over_budget_periods) {
    json row;
    row["frame"] = period.index;
    row["start_ms"] = round6(ticks_to_ms(period.begin));
    size_t pair_index = 0;
    const platform::pair_check* pair = pair_ready_in(period, score, &pair_index);
    row["sync"] = period_sync_json(period, top, score, pair);
    row["budget"] = period_budget_json(period, budget, over_budget_periods);
    add_pair_fields(row, top, budget, pair, pair ? &budget.pairs[pair_index] : nullptr);
    return row;
}

// Periods with an overrun (*over: a period's own, or the period its pair
// became ready in) and report["overruns"].
json overruns_json(const platform::scoreboard_report& score, const platform::budget_report& budget,
                   simtime::ticks period_ticks, std::set<int>* over) {
    json overruns = json::array();
    for (const platform::overrun& o : budget.overruns) {
        int period = o.period;
        if (period < 0) {
            for (const platform::pair_check& p : score.pairs)
                if (p.pair == o.pair) period = period_of(p.ready, period_ticks);
        }
        if (period >= 0) over->insert(period);
        overruns.push_back({{"resource", platform::resource_name(o.what)},
                            {"stage", o.stage_name},
                            {"period", o.period >= 0 ? json(o.period) : json(nullptr)},
                            {"pair", o.pair > 0 ? json(o.pair) : json(nullptr)},
                            {"value_ms", round6(o.value_ms)},
                            {"limit_ms", round6(o.limit_ms)},
                            {"text", o.describe()}});
    }
    return overruns;
}

json sync_summary_json(const platform::scoreboard_report& score) {
    return {{"mismatches_detected", score.card_sync_errors},
            {"resyncs", score.oe_restarts},
            {"unsynced_pairs_used", score.used_out_of_step},
            {"oe_starts", score.starts.size()},
            {"starts_agreeing_with_truth", score.starts_agreeing},
            {"firmware_sync_errors", score.firmware_sync_errors},
            {"pairs_forwarded", score.pairs.size()},
            {"forwarded_out_of_step", score.forwarded_out_of_step},
            {"used_before_verdict", score.used_before_verdict},
            {"first_in_step_ms", score.first_in_step_ready >= 0
                                     ? json(round6(ticks_to_ms(score.first_in_step_ready)))
                                     : json(nullptr)}};
}

json timing_summary_json(const platform::budget_report& budget, size_t frames_over_budget) {
    json stage_ms = json::object();
    for (size_t s = 0; s < budget.stage_names.size(); ++s)
        stage_ms[budget.stage_names[s]] = {{"mean", round6(budget.stage_ms_mean[s])},
                                           {"max", round6(budget.stage_ms_max[s])}};
    return {{"budget_ms", round6(budget.period_ms)},
            {"frames_over_budget", frames_over_budget},
            {"judged_periods", budget.judged_periods},
            {"stage_ms", stage_ms},
            {"capture_ms",
             {{"mean", round6(budget.mean_capture_ms)}, {"max", round6(budget.max_capture_ms)}}},
            {"processing_ms_max", round6(budget.max_processing_ms)},
            {"latency_ms_max", round6(budget.latency_ms_max)},
            {"cpu_busy_ms_max", round6(budget.max_cpu_busy_ms)},
            {"emif_busy_ms_max", round6(budget.max_emif_busy_ms)},
            {"fifo_peak_words",
             {{"left", budget.fifo_peak_words[0]}, {"right", budget.fifo_peak_words[1]}}},
            {"fifo_capacity_words", platform::card_fifo_words},
            {"drops", budget.drops},
            {"overflows", budget.overflows},
            {"cpu_mhz", round6(budget.cpu_hz / 1e6)}};
}

json accuracy_summary_json(const platform::scoreboard_report& score) {
    const platform::run_summary& s = score.summary;
    const bool scored = s.point_scored_frames > 0;
    return {
        {"frames_tracked", s.tracked_frames},
        {"first_motion_frame",
         score.first_motion_frame >= 0 ? json(score.first_motion_frame) : json(nullptr)},
        {"detection_frame",
         score.detection_frame >= 0 ? json(score.detection_frame) : json(nullptr)},
        {"detect_latency_frames", score.first_motion_frame >= 0 && score.detection_frame >= 0
                                      ? json(score.detection_frame - score.first_motion_frame)
                                      : json(nullptr)},
        {"points_scored", s.point_scored_frames},
        {"rmse_mm",
         {{"x", scored ? json(round6(s.rmse_x_mm)) : json(nullptr)},
          {"y", scored ? json(round6(s.rmse_y_mm)) : json(nullptr)},
          {"z", scored ? json(round6(s.rmse_z_mm)) : json(nullptr)}}},
        // A maximum over no frame is null, not 0.
        {"box_err_px_max",
         s.box_scored_frames > 0 ? json(round6(score.max_box_err_px)) : json(nullptr)},
        {"depth_scored_1_3m", score.depth_scored_1_3m},
        {"depth_err_pct_max",
         score.depth_scored_1_3m > 0 ? json(round6(score.max_depth_err_pct)) : json(nullptr)},
        {"depth_err_pct_max_all", scored ? json(round6(s.max_abs_depth_err_pct)) : json(nullptr)}};
}

json summary_json(const platform::platform_top& top, const platform::scoreboard_report& score,
                  const platform::budget_report& budget, size_t frames_over_budget) {
    json summary;
    summary["sync"] = sync_summary_json(score);
    summary["timing"] = timing_summary_json(budget, frames_over_budget);
    summary["accuracy"] = accuracy_summary_json(score);
    summary["data_path"] = {{"pairs_checked", score.integrity_checked},
                            {"pairs_intact", score.integrity_equal}};
    const platform::run_figures f = platform::figures_of(top);
    summary["sim"] = {{"simulated_s", round6(f.sim_s)},
                      {"wall_s", round6(f.wall_s)},
                      {"ratio", round6(f.sim_per_wall())}};
    summary["hashes"] = {
        {"pins",
         top.config().hash_pins ? json(hex64(top.cycle_island().pin_hash())) : json(nullptr)},
        {"timeline", hex64(top.events().hash())}};
    return summary;
}

}  // namespace

std::vector<std::string> stage_names(const json& report) {
    std::vector<std::string> names;
    for (const json& s : report.at("tool").at("firmware").at("stages"))
        names.push_back(s.get<std::string>());
    return names;
}

// Why a run judged only part of the budget, and how long a run would judge
// all of it: the detector needs three frames with motion, tracking starts on
// the pair after the detection, and a first start out of step (about 44 % of
// seeds) costs a period: the first motion frame + 6.
std::string not_judged_text(const platform::budget_report& budget,
                            const platform::scoreboard_report& score, int frames) {
    std::string stages;
    for (int s : budget.stages_not_run)
        stages += (stages.empty() ? "" : ", ") + budget.stage_names[static_cast<size_t>(s)];
    std::string text =
        "not judged: " + stages + " never ran in " + std::to_string(frames) + " periods; ";
    if (score.first_motion_frame < 0)
        return text + "the scene has no motion in them, nothing for the tracker to follow";
    const int need = std::max(frames + 1, score.first_motion_frame + 6);
    return text + "ask for --frames " + std::to_string(need) + " or more";
}

// A replay: its manifest by an absolute path, so that the report repeats the
// run from any folder; the manifest's calibration is the rig, so the rig
// keys, unused, are not shown as if they were (`replay.calibration`).
void add_replay(json& report, const run_setup& setup, const platform::platform_top& top) {
    std::error_code ec;
    const std::string manifest =
        std::filesystem::absolute(setup.scenario.replay, ec).lexically_normal().string();
    report["config"]["scenario"]["replay"] = manifest;
    report["config"].erase("rig");
    const scene::replay* r = top.replay();
    if (!r) return;
    const scene::replay_calibration& c = r->calibration();
    report["replay"] = {{"manifest", manifest},
                        {"size", {r->width(), r->height()}},
                        {"frames", r->frame_count()},
                        {"truth", r->has_truth()},
                        {"calibration",
                         {{"focal_px", c.focal_px},
                          {"baseline_mm", round6(c.baseline_m * 1000.0)},
                          {"principal_left", {c.cx_left, c.cy_left}},
                          {"principal_right", {c.cx_right, c.cy_right}}}}};
}

json build_report(const run_setup& setup, const platform::platform_top& top,
                  const platform::scoreboard_report& score, const platform::budget_report& budget) {
    std::set<int> over;
    const json overruns = overruns_json(score, budget, top.config().period, &over);

    json report;
    report["schema_version"] = report_schema_version;
    report["tool"] = {{"name", "stereosim"}, {"cost_model", c64x::cost_model().id()}};
    // The firmware under test; a plugin's file and digest, null when built in.
    report["tool"]["firmware"] =
        firmware_identity(top.firmware_descriptor(), top.firmware_plugin());
    report["config"] = config_json(setup);
    // Every key value the firmware ran with, its defaults included, so that
    // the report replays its run whatever the defaults become.
    const json values =
        firmware_values_json(top.firmware_descriptor(),
                             platform::plugin_values(top.firmware_descriptor(), top.config()));
    for (const auto& [name, value] : values.items()) report["config"]["firmware"][name] = value;
    if (!setup.scenario.replay.empty()) add_replay(report, setup, top);
    report["verdict"] = budget.fits ? "within_budget" : "over_budget";
    // A run too short for a stage to run judged only part of the budget.
    report["judged"] = budget.stages_not_run.empty();
    report["not_judged"] = budget.stages_not_run.empty()
                               ? json(nullptr)
                               : json(not_judged_text(budget, score, top.config().frames));
    report["overruns"] = overruns;
    report["summary"] = summary_json(top, score, budget, over.size());

    json frames = json::array();
    for (const platform::period_budget& p : budget.periods)
        frames.push_back(frame_row(p, top, score, budget, over));
    report["frames"] = frames;
    return report;
}

std::vector<std::pair<std::string, std::string>> frame_csv_columns(const json& report) {
    std::vector<std::pair<std::string, std::string>> c = {
        {"frame", "/frame"},
        {"start_ms", "/start_ms"},
        {"card_verdict", "/sync/card"},
        {"oe_restarts", "/sync/oe_restarts"},
        {"pair", "/sync/pair"},
        {"in_step", "/sync/in_step"},
        {"judged", "/budget/judged"},
        {"over_budget", "/budget/over_budget"},
        {"cpu_busy_ms", "/budget/cpu_busy_ms"},
        {"emif_busy_ms", "/budget/emif_busy_ms"},
        {"slack_ms", "/budget/slack_ms"},
        {"fifo_peak_left", "/budget/fifo_peak_words/left"},
        {"fifo_peak_right", "/budget/fifo_peak_words/right"},
        {"overflow", "/budget/overflow"},
        {"drops", "/budget/drops"},
        {"scene_frame", "/pair/scene_frame"},
        {"captured", "/pair/captured"},
        {"processed", "/pair/processed"},
        {"capture_ms", "/pair/capture_ms"},
        {"processing_ms", "/pair/processing_ms"},
        {"latency_ms", "/pair/latency_ms"}};
    for (const std::string& s : stage_names(report))
        c.push_back({"stage_" + s + "_ms", "/stage_ms/" + s});
    const std::vector<std::pair<std::string, std::string>> rest = {
        {"tracker_state", "/tracker_state"},
        {"box_right_x", "/box_right/x"},
        {"box_right_y", "/box_right/y"},
        {"box_right_width", "/box_right/width"},
        {"box_right_height", "/box_right/height"},
        {"box_left_x", "/box_left/x"},
        {"box_left_y", "/box_left/y"},
        {"box_left_width", "/box_left/width"},
        {"box_left_height", "/box_left/height"},
        {"disparity_px", "/disparity_px"},
        {"est_x_mm", "/estimate/x"},
        {"est_y_mm", "/estimate/y"},
        {"est_z_mm", "/estimate/z"},
        {"true_x_mm", "/truth/x"},
        {"true_y_mm", "/truth/y"},
        {"true_z_mm", "/truth/z"},
        {"true_z_visible_mm", "/truth/z_visible"},
        {"err_x_mm", "/errors/x_mm"},
        {"err_y_mm", "/errors/y_mm"},
        {"err_z_mm", "/errors/z_mm"},
        {"err_depth_pct", "/errors/depth_pct"},
        {"err_disparity_px", "/errors/disparity_px"},
        {"err_box_centre_px", "/errors/box_centre_px"}};
    c.insert(c.end(), rest.begin(), rest.end());
    return c;
}

std::string frames_csv(const json& report) {
    std::string out;
    const auto columns = frame_csv_columns(report);
    for (size_t i = 0; i < columns.size(); ++i) out += (i ? "," : "") + columns[i].first;
    out += "\n";
    for (const json& row : report.at("frames")) {
        for (size_t i = 0; i < columns.size(); ++i) {
            if (i) out += ",";
            // A null parent (no pair) makes every field under it empty. No
            // exception: the run's SystemC threads leave AddressSanitizer
            // unsure of the stack, and a throw now poisons it falsely.
            const json::json_pointer pointer(columns[i].second);
            if (!row.contains(pointer)) continue;
            const json* value = &row.at(pointer);
            if (value->is_null()) continue;
            if (value->is_boolean())
                out += value->get<bool>() ? "1" : "0";
            else if (value->is_string())
                out += value->get<std::string>();
            else
                out += value->dump();
        }
        out += "\n";
    }
    return out;
}

}  // namespace cli
