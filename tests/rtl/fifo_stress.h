// Cycle-by-cycle stress of a verilated dual-clock FIFO (rtl/async_fifo.v or
// the binary-pointer negative control), shared by test_async_fifo.cpp and
// test_async_fifo_binary.cpp. Model: any class with the async_fifo ports.
//
// Writer and reader run random bursts on two unrelated clocks; the writer
// sends sequence numbers, so the scoreboard sees every loss, duplicate or
// reordering. At every edge, before it, the checks read the DUT's flags and
// levels and compare them with the exact expectations:
//   - wr_full == (wr_level == depth), rd_empty == (rd_level == 0);
//   - wr_level >= true occupancy >= rd_level (flags are safe);
//   - held value: the other side's pointer as this side sees it (implied by
//     the level: rptr_seen = wptr - wr_level, wptr_seen = rptr + rd_level)
//     must be a value that pointer really held in the synchronizer's window
//     (3 destination periods + 2 source periods back, up to now);
//   - wr_overflow set exactly when a write hit a full FIFO since wr_clear,
//     wr_peak equal to the maximum level seen since wr_clear.
#pragma once

#include <chrono>
#include <cstdint>
#include <deque>
#include <memory>
#include <random>

#include "tests/rtl/rtl_sim.h"

namespace rtl_test {

struct fifo_stress_config {
    uint64_t write_period = ticks_pclk_default;
    uint64_t read_period = ticks_eclk_v1;
    uint64_t write_phase = 0;
    uint64_t read_phase = 0;
    uint64_t words = 100000;  // run until this many words were read
    uint64_t seed = 1;
    bool allow_overflow = true;  // some phases write without looking at full
};

struct fifo_stress_result {
    uint64_t accepted = 0;  // words written
    uint64_t read = 0;      // words read
    uint64_t dropped = 0;   // writes that hit a full FIFO
    uint64_t write_edges = 0, read_edges = 0;
    uint64_t full_edges = 0, empty_edges = 0;  // edges that saw full / empty
    uint64_t data_errors = 0;                  // a word read that is not the next one written
    uint64_t flag_errors = 0;                  // full/empty/overflow/peak not exactly as expected
    uint64_t bound_errors = 0;                 // a level on the unsafe side of the true occupancy
    uint64_t held_violations = 0;              // a synchronized pointer the source never held
    uint64_t held_checks = 0;
    uint64_t window_too_wide = 0;  // test self-check: history window >= pointer range
    uint64_t rtl_errors = 0;       // Verilator assertion failures
    double seconds = 0.0;
};

namespace detail {

// A pointer's values over time (absolute counts, not wrapped).
class pointer_history {
  public:
    void record(uint64_t tick, uint64_t count) { m_hist.push_back({tick, count}); }
    // Value held just before `tick` (the oldest value in the window).
    uint64_t value_before(uint64_t tick) {
        while (m_hist.size() > 1 && m_hist[1].tick < tick) m_hist.pop_front();
        return m_hist.front().count;
    }

