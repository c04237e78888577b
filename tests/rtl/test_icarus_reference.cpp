// Icarus Verilog as the outside reference for the verilated card (issue 8;
// docs/arrangements.md "Icarus reference"): the card's input pins of a
// window from reset are recorded into a stimulus file, replayed under vvp by
// tests/rtl/icarus/card_replay_tb.v and into a fresh verilated card (rtl_card,
// the platform's parameters), and the card's outputs (OE, ED, ED_OE, ARDY,
// EXT_INT4-6) must be equal after every phase of every clock event.
//
// The stimulus: the rtl test bench (tests/rtl/card_bench.h) on the real
// clocks (120/7 MHz pixel clock, 100 MHz ECLK, CECTL 0x22A28A22) with the
// small sensor layout (a 73 us frame), so 2 ms from reset hold the register
// writes over the EMIF, a sync-check failure (the right sensor starts a line
// late), the OE restart, in-step frames, FRAME_READY and the DSP model's
// reads of whole frame pairs out of both FIFOs. The VGA layout would need
// ~26 ms from reset before the first read (minutes under Icarus).
//
// iverilog and vvp run as child processes (PATH). Icarus is four-state: any
// x or z on an output prints as such and fails the comparison.
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "Vcard.h"
#include "tests/rtl/card_bench.h"
#include "tests/rtl/icarus/card_stimulus.h"

