#include "tb/platform/closed_form.h"

#include <algorithm>

#include "model/c6416/c6416_regs.h"
#include "model/emif/cectl.h"
#include "tb/platform/firmware_board.h"

namespace platform {

frame_placement reference_placement(int cols, int rows) {
    // control_program_edma::header_bytes ahead of the left frame (docs/budget.md).
    constexpr uint64_t header_bytes = 64;
    const uint64_t frame_bytes = static_cast<uint64_t>(cols) * static_cast<uint64_t>(rows);
    return {header_bytes, header_bytes + frame_bytes};
}

readout_figures readout(const sensor::sensor_profile& p) {
    readout_figures r;
    const int64_t line = p.line_pclks;
    const int64_t first_row = p.first_row_line + p.active_row0();
    const int64_t first_col = p.href_start + p.active_col0();
    r.first_active_pclk = first_row * line + first_col;
    r.last_active_pclk = (first_row + p.active_rows - 1) * line + first_col + p.active_cols - 1;
    r.frame_pclks = p.frame_pclks();
    const simtime::rational_ticks period = p.pclk_period();
    r.pclk_ns = static_cast<double>(period.num) / static_cast<double>(period.den) /
                static_cast<double>(simtime::ticks_per_ns);
    return r;
}

frame_placement reported_placement(const std::vector<fw_event>& events, int cols, int rows) {
    for (const fw_event& e : events) {
        if (e.event.kind != STEREOSIM_EV_PAIR_CAPTURED) continue;
        // Both at one address: the report named no frames (as rule 7 reads it).
        if (e.event.left == e.event.right) continue;
        if (!c6416::in_sdram(e.event.left) || !c6416::in_sdram(e.event.right)) continue;
        return {e.event.left, e.event.right};
    }
    return reference_placement(cols, rows);
}

capture_figures capture(int cols, int rows, uint32_t card_cectl, const emif::emif_config& emif,
                        const frame_placement& frames) {
    capture_figures c;
    const emif::async_timing card = emif::decode_cectl(card_cectl);
    const uint64_t ta = card.turnaround;  // CE2/CE3 <-> CE0 and back: the async space's TA
    const uint64_t words_per_line = static_cast<uint64_t>(cols) / 4;
    const emif::sdram_timing& sd = emif.sdram;
    // An SDRAM burst: one row access, then 2 words per ECLK (64-bit bus);
    // the chunks of one burst follow each other with the row open.
    const auto sdram_write = [&](uint64_t words) { return sd.access_cycles + (words + 1) / 2; };
    const uint64_t status_words = 5;  // VERDICT .. PAIRS_OK
    c.header_eclk = status_words * card.read_cycles() + ta + sdram_write(status_words);
    c.line_eclk = ta + words_per_line * card.read_cycles() + ta + sdram_write(words_per_line);
    c.pair_eclk = c.header_eclk + 2 * static_cast<uint64_t>(rows) * c.line_eclk;
    // An SDRAM line burst that crosses a 2 KB row boundary pays the row
    // access again there (docs/emif.md). Each frame is written line after line.
    const uint64_t line_bytes = static_cast<uint64_t>(cols);
    const uint64_t starts[2] = {frames.left, frames.right};
    for (uint64_t start : starts) {
        for (uint64_t k = 0; sd.row_bytes > 0 && k < static_cast<uint64_t>(rows); ++k) {
            const uint64_t first = start + k * line_bytes;
            const uint64_t last = first + line_bytes - 1;
            c.row_crossings += last / sd.row_bytes - first / sd.row_bytes;
        }
    }
    c.pair_eclk += c.row_crossings * sd.access_cycles;
    // Refresh: one every refresh_period ECLK. Inside a card burst it costs
    // TA + refresh + TA, next to SDRAM data only the refresh (docs/emif.md).
    const double async_share =
        static_cast<double>(words_per_line * card.read_cycles()) / static_cast<double>(c.line_eclk);
    if (sd.refresh_period > 0) {
        const double cost = sd.refresh_cycles + 2.0 * ta * async_share;
        c.refresh_fraction = cost / (static_cast<double>(sd.refresh_period) - cost);
    }
    c.total_eclk =
        static_cast<uint64_t>(static_cast<double>(c.pair_eclk) * (1.0 + c.refresh_fraction) + 0.5);
    const simtime::tick_clock& eclk = emif.eclk;
    c.eclk_ns = static_cast<double>(eclk.period_num()) / static_cast<double>(eclk.period_den()) /
                static_cast<double>(simtime::ticks_per_ns);
    return c;
}

traffic_figures firmware_traffic(int cols, int rows, uint32_t card_cectl,
                                 const emif::emif_config& emif, uint32_t l2_line_bytes) {
    traffic_figures t;
    const uint64_t bytes = 2ull * static_cast<uint64_t>(cols) * static_cast<uint64_t>(rows);
    t.lines = (bytes + l2_line_bytes - 1) / l2_line_bytes;
    const uint64_t ta = emif::decode_cectl(card_cectl).turnaround;
    t.line_eclk = ta + emif.sdram.access_cycles + (l2_line_bytes / 4 + 1) / 2 + ta;
    t.eclk = t.lines * t.line_eclk;
    t.eclk_ns = static_cast<double>(emif.eclk.period_num()) /
                static_cast<double>(emif.eclk.period_den()) /
                static_cast<double>(simtime::ticks_per_ns);
    return t;
}

mode_estimate estimate_overlapped(double capture_ms, double traffic_ms, double processing_ms,
                                  double period_ms) {
    return estimate_overlapped(capture_ms + traffic_ms, processing_ms, period_ms);
}

mode_estimate estimate_sequential(double capture_ms, double traffic_ms, double processing_ms,
                                  double period_ms) {
    (void)traffic_ms;  // inside the processing time
    return estimate_sequential(capture_ms, processing_ms, period_ms);
}

mode_estimate estimate_sequential(double capture_ms, double processing_ms, double period_ms) {
    mode_estimate e;
    e.need_ms = capture_ms + processing_ms;
    e.fits = e.need_ms <= period_ms;
    return e;
}

mode_estimate estimate_overlapped(double capture_ms, double processing_ms, double period_ms) {
    mode_estimate e;
    e.need_ms = std::max(capture_ms, processing_ms);
    e.fits = e.need_ms <= period_ms;
    return e;
}

budget_estimate estimate_budget(const platform_config& config, double processing_ms,
                                bool overlapped) {
    const emif::emif_config emif = engine_config(config);
    const uint32_t cectl = card_cectl_asked(config);
    const int cols = config.profile.active_cols, rows = config.profile.active_rows;
    budget_estimate b;
    b.capture_ms = capture(cols, rows, cectl, emif, reference_placement(cols, rows)).total_ms();
    b.traffic_ms = config.sdram_traffic_on_bus ? firmware_traffic(cols, rows, cectl, emif).ms() : 0;
    b.processing_ms = processing_ms;
    const double period_ms = static_cast<double>(config.period) / (simtime::ticks_per_ns * 1e6);
    b.verdict = overlapped
                    ? estimate_overlapped(b.capture_ms, b.traffic_ms, processing_ms, period_ms)
                    : estimate_sequential(b.capture_ms, b.traffic_ms, processing_ms, period_ms);
    return b;
}

}  // namespace platform
