// The firmware's own SDRAM traffic on EMIFA (issue 5, docs/c6416.md): a
// charge with SDRAM traffic puts its bytes on emifa_cpu as 128-byte L2 line
// transfers, spread over the charge's CPU cycles, through the real EMIF
// engine (emif_tlm_target + emif_cycle_driver, SDRAM on CE0, an SRAM with the
// card's timing on CE2). One simulation, four phases:
//   A (0 ms)  a charge with traffic on an idle bus: the charge takes exactly
//             its cycles; the bus carries exactly the closed-form lines;
//   B (2 ms)  a 2000-word card burst (CE2, fixed address) alone;
//   C (3 ms)  the same burst while a charge's 40 line reads are spread over
//             it: the burst is delayed by exactly 40 x (TA + line + TA);
//   D (4 ms)  more traffic than the charge's cycles can cover: the CPU waits
//             past the charged end for its last line.
// Refresh is off so every figure is exact.
#include <gtest/gtest.h>
#include <tlm_utils/simple_initiator_socket.h>

#include <cstdio>
#include <vector>

#include "c6416_test_util.h"
#include "model/c6416/c6416_regs.h"
#include "model/c6416/c6416_sc.h"
#include "model/c64x/cost_model.h"
#include "model/emif/cectl.h"
#include "model/emif/emif_tlm_target_sc.h"
#include "tests/support/emif/async_sram_slave.h"
#include "tests/support/emif/emif_cycle_driver_sc.h"

using namespace c6416_test;

namespace {

constexpr uint64_t line_bytes = 128;
constexpr uint64_t eclk_ps = 10000;  // 100 MHz

// A stand-in for the EDMA's capture: one fixed-address burst from the card's
// space (CE2) at each given time, its completion time recorded.
class card_reader : public sc_core::sc_module {
  public:
    tlm_utils::simple_initiator_socket<card_reader> socket;
    std::vector<sc_core::sc_time> starts;
    std::vector<sc_core::sc_time> done;
    uint32_t words = 2000;

    SC_HAS_PROCESS(card_reader);
    explicit card_reader(sc_core::sc_module_name name)
        : sc_core::sc_module(name), socket("socket") {
        SC_THREAD(run);
    }

  private:
    void run() {
        std::vector<uint8_t> data(words * 4u);
        for (const sc_core::sc_time& t : starts) {
            if (t > sc_core::sc_time_stamp()) wait(t - sc_core::sc_time_stamp());
            tlm::tlm_generic_payload p;
            p.set_command(tlm::TLM_READ_COMMAND);
            p.set_address(0xA0000000u);
            p.set_data_ptr(data.data());
            p.set_data_length(words * 4u);
            p.set_streaming_width(4);  // a FIFO port
            p.set_byte_enable_ptr(nullptr);
            p.set_response_status(tlm::TLM_INCOMPLETE_RESPONSE);
            sc_core::sc_time delay = sc_core::SC_ZERO_TIME;
            socket->b_transport(p, delay);
            wait(delay);
            EXPECT_TRUE(p.is_response_ok());
            done.push_back(sc_core::sc_time_stamp());
        }
    }
};

struct bus_snapshot {
    uint64_t busy_edges = 0;
    uint64_t cpu_words = 0;
    uint64_t lines_read = 0;
    uint64_t lines_written = 0;
};

}  // namespace

