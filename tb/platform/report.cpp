#include "tb/platform/report.h"

#include <cctype>
#include <string>

#include "tb/platform/firmware_board.h"

namespace platform {

namespace {

double ticks_to_ms(simtime::ticks t) {
    return static_cast<double>(t) / (static_cast<double>(simtime::ticks_per_ns) * 1e6);
}

// The paper's DSK figures (docs/design-brief.md): SAD tracking ~1.756 ms, SAD stereo
// ~4.71 ms, edge stereo + 3D < 5 ms.
constexpr double paper_track_ms = 1.756;
constexpr double paper_stereo_sad_ms = 4.71;
constexpr double paper_edge_xyz_ms = 5.0;

// The card's CECTL as the firmware programmed it on the bus (docs/budget.md;
// the DSK's reset value if it never did): CE3, the pixel port.
uint32_t card_cectl(const platform_top& top) {
    return top.engine().cectl(3);
}

}  // namespace

run_figures figures_of(const platform_top& top) {
    run_figures f;
    f.sim_s = ticks_to_ms(top.end_tick()) / 1e3;
    f.wall_s = top.wall_s();
    f.island_wall_s = top.cycle_island().stats().wall_s;
    f.firmware_wall_s = top.firmware_started() ? top.probe().firmware_wall_s() : 0.0;
    return f;
}

capture_figures capture_closed_form(const platform_top& top) {
    const int cols = top.config().profile.active_cols, rows = top.config().profile.active_rows;
    const frame_placement frames = top.firmware_started()
                                       ? reported_placement(top.probe().fw_events(), cols, rows)
                                       : reference_placement(cols, rows);
    return capture(cols, rows, card_cectl(top), top.engine().config(), frames);
}

namespace {

// The firmware's mode as its policy states it (the run's, or the one it
// was created with).
const char* mode_of(const platform_top& top) {
    if (!top.firmware_started() || top.firmware_init_failed()) return "no firmware";
    return top.firmware_policy().overlapped != 0 ? "overlapped" : "sequential";
}

// What ran and how fast: the DSK, the run's speed, the island's counters.
void print_run(std::FILE* out, const platform_top& top) {
    const platform_config& config = top.config();
    const island& isl = top.cycle_island();
    const run_figures f = figures_of(top);
    const island_stats& st = isl.stats();
    std::fprintf(
        out, "== stereosim platform: DSK %s (CPU %.0f MHz, EMIF %.0f MHz), %s mode, seed %llu\n",
        config.dsk.name, config.dsk.cpu_hz / 1e6, config.dsk.emif_hz / 1e6, mode_of(top),
        static_cast<unsigned long long>(config.seed));
    std::fprintf(out,
                 "run: %.1f ms simulated (%d periods) in %.2f s wall: %.4f simulated/wall, "
                 "%.3f s wall per period; firmware %.2f s wall (%.1f %%), island %.2f s\n",
                 f.sim_s * 1e3, config.frames, f.wall_s, f.sim_per_wall(),
                 f.wall_s / std::max(1, config.frames), f.firmware_wall_s,
                 100.0 * f.firmware_share(), f.island_wall_s);
    std::fprintf(
        out,
        "island: %llu pclk + %llu eclk edges, %llu syncs (%llu at bus completions, %llu at "
        "interrupt pins), pin hash %016llx over %llu changes, timeline %zu events hash %016llx\n",
        static_cast<unsigned long long>(st.pclk_edges),
        static_cast<unsigned long long>(st.eclk_edges), static_cast<unsigned long long>(st.syncs),
        static_cast<unsigned long long>(st.stops_bus),
        static_cast<unsigned long long>(st.stops_irq),
        static_cast<unsigned long long>(isl.pin_hash()),
        static_cast<unsigned long long>(st.pin_changes), top.events().events().size(),
        static_cast<unsigned long long>(top.events().hash()));
    std::fprintf(out, "cycles from cost model %s\n", c64x::cost_model().id());
}

// The OE starts against the sensors' timing truth, and the data path.
void print_sync(std::FILE* out, const scoreboard_report& score) {
    std::fprintf(out,
                 "\n-- sync: %d OE restart(s); first pair in step: sensor frame %lld, FRAME_READY "
                 "at %.3f ms\n",
                 score.oe_restarts, static_cast<long long>(score.first_in_step_frame),
                 score.first_in_step_ready >= 0 ? ticks_to_ms(score.first_in_step_ready) : -1.0);
    for (size_t s = 0; s < score.starts.size(); ++s) {
        const start_check& c = score.starts[s];
        std::fprintf(out, "  OE start %zu at %9.3f ms: frames L %lld R %lld, truth %s, card %s%s\n",
                     s, ticks_to_ms(c.oe_rise), static_cast<long long>(c.frame[0]),
                     static_cast<long long>(c.frame[1]),
                     c.truth_in_step ? "in step" : "OUT of step", card_verdict_name(c.card),
                     c.card == card_verdict::none ? ""
                     : c.agree()                  ? " (agree)"
                                                  : " (DISAGREE)");
    }
    std::fprintf(out,
                 "  forwarded pairs out of step (truth): %d; processed before their verdict: %d; "
                 "processed out of step: %d\n",
                 score.forwarded_out_of_step, score.used_before_verdict, score.used_out_of_step);
    std::fprintf(
        out, "  firmware: %d sync_error reports for %d SYNC_ERROR pulses, in_step at pair %lld\n",
        score.firmware_sync_errors, score.card_sync_errors,
        static_cast<long long>(score.firmware_in_step_pair));
    std::fprintf(
        out,
        "-- data path: %d captured pairs, %d with both frames' checksums equal to the sensors'\n",
        score.integrity_checked, score.integrity_equal);
}

// One row of the per-pair table; the firmware's columns only for a processed pair.
void print_pair_row(std::FILE* out, const platform_top& top, const pair_check& p,
                    const pair_budget& pb) {
    std::fprintf(out, "  %3u %9.3f  %3lld,%-3lld %4llu %s %s %s", p.pair, ticks_to_ms(p.ready),
                 static_cast<long long>(p.frame[0]), static_cast<long long>(p.frame[1]),
                 static_cast<unsigned long long>(p.scene_frame), p.truth_in_step ? "yes" : "NO ",
                 p.captured ? "yes" : "no ", p.processed ? "yes" : "no ");
    if (p.processed) {
        std::fprintf(out, "  %-6s", top.events().state_name(static_cast<int>(p.record.out.state)));
        if (p.errors.box_scored)
            std::fprintf(out, "  %6.2f", p.errors.box_centre_err_px);
        else
            std::fprintf(out, "       -");
        if (p.errors.point_scored)
            std::fprintf(out, "  %7.2f", p.errors.depth_err_pct);
        else
            std::fprintf(out, "        -");
        std::fprintf(out, "  %7.3f %7.3f %7.3f", p.latency_ms, pb.capture_ms, pb.processing_ms);
    } else if (pb.capture_ms > 0.0) {
        std::fprintf(out, "  %41s %7.3f", "", pb.capture_ms);
    }
    std::fprintf(out, "\n");
}

void print_pairs(std::FILE* out, const platform_top& top, const scoreboard_report& score,
                 const budget_report& budget) {
    std::fprintf(out,
                 "\n-- pairs (times ms): pair ready  frames(L,R) scene step captured processed  "
                 "state  box_err_px  depth_err_%%  latency capture processing\n");
    for (size_t i = 0; i < score.pairs.size(); ++i)
        print_pair_row(out, top, score.pairs[i], budget.pairs[i]);
}

// The firmware's track against the scene's truth.
void print_tracking(std::FILE* out, const scoreboard_report& score) {
    const run_summary& s = score.summary;
    char box[64] = "no box scored", near[96] = "none in range", all[64] = "none scored";
    if (s.box_scored_frames > 0)
        std::snprintf(box, sizeof box, "within 3 px in %d (max %.2f px)", score.box_within_3px,
                      score.max_box_err_px);
    if (score.depth_scored_1_3m > 0)
        std::snprintf(near, sizeof near, "within 2 %% in %d of %d (max %.2f %%)",
                      score.depth_within_2pct, score.depth_scored_1_3m, score.max_depth_err_pct);
    if (s.point_scored_frames > 0)
        std::snprintf(all, sizeof all, "%d, max %.2f %%", s.point_scored_frames,
                      s.max_abs_depth_err_pct);
    std::fprintf(out,
                 "\n-- track: first motion scene frame %d, detected at %d; after it %d pairs: box "
                 "centre %s; depth at 1-3 m %s; all scored depths %s; RMSE X %.1f Y %.1f Z %.1f "
                 "mm\n",
                 score.first_motion_frame, score.detection_frame, score.frames_after_detection, box,
                 near, all, s.rmse_x_mm, s.rmse_y_mm, s.rmse_z_mm);
}

// The index of the firmware's stage called `name`, or -1.
int stage_index(const budget_report& budget, const char* name) {
    for (size_t s = 0; s < budget.stage_names.size(); ++s)
        if (budget.stage_names[s] == name) return static_cast<int>(s);
    return -1;
}

// Each stage's modelled time, beside the paper's DSK figures.
void print_stages(std::FILE* out, const budget_report& budget) {
    std::fprintf(
        out,
        "\n-- stages (modelled, %s at %.0f MHz): mean / max per processed pair, ms; total cycles\n",
        c64x::cost_model().id(), budget.cpu_hz / 1e6);
    const int stages = static_cast<int>(budget.stage_names.size());
    for (int s = 0; s < stages; ++s) {
        std::fprintf(out, "  %-11s %8.3f %8.3f  %12llu\n", budget.stage_names[s].c_str(),
                     budget.stage_ms_mean[s], budget.stage_ms_max[s],
                     static_cast<unsigned long long>(budget.stage_cycles_total[s]));
    }
    // The paper's figures are of its stages: shown for a firmware that has them.
    const int track = stage_index(budget, "track"), sad = stage_index(budget, "stereo_sad"),
              edge = stage_index(budget, "stereo_edge"), xyz = stage_index(budget, "xyz");
    if (track < 0 || sad < 0 || edge < 0 || xyz < 0) return;
    std::fprintf(
        out,
        "  paper (DSK): track ~%.3f ms (ours max %.3f), stereo_sad ~%.2f ms (ours max %.3f), "
        "stereo_edge + xyz < %.1f ms (ours max %.3f)\n",
        paper_track_ms, budget.stage_ms_max[track], paper_stereo_sad_ms, budget.stage_ms_max[sad],
        paper_edge_xyz_ms, budget.stage_ms_max[edge] + budget.stage_ms_max[xyz]);
}

// The measured capture beside the closed forms, and what the modes need.
void print_closed_forms(std::FILE* out, const platform_top& top, const budget_report& budget) {
    const platform_config& config = top.config();
    const capture_figures cf = capture_closed_form(top);
    const readout_figures rf = readout(config.profile);
    std::fprintf(
        out,
        "\n-- capture: measured mean %.3f ms max %.3f ms per pair (FRAME_READY to the chain's last "
        "burst); closed form %.3f ms (%llu ECLK: line %llu, header %llu, refresh +%.2f %%)\n",
        budget.mean_capture_ms, budget.max_capture_ms, cf.total_ms(),
        static_cast<unsigned long long>(cf.total_eclk),
        static_cast<unsigned long long>(cf.line_eclk),
        static_cast<unsigned long long>(cf.header_eclk), 100.0 * cf.refresh_fraction);
    std::fprintf(out,
                 "   readout: first active pixel %.3f ms after frame start, active span %.3f ms, "
                 "frame %.3f ms\n",
                 rf.first_active_ms(), rf.active_span_ms(), rf.frame_ms());
    // The firmware's SDRAM lines on the bus (docs/budget.md): only when they
    // are replayed there.
    const traffic_figures tf =
        firmware_traffic(config.profile.active_cols, config.profile.active_rows, card_cectl(top),
                         top.engine().config());
    const double traffic_ms = config.sdram_traffic_on_bus ? tf.ms() : 0.0;
    std::fprintf(out,
                 "   firmware SDRAM lines per pair %llu x %llu ECLK (inside a card burst) = %.3f "
                 "ms%s\n",
                 static_cast<unsigned long long>(tf.lines),
                 static_cast<unsigned long long>(tf.line_eclk), tf.ms(),
                 config.sdram_traffic_on_bus ? "" : " (off the bus: not counted)");
    const mode_estimate seq =
        estimate_sequential(cf.total_ms(), traffic_ms, budget.max_processing_ms, budget.period_ms);
    const mode_estimate ovl =
        estimate_overlapped(cf.total_ms(), traffic_ms, budget.max_processing_ms, budget.period_ms);
    std::fprintf(out,
                 "   estimate with max processing %.3f ms: sequential needs %.3f ms (%s), "
                 "overlapped %.3f ms (%s)\n",
                 budget.max_processing_ms, seq.need_ms, seq.fits ? "fits" : "over", ovl.need_ms,
                 ovl.fits ? "fits" : "over");
}

// The firmware's SDRAM traffic as the chip saw it, then per stage.
void print_sdram_traffic(std::FILE* out, const platform_top& top) {
    const platform_config& config = top.config();
    const c6416::c6416_sc& chip = top.cpu();
    // Where the firmware keeps its frames, if it has the reference's key for it.
    std::string memory = key_choice(top.firmware_descriptor(), config, "frame_memory");
    for (char& c : memory) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    if (!memory.empty()) memory = "frames in " + memory + ", ";
    std::fprintf(out,
                 "\n-- firmware SDRAM traffic (%s%s): L2 lines read %llu, written back "
                 "%llu; transfer time %.3f ms; CPU waited past its charges %.3f ms\n",
                 memory.c_str(), config.sdram_traffic_on_bus ? "on the EMIF bus" : "off the bus",
                 static_cast<unsigned long long>(chip.sdram_lines_read()),
                 static_cast<unsigned long long>(chip.sdram_lines_written()),
                 chip.sdram_transfer_time().to_seconds() * 1e3,
                 chip.sdram_late_time().to_seconds() * 1e3);
    if (!top.firmware_started()) return;
    for (uint32_t s = 0; s < top.firmware_descriptor().stage_count; ++s) {
        const stereosim_sdram_traffic& t = top.probe().stage_traffic(static_cast<int>(s));
        if (t.bytes_read == 0 && t.bytes_written == 0) continue;
        std::fprintf(out, "   %-11s read %llu B, written %llu B\n",
                     top.events().stage_name(static_cast<int>(s)),
                     static_cast<unsigned long long>(t.bytes_read),
                     static_cast<unsigned long long>(t.bytes_written));
    }
}

// The budget period by period, the peaks, the verdict and the first overruns.
void print_budget(std::FILE* out, const budget_report& budget) {
    std::fprintf(
        out,
        "\n-- budget per %.1f ms period (judged from the first forwarded pair): cpu_busy emif_busy "
        "cpu_words fifo_peak_L fifo_peak_R overflow drops | stage ms\n",
        budget.period_ms);
    for (const period_budget& p : budget.periods) {
        std::fprintf(out, "  %2d %s %7.3f %7.3f %7llu %6u %6u %d %d |", p.index,
                     p.judged ? "*" : " ", p.cpu_busy_ms, p.emif_busy_ms,
                     static_cast<unsigned long long>(p.cpu_words), p.fifo_peak_words[0],
                     p.fifo_peak_words[1], p.overflow ? 1 : 0, p.drops);
        for (size_t s = 0; s < budget.stage_names.size(); ++s)
            std::fprintf(out, " %6.3f", p.stage_ms[s]);
        std::fprintf(out, "\n");
    }
    std::fprintf(
        out, "  fifo peak words L %u R %u (of %u); latency max %.3f ms; drops %d; overflows %d\n",
        budget.fifo_peak_words[0], budget.fifo_peak_words[1], card_fifo_words,
        budget.latency_ms_max, budget.drops, budget.overflows);
    // No period judged (no in-step pair ever forwarded) is no fit, but not
    // an overrun either: say which.
    std::fprintf(out, "VERDICT: %s (%d judged periods, %zu overruns)\n",
                 budget.fits                  ? "within budget"
                 : budget.judged_periods == 0 ? "NOT JUDGED: no period could be judged"
                                              : "OVER BUDGET",
                 budget.judged_periods, budget.overruns.size());
    const size_t shown = std::min<size_t>(budget.overruns.size(), 8);
    for (size_t i = 0; i < shown; ++i)
        std::fprintf(out, "  %s\n", budget.overruns[i].describe().c_str());
    if (budget.overruns.size() > shown)
        std::fprintf(out, "  ... %zu more\n", budget.overruns.size() - shown);
}

}  // namespace

void print_report(std::FILE* out, const platform_top& top, const scoreboard_report& score,
                  const budget_report& budget, bool per_pair) {
    print_run(out, top);
    print_sync(out, score);
    if (per_pair) print_pairs(out, top, score, budget);
    print_tracking(out, score);
    print_stages(out, budget);
    print_closed_forms(out, top, budget);
    print_sdram_traffic(out, top);
    print_budget(out, budget);
}

}  // namespace platform