namespace {

using bench = rtl_test::card_bench<Vcard>;
namespace regs = dsp::card_regs;
using icarus_ref::clock_event;

constexpr simtime::ticks ticks_per_us = 18000;
constexpr simtime::ticks window_ticks = 2000 * ticks_per_us;  // 2 ms from reset

std::string repo_root() {
    // From CMake, not __FILE__: ccache's base_dir makes __FILE__ relative.
    return STEREOSIM_SOURCE_DIR;
}

double wall_since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

struct recording {
    icarus_ref::card_inputs before_reset;
    std::vector<clock_event> events;
    std::vector<std::string> outputs;  // the bench's card after each event (phase 2)
    size_t frame_ready = 0, sync_errors = 0, oe_restarts = 0, pairs_read = 0;
    uint64_t words_read = 0, bad_words = 0;
};

void push_write(bench& b, uint32_t offset, uint32_t value) {
    rtl_test::emif_access a;
    a.k = rtl_test::emif_access::kind::write;
    a.addr = regs::ce2_base + offset;
    a.data = value;
    b.master.push(a);
}

void push_read(bench& b, uint32_t offset) {
    rtl_test::emif_access a;
    a.k = rtl_test::emif_access::kind::read;
    a.addr = regs::ce2_base + offset;
    b.master.push(a);
}

// Runs the bench for the window, recording every clock event's inputs.
recording record() {
    rtl_test::bench_options o;
    o.layout = rtl_test::small_layout();
    bench b(o);
    b.right.set_start_extra({o.layout.line_total});  // first OE start: one line late
    recording r;
    r.before_reset = icarus_ref::read_inputs(b.dut());
    // The DSP's configuration writes, queued (the bench's blocking helpers
    // would step edges this loop does not see).
    const rtl_test::sensor_layout& l = o.layout;
    struct reg_write {
        uint32_t offset;
        int value;
    };
    const reg_write layout[] = {{regs::h_start, l.h_start},
                                {regs::dark_cols_left, l.dark_left},
                                {regs::border_cols_left, l.border_left},
                                {regs::active_cols, l.active_cols},
                                {regs::border_cols_right, l.border_right},
                                {regs::dark_cols_right, l.dark_right},
                                {regs::line_total, l.line_total},
                                {regs::v_start, l.v_start},
                                {regs::dark_rows_top, l.dark_top},
                                {regs::border_rows_top, l.border_top},
                                {regs::active_rows, l.active_rows},
                                {regs::border_rows_bottom, l.border_bottom},
                                {regs::dark_rows_bottom, l.dark_bottom},
                                {regs::frame_lines, l.frame_lines},
                                {regs::oe_low_cycles, 60},
                                {regs::start_timeout, 100}};
    for (const reg_write& w : layout) push_write(b, w.offset, static_cast<uint32_t>(w.value));
    push_write(b, regs::ctrl, regs::ctrl_enable_mask);
    b.reader_enabled = true;
    bool status_read = false;
    r.events.reserve(static_cast<size_t>(window_ticks / 150));
    while (b.now() + b.opt.eclk_ticks < static_cast<uint64_t>(window_ticks)) {
        if (!status_read && b.now() > static_cast<uint64_t>(window_ticks) * 3 / 4) {
            for (uint32_t reg : {regs::status, regs::verdict, regs::pairs_ok, regs::retries})
                push_read(b, reg);
            status_read = true;
        }
        const uint64_t p0 = b.pclk_edges(), e0 = b.eclk_edges();
        b.step();
        clock_event e;
        e.tick = static_cast<simtime::ticks>(b.now());
        e.edges = static_cast<uint8_t>((b.pclk_edges() != p0 ? icarus_ref::edge_pclk : 0) |
                                       (b.eclk_edges() != e0 ? icarus_ref::edge_eclk : 0));
        e.in = icarus_ref::read_inputs(b.dut());
        r.events.push_back(e);
        r.outputs.push_back(icarus_ref::format_outputs(icarus_ref::read_outputs(b.dut())));
    }
    r.frame_ready = b.int4.rise_ticks.size();
    r.sync_errors = b.int5.rise_ticks.size();
    r.oe_restarts = b.oe_fall_edges.size();
    r.pairs_read = b.pairs.size();
    r.words_read = b.words_read;
    for (const auto& p : b.pairs) r.bad_words += p.bad_words;
    return r;
}

std::vector<std::string> read_lines(const std::string& path) {
    std::vector<std::string> lines;
    std::ifstream in(path);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

// Index of the first differing line (SIZE_MAX if none), printed.
size_t first_difference(const std::vector<std::string>& a, const std::vector<std::string>& b,
                        const std::vector<clock_event>& events, const char* what) {
    const size_t n = std::min(a.size(), b.size());
    for (size_t i = 0; i < n; ++i) {
        if (a[i] != b[i]) {
            std::printf("%s: first difference at event %zu (tick %lld):\n  %s\n  %s\n", what, i,
                        static_cast<long long>(events[i].tick), a[i].c_str(), b[i].c_str());
            return i;
        }
    }
    if (a.size() != b.size()) std::printf("%s: %zu lines against %zu\n", what, a.size(), b.size());
    return a.size() == b.size() ? SIZE_MAX : n;
}

TEST(IcarusReference, SameCardOutputsAsTheVerilatedCardForTheSameStimulus) {
    const auto t0 = std::chrono::steady_clock::now();
    const recording r = record();
    const double record_s = wall_since(t0);
    // The window exercises the sync check, the OE restart, the FIFOs and the EMIF slave.
    EXPECT_GE(r.sync_errors, 1u);
    EXPECT_GE(r.oe_restarts, 1u);
    EXPECT_GE(r.frame_ready, 3u);
    EXPECT_GE(r.words_read, 2000u);
    EXPECT_EQ(r.bad_words, 0u);

    char dir_template[] = "/tmp/icarus_reference_XXXXXX";
    ASSERT_NE(mkdtemp(dir_template), nullptr);
    const std::string dir = dir_template;
    const std::string stimulus = dir + "/stimulus.txt", outputs = dir + "/outputs.txt",
                      vvp_file = dir + "/card_replay.vvp", log = dir + "/log.txt";
    ASSERT_TRUE(icarus_ref::write_stimulus(stimulus, r.before_reset, r.events));

    // The verilated card replaying the file's stimulus.
    const auto t1 = std::chrono::steady_clock::now();
    std::vector<std::string> verilated;
    {
        VerilatedContext context;
        Vcard card(&context, "card");
        verilated = icarus_ref::replay(card, r.before_reset, r.events);
        card.final();
    }
    const double verilator_s = wall_since(t1);
    // The recording is complete: the replay's phase-2 outputs are the bench's.
    std::vector<std::string> replay_phase2;
    for (const std::string& line : verilated)
        replay_phase2.push_back(line.substr(line.size() / 2 + 1));
    EXPECT_EQ(first_difference(r.outputs, replay_phase2, r.events, "bench vs replay"), SIZE_MAX);

    // Icarus: compile the card RTL with the testbench, replay.
    const std::string rtl = repo_root() + "/rtl";
    const std::string compile = "iverilog -g2012 -I" + rtl + " -s card_replay_tb -o " + vvp_file +
                                " " + repo_root() + "/tests/rtl/icarus/card_replay_tb.v " + rtl +
                                "/*.v > " + log + " 2>&1";
    const auto t2 = std::chrono::steady_clock::now();
    ASSERT_EQ(std::system(compile.c_str()), 0) << compile << " (see " << log << ")";
    const double compile_s = wall_since(t2);
    const std::string run = "vvp -n " + vvp_file + " +stimulus=" + stimulus +
                            " +outputs=" + outputs + " >> " + log + " 2>&1";
    const auto t3 = std::chrono::steady_clock::now();
    ASSERT_EQ(std::system(run.c_str()), 0) << run;
    const double icarus_s = wall_since(t3);
    const std::vector<std::string> icarus = read_lines(outputs);

    const size_t first = first_difference(verilated, icarus, r.events, "verilated vs icarus");
    EXPECT_EQ(first, SIZE_MAX);
    EXPECT_EQ(icarus.size(), r.events.size());

    // The comparison sees a one-pixel difference: the verilated card fed the
    // same stimulus with one right-sensor pixel inverted in the middle of a
    // line at 1 ms differs from Icarus's outputs.
    std::vector<clock_event> changed = r.events;
    size_t line_run = 0, flipped = SIZE_MAX;
    for (size_t i = 0; i < changed.size() && flipped == SIZE_MAX; ++i) {
        if (!(changed[i].edges & icarus_ref::edge_pclk)) continue;  // sensor pins change here
        const bool pixel = changed[i].in.r_href && changed[i].in.r_valid;
        line_run = pixel ? line_run + 1 : 0;
        if (changed[i].tick > 1000 * ticks_per_us && line_run == 16) {
            // The pixel stays on the pins until the next pixel clock event.
            const uint8_t inverted = static_cast<uint8_t>(~changed[i].in.r_data);
            for (size_t k = i;
                 k == i || (k < changed.size() && !(changed[k].edges & icarus_ref::edge_pclk)); ++k)
                changed[k].in.r_data = inverted;
            flipped = i;
        }
    }
    ASSERT_NE(flipped, SIZE_MAX);
    std::vector<std::string> verilated_changed;
    {
        VerilatedContext context;
        Vcard card(&context, "card");
        verilated_changed = icarus_ref::replay(card, r.before_reset, changed);
        card.final();
    }
    const size_t changed_first = first_difference(verilated_changed, icarus, changed,
                                                  "negative control (one pixel inverted)");
    EXPECT_NE(changed_first, SIZE_MAX);

    // How much the outputs did: changes of the phase-2 output line.
    size_t output_changes = 0;
    for (size_t i = 1; i < r.outputs.size(); ++i)
        output_changes += r.outputs[i] != r.outputs[i - 1];
    EXPECT_GT(output_changes, 1000u);

    const double simulated_us = static_cast<double>(r.events.back().tick) / ticks_per_us;
    std::printf(
        "window %.0f us from reset: %zu clock events, %zu output changes; FRAME_READY %zu, "
        "SYNC_ERROR %zu, OE restarts %zu, pairs read %zu (%llu words)\n"
        "icarus: compile %.2f s, replay %.2f s wall = %.1f simulated us per wall s\n"
        "verilated card replay: %.3f s wall = %.0f simulated us per wall s (%.0fx icarus); "
        "recording (bench) %.2f s\n",
        simulated_us, r.events.size(), output_changes, r.frame_ready, r.sync_errors, r.oe_restarts,
        r.pairs_read, static_cast<unsigned long long>(r.words_read), compile_s, icarus_s,
        simulated_us / icarus_s, verilator_s, simulated_us / verilator_s, icarus_s / verilator_s,
        record_s);
    RecordProperty("events", std::to_string(r.events.size()));
    RecordProperty("icarus_us_per_wall_s", std::to_string(simulated_us / icarus_s));
    RecordProperty("verilator_us_per_wall_s", std::to_string(simulated_us / verilator_s));
    if (first == SIZE_MAX && !HasFailure()) std::filesystem::remove_all(dir);
}

}  // namespace