TEST(C6416SdramTrafficSc, FirmwareSdramLinesTakeBusTimeAndDelayTheCapture) {
    emif::emif_config ec;
    ec.sdram.refresh_period = 0;  // exact figures
    emif::emif_async_master engine(ec);
    emif::emif_tlm_target target("emifa", engine);
    emif::sram_config sc;
    sc.ce = 2;
    emif::async_sram_slave card(sc);
    emif::emif_cycle_driver driver("driver", engine, target.work_event(), card);
    c6416::c6416_sc chip("dsk");
    engine.set_sdram_storage(chip.sdram_storage(), chip.sdram_storage_bytes());
    chip.emifa_cpu.bind(target.cpu);
    card_reader reader("reader");
    reader.socket.bind(target.edma);
    reader.starts = {us(2000), us(3000)};

    const emif::emif_stats& stats = engine.stats();
    auto snapshot = [&] {
        return bus_snapshot{stats.busy_edges, stats.words[static_cast<int>(emif::requester::cpu)],
                            chip.sdram_lines_read(), chip.sdram_lines_written()};
    };

    // Phase A: 1 ms of CPU (600,000 cycles) streaming 100 lines in, 50 out.
    const uint64_t cycles_a = 600000;
    const c6416::sdram_traffic traffic_a{100 * line_bytes, 50 * line_bytes};
    // Phase C: 200 us from 3.010 ms, 40 lines in, while the card burst
    // (3.000 ms + 2000 x 14 ECLK = 280 us) runs.
    const uint64_t cycles_c = 120000;
    const c6416::sdram_traffic traffic_c{40 * line_bytes, 0};
    // Phase D: 10 us of CPU for 100 lines (100 x 23 ECLK = 23 us of bus).
    const uint64_t cycles_d = 6000;
    const c6416::sdram_traffic traffic_d{100 * line_bytes, 0};

    bus_snapshot before_a, after_a, before_c, after_c;
    sc_core::sc_time a_begin, a_end, c_begin, c_end, d_begin, d_end;
    chip.set_firmware([&](c6416::cpu_port& h) {
        before_a = snapshot();
        a_begin = sc_core::sc_time_stamp();
        h.charge(stage::preprocess, cycles_a, traffic_a);
        a_end = sc_core::sc_time_stamp();
        after_a = snapshot();
        h.charge(stage::capture, 1806000 - cycles_a);  // to 3.010 ms
        before_c = snapshot();
        c_begin = sc_core::sc_time_stamp();
        h.charge(stage::detect, cycles_c, traffic_c);
        c_end = sc_core::sc_time_stamp();
        after_c = snapshot();
        h.charge(stage::capture, 2400000 - 1806000 - cycles_c);  // to 4 ms
        d_begin = sc_core::sc_time_stamp();
        h.charge(stage::track, cycles_d, traffic_d);
        d_end = sc_core::sc_time_stamp();
    });
    sc_core::sc_start(us(5000));

    // ---- A: the closed form of the lines, the charge's time unchanged ----------------------
    // Lines read: 100 reads + 50 write-allocate fetches; written back: 50.
    // A line is one SDRAM access: row access 7 + 16 data ECLK = 23. On an
    // otherwise idle bus the engine keeps the SDRAM row open from one CPU
    // line to the next when the next is in the same 2 KB row (docs/emif.md):
    // the replayed lines go to consecutive addresses of the window
    // (0x80C00000, row aligned), so a row access only every 16 lines:
    // 200 lines touch 13 rows: 13 x 7 + 200 x 16 (docs/c6416.md).
    const uint64_t transfers_a = 100 + 2 * 50;
    const uint64_t data_edges = line_bytes / 8;                       // 2 words per ECLK
    const uint64_t line_edges = ec.sdram.access_cycles + data_edges;  // 7 + 16 = 23
    const uint64_t lines_per_row = ec.sdram.row_bytes / line_bytes;   // 16
    // Rows touched by `count` consecutive lines from replayed line `first`.
    auto rows_touched = [&](uint64_t first, uint64_t count) {
        return (first + count - 1) / lines_per_row - first / lines_per_row + 1;
    };
    EXPECT_EQ(after_a.lines_read - before_a.lines_read, 150u);
    EXPECT_EQ(after_a.lines_written - before_a.lines_written, 50u);
    EXPECT_EQ(after_a.cpu_words - before_a.cpu_words, transfers_a * line_bytes / 4);
    EXPECT_EQ(rows_touched(0, transfers_a), 13u);
    EXPECT_EQ(after_a.busy_edges - before_a.busy_edges,
              rows_touched(0, transfers_a) * ec.sdram.access_cycles + transfers_a * data_edges);
    EXPECT_EQ(fs_of(a_begin), 0);
    EXPECT_EQ(fs_of(a_end), cpu_edge_fs(cycles_a, 600000000));
    // The cost model's own figure for the same bytes (model/c64x/cost_model.h:
    // 7 + 16 ECLK per line, the engine's line with its row closed).
    c64x::memory_traffic stream;
    stream.bytes_read = traffic_a.bytes_read;
    stream.bytes_written = traffic_a.bytes_written;
    stream.where = c64x::placement::sdram;
    const uint64_t cost_model_ps = c64x::cost_model().emif_busy_ps(stream);
    EXPECT_EQ(cost_model_ps, transfers_a * line_edges * eclk_ps);
    std::printf(
        "A: %llu transfers, bus busy %llu ECLK (engine: 16 per line, 7 per row opened) vs cost "
        "model %.0f "
        "ECLK (23 per line); charge %.3f us as charged\n",
        static_cast<unsigned long long>(transfers_a),
        static_cast<unsigned long long>(after_a.busy_edges - before_a.busy_edges),
        static_cast<double>(cost_model_ps) / eclk_ps, a_end.to_seconds() * 1e6);

    // ---- B and C: the card burst alone, then with 40 lines spread over it --------------------
    ASSERT_EQ(reader.done.size(), 2u);
    const emif::async_timing card_timing = emif::decode_cectl(ec.cectl[2]);
    const uint64_t ta = card_timing.turnaround;
    const sc_core::sc_time alone = reader.done[0] - reader.starts[0];
    const sc_core::sc_time shared = reader.done[1] - reader.starts[1];
    const int64_t delay_fs = fs_of(shared) - fs_of(alone);
    const int64_t expected_fs = 40 * static_cast<int64_t>(ta + line_edges + ta) * 10000000;
    EXPECT_EQ(fs_of(alone), (1 + 2000 * 14) * 10000000LL);  // first edge after the request
    EXPECT_EQ(delay_fs, expected_fs);
    EXPECT_EQ(after_c.lines_read - before_c.lines_read, 40u);
    EXPECT_EQ(fs_of(c_end) - fs_of(c_begin),
              fs_of(chip.time_of_cpu_cycle(chip.cpu_cycle_at_or_after(c_begin) + cycles_c)) -
                  fs_of(c_begin));
    std::printf(
        "B/C: card burst of 2000 words alone %.3f us, with 40 SDRAM lines %.3f us: "
        "delayed %.3f us = 40 x (TA %llu + %llu + TA %llu) ECLK\n",
        alone.to_seconds() * 1e6, shared.to_seconds() * 1e6, delay_fs * 1e-9,
        static_cast<unsigned long long>(ta), static_cast<unsigned long long>(line_edges),
        static_cast<unsigned long long>(ta));

    // ---- D: the CPU waits for lines its cycles cannot cover -------------------------------------
    // Back to back each line is 16 ECLK (row kept open, as in A; 7 more per
    // row opened: replayed lines 240..339 touch 7 rows) plus the one edge a
    // request made at an edge waits (docs/emif.md rule 5): 7 x 7 + 100 x 17
    // ECLK = 17.49 us after 4 ms.
    EXPECT_EQ(fs_of(d_begin), 4000000000000LL);
    EXPECT_EQ(rows_touched(240, 100), 7u);
    EXPECT_EQ(fs_of(d_end) - fs_of(d_begin),
              static_cast<int64_t>(rows_touched(240, 100) * ec.sdram.access_cycles +
                                   100 * (data_edges + 1)) *
                  10000000LL);
    const int64_t late_fs = fs_of(d_end) - fs_of(d_begin) - 10000000000LL;  // charged 10 us
    EXPECT_EQ(fs_of(chip.sdram_late_time()), late_fs);
    std::printf("D: 100 lines in a 10 us charge: the CPU took %.3f us (late %.3f us)\n",
                (d_end - d_begin).to_seconds() * 1e6, late_fs * 1e-9);
    EXPECT_EQ(chip.bus_errors(), 0u);
}