  private:
    struct entry {
        uint64_t tick, count;
    };
    std::deque<entry> m_hist{{0, 0}};
};

struct burst_state {
    uint64_t burst_left = 0, idle_left = 0;
    uint64_t max_burst = 16, max_idle = 16;
    void next(std::mt19937_64& rng) {
        burst_left = 1 + rng() % max_burst;
        idle_left = max_idle ? rng() % (max_idle + 1) : 0;
    }
};

}  // namespace detail

template <class Model>
fifo_stress_result run_fifo_stress(const fifo_stress_config& cfg, int aw,
                                   uint64_t error_limit = 1) {
    const uint64_t depth = uint64_t{1} << aw;
    const uint64_t range = depth * 2;  // pointer values are mod 2^(AW+1)
    const uint64_t mask = range - 1;

    auto context = std::make_unique<VerilatedContext>();
    context->randSeed(static_cast<int>(cfg.seed & 0x7fffffff));
    context->errorLimit(static_cast<int>(error_limit));
    auto dut = std::make_unique<Model>(context.get(), "fifo");

    std::mt19937_64 rng(cfg.seed);
    fifo_stress_result res;
    const auto wall_start = std::chrono::steady_clock::now();

    // Reset both domains.
    dut->wclk = 0;
    dut->rclk = 0;
    dut->wrst_n = 0;
    dut->rrst_n = 0;
    dut->wr_en = 0;
    dut->rd_en = 0;
    dut->wr_clear = 0;
    dut->wr_data = 0;
    dut->eval();
    dut->wrst_n = 1;
    dut->rrst_n = 1;
    dut->eval();

    two_clocks clocks(cfg.write_period, cfg.read_period, cfg.write_phase, cfg.read_phase);
    const uint64_t tw = cfg.write_period, tr = cfg.read_period;
    const uint64_t window_at_read = 3 * tr + 2 * tw;   // write pointer seen by the reader
    const uint64_t window_at_write = 3 * tw + 2 * tr;  // read pointer seen by the writer

    detail::pointer_history whist, rhist;
    std::deque<uint32_t> expected;  // words written, not yet read
    uint64_t wcount = 0, rcount = 0, attempts = 0;
    uint64_t drops_since_clear = 0, model_peak = 0;
    bool wr_en = false, rd_en = false, wr_clear = false;
    bool writer_ignores_full = false;
    detail::burst_state writer, reader;
    writer.next(rng);
    reader.next(rng);
    uint64_t next_phase_at = 0;

    const auto new_phase = [&]() {
        // Duty cycles change every few thousand words: the FIFO spends whole
        // stretches full, empty, and in between.
        writer.max_burst = 1 + rng() % 48;
        writer.max_idle = rng() % 4 == 0 ? 0 : rng() % 48;
        reader.max_burst = 1 + rng() % 48;
        reader.max_idle = rng() % 4 == 0 ? 0 : rng() % 48;
        writer_ignores_full = cfg.allow_overflow && rng() % 5 == 0;
    };
    new_phase();

    const uint64_t max_edges = cfg.words * 400 + 100000;
    while (res.read < cfg.words && res.write_edges + res.read_edges < max_edges) {
        const unsigned edges = clocks.advance();
        const uint64_t t = clocks.now();
        const bool w_edge = edges & two_clocks::edge_a;
        const bool r_edge = edges & two_clocks::edge_b;

        // ---- checks on the values just before the edge(s) ----
        bool w_accept = false, w_drop = false, r_accept = false;
        uint64_t level_before_w = 0;
        if (w_edge) {
            const uint64_t level = dut->wr_level;
            level_before_w = level;
            const bool full = dut->wr_full;
            if (full != (level == depth)) ++res.flag_errors;
            if (level < wcount - rcount) ++res.bound_errors;
            const uint64_t lo = rhist.value_before(t > window_at_write ? t - window_at_write : 0);
            if (rcount - lo >= range) ++res.window_too_wide;
            const uint64_t seen = (wcount - level) & mask;
            ++res.held_checks;
            if (((seen - lo) & mask) > rcount - lo) ++res.held_violations;
            if (full) ++res.full_edges;
            w_accept = wr_en && !full;
            w_drop = wr_en && full;
        }
        if (r_edge) {
            const uint64_t level = dut->rd_level;
            const bool empty = dut->rd_empty;
            if (empty != (level == 0)) ++res.flag_errors;
            if (level > wcount - rcount) ++res.bound_errors;
            const uint64_t lo = whist.value_before(t > window_at_read ? t - window_at_read : 0);
            if (wcount - lo >= range) ++res.window_too_wide;
            const uint64_t seen = (rcount + level) & mask;
            ++res.held_checks;
            if (((seen - lo) & mask) > wcount - lo) ++res.held_violations;
            if (empty) ++res.empty_edges;
            r_accept = rd_en && !empty;
        }

        // ---- the edge ----
        if (w_edge) dut->wclk = 1;
        if (r_edge) dut->rclk = 1;
        dut->eval();

        // ---- scoreboard and new stimulus after the edge ----
        if (w_edge) {
            ++res.write_edges;
            if (w_accept) {
                expected.push_back(static_cast<uint32_t>(dut->wr_data));
                ++wcount;
                ++res.accepted;
                whist.record(t, wcount);
            }
            if (w_drop) {
                ++res.dropped;
                ++drops_since_clear;
            }
            if (wr_clear) {
                drops_since_clear = 0;
                model_peak = level_before_w;
            } else if (level_before_w > model_peak) {
                model_peak = level_before_w;
            }
            if (dut->wr_overflow != (drops_since_clear > 0)) ++res.flag_errors;
            if (dut->wr_peak != model_peak) ++res.flag_errors;

            // Next write: bursts and gaps; full is stable until the next write edge.
            wr_en = false;
            if (writer.idle_left > 0) {
                --writer.idle_left;
            } else {
                if (writer_ignores_full || !dut->wr_full) {
                    wr_en = true;
                    if (--writer.burst_left == 0) writer.next(rng);
                }
            }
            wr_clear = rng() % 4096 == 0;
            dut->wr_en = wr_en;
            dut->wr_clear = wr_clear;
            dut->wr_data = static_cast<uint32_t>(0x5EC00000u + attempts);
            if (wr_en) ++attempts;
        }
        if (r_edge) {
            ++res.read_edges;
            if (r_accept) {
                const uint32_t got = dut->rd_data;
                if (expected.empty() || expected.front() != got) ++res.data_errors;
                if (!expected.empty()) expected.pop_front();
                ++rcount;
                ++res.read;
                rhist.record(t, rcount);
                if (res.read >= next_phase_at) {
                    next_phase_at = res.read + 2048 + rng() % 4096;
                    new_phase();
                }
            }
            rd_en = false;
            if (reader.idle_left > 0) {
                --reader.idle_left;
            } else if (!dut->rd_empty) {
                rd_en = true;
                if (--reader.burst_left == 0) reader.next(rng);
            }
            dut->rd_en = rd_en;
        }
        if (w_edge) dut->wclk = 0;
        if (r_edge) dut->rclk = 0;
        dut->eval();
    }
    if (res.read < cfg.words) ++res.data_errors;  // stalled: the FIFO lost words for good

    res.rtl_errors = context->errorCount();
    res.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
    dut->final();
    write_coverage(*context, "async_fifo");
    return res;
}

}  // namespace rtl_test
