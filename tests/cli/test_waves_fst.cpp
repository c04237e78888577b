// `stereosim run --waves fst` as a user runs it (docs/waveforms.md): the FST
// read back by GTKWave's own converter (fst2vcd, Debian's gtkwave package, not
// Verilator's writer), compared change by change with the VCD of the same
// window, and the card's RTL internals found in it and moving as the RTL
// says they must (sync_check's counters at the pixel clock, the FIFO's
// pointers while the EDMA reads, the OE controller at the start).
#include <gtest/gtest.h>

#include <stdlib.h>
#include <sys/wait.h>
#include <unistd.h>
#include <filesystem>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "model/sensor/profile.h"
#include "model/time/ticks.h"
#include "tests/support/shell.h"
#include "tests/support/vcd_reader.h"

namespace {

using simtime::ticks;
using testsupport::vcd_file;

using testsupport::read_text;

int run(const std::string& command) {
    return testsupport::run_command(command).exit_code;
}

long file_size(const std::string& path) {
    std::ifstream in(path, std::ios::binary | std::ios::ate);
    return in ? static_cast<long>(in.tellg()) : -1;
}

// The run's FST through fst2vcd.
vcd_file read_fst(const std::string& fst) {
    const std::string vcd = fst + ".fst2vcd.vcd";
    EXPECT_EQ(run("fst2vcd -f " + fst + " -o " + vcd), 0) << "fst2vcd (gtkwave) failed";
    return testsupport::read_vcd(vcd);
}

// A window of the default scenario in `format` into a new folder.
std::string waves_run(const std::string& format, const std::string& args) {
    const std::string dir = testsupport::temp_dir("stereosim-test-waves-fst");
    const testsupport::command_result r =
        testsupport::run_command("SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1 " STEREOSIM_BINARY " run " +
                                 args + " --waves " + format + " --quiet --out " + dir);
    // 0 within budget, 1 over, 4 a fault run's contract broken: finished runs.
    EXPECT_TRUE(r.exit_code <= 1 || r.exit_code == 4) << r.output;
    return dir;
}

size_t changes_of(const vcd_file& v, const std::string& name) {
    return v.of(name).size();
}

const char* const check = "platform.card.card_top.u_capture.u_check.";
const char* const fifo_l = "platform.card.card_top.u_fifo_l.";

}  // namespace

// The end of the first in-step frame and its FRAME_READY (48-50 ms of 3 periods): the same window
// as FST and as VCD holds the same signals with the same changes; the card's internals are there
// and move.
TEST(waves_fst, same_changes_as_the_vcd_and_the_card_internals_move) {
    const std::string window = "--frames 3 --waves-from 48 --waves-to 50";
    const std::string fst_dir = waves_run("fst", window);
    const std::string vcd_dir = waves_run("vcd", window);
    const std::string fst = fst_dir + "/waves/default.fst";
    const vcd_file f = read_fst(fst);
    const vcd_file v = testsupport::read_vcd(vcd_dir + "/waves/default.vcd");
    ASSERT_TRUE(f.ok && v.ok);
    EXPECT_EQ(f.timescale, "1fs");
    EXPECT_TRUE(f.times_increase);

    // Signal by signal, change by change.
    ASSERT_EQ(f.code_of.size(), v.code_of.size());
    size_t compared = 0, changes = 0;
    for (const auto& named : v.code_of) {
        ASSERT_TRUE(f.code_of.count(named.first)) << named.first << " not in the FST";
        EXPECT_EQ(f.history(named.first), v.history(named.first)) << named.first;
        changes += v.of(named.first).size();
        ++compared;
    }
    EXPECT_GT(compared, 900u);  // the card's hierarchy and the pin trace's 42
    EXPECT_EQ(f.first_fs, simtime::to_fs(48 * 18000000LL));
    EXPECT_EQ(f.last_fs, simtime::to_fs(50 * 18000000LL));

    // sync_check counts columns at every pixel clock (17.14 MHz).
    const sensor::sensor_profile profile = sensor::default_profile();
    const ticks pclk = profile.pclk_period().num / profile.pclk_period().den;
    const size_t pclks_in_window = static_cast<size_t>(2 * 18000000 / pclk);
    EXPECT_GT(changes_of(f, std::string(check) + "col_q[15:0]"), pclks_in_window * 9 / 10);
    EXPECT_GE(changes_of(f, std::string(check) + "line_q[15:0]"), 20u);  // one per line
    // The FIFO: written while the frame's active lines come in (to ~48.5 ms),
    // read by the EDMA after FRAME_READY (49.24 ms).
    EXPECT_GT(changes_of(f, std::string(fifo_l) + "wr_ptr[17:0]"), 1000u);
    EXPECT_GT(changes_of(f, std::string(fifo_l) + "rd_ptr[17:0]"), 1000u);
    EXPECT_GT(changes_of(f, std::string(fifo_l) + "wgray_q[17:0]"), 1000u);
    const long fst_bytes = file_size(fst);
    const long vcd_bytes = file_size(vcd_dir + "/waves/default.vcd");
    EXPECT_LT(fst_bytes * 10, vcd_bytes);
    std::printf(
        "2 ms window: %zu signals, %zu changes, FST %ld bytes, VCD %ld bytes; col_q %zu, "
        "line_q %zu, FIFO L wr_ptr %zu rd_ptr %zu changes\n",
        compared, changes, fst_bytes, vcd_bytes, changes_of(f, std::string(check) + "col_q[15:0]"),
        changes_of(f, std::string(check) + "line_q[15:0]"),
        changes_of(f, std::string(fifo_l) + "wr_ptr[17:0]"),
        changes_of(f, std::string(fifo_l) + "rd_ptr[17:0]"));
}

// The start (0-2 ms of one period): the OE controller leaves IDLE when the
// firmware enables the card and reaches RUN at the first VSYNC.
TEST(waves_fst, oe_controller_moves_at_the_start) {
    const std::string dir = waves_run("fst", "--frames 1 --waves-from 0 --waves-to 2");
    const vcd_file f = read_fst(dir + "/waves/default.fst");
    const auto state = f.history("platform.card.card_top.u_capture.u_oe.state_q[2:0]");
    ASSERT_GE(state.size(), 3u);
    EXPECT_EQ(state.front().value, "0");  // IDLE
    EXPECT_EQ(state.back().value, "11");  // RUN (rtl/oe_control.v)
    // The same state as the pin trace's decoded copy.
    EXPECT_EQ(f.history("platform.card.sync_check.oe_state[2:0]"), state);
    std::printf("OE state: %zu values, RUN from %.3f us\n", state.size(),
                static_cast<double>(state.back().fs) / 1e9);
}

// The summary's waveform line gives the file's size as written (it had
// read the staged file after it was renamed: 0.0 MB).
TEST(waves_fst, summary_gives_the_file_size) {
    const std::string dir = testsupport::temp_dir("stereosim-test-waves-size");
    const testsupport::command_result r = testsupport::run_command(
        "SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1 " STEREOSIM_BINARY
        " run --frames 1 --waves-from 0 --waves-to 2 --waves fst --summary --out " +
        dir);
    EXPECT_LE(r.exit_code, 1) << r.output;
    const uint64_t bytes = std::filesystem::file_size(dir + "/waves/default.fst");
    char expected[64];
    if (bytes >= 1000000)
        std::snprintf(expected, sizeof expected, "%.1f MB", static_cast<double>(bytes) / 1e6);
    else
        std::snprintf(expected, sizeof expected, "%.0f kB", static_cast<double>(bytes) / 1e3);
    EXPECT_NE(r.output.find("waveform (fst): 0.000..2.000 ms, " + std::string(expected)),
              std::string::npos)
        << r.output;
    EXPECT_GT(bytes, 1000u);
}

// A fault's marker in the FST (merged through fstapi after the run) is at
// report.json's onset, as in the VCD (test_faults_vcd.cpp).
TEST(waves_fst, fault_marker_at_the_onset) {
    const std::string dir = waves_run(
        "fst",
        "--frames 4 --fault skew:sensor=R,lines=3@frame=2 --waves-from 24.5 --waves-to 25.5");
    const nlohmann::json report =
        nlohmann::json::parse(read_text(dir + "/report.json"), nullptr, false);
    ASSERT_TRUE(report.is_object());
    const double onset_ms = report["faults"][0]["onset_ms"].get<double>();
    const ticks onset = static_cast<ticks>(std::llround(onset_ms * 1e6 * simtime::ticks_per_ns));
    const vcd_file f = read_fst(dir + "/waves/default.fst");
    const auto& marker = f.of("platform.faults.kind[7:0]");
    ASSERT_EQ(marker.size(), 1u);
    EXPECT_EQ(marker[0].fs, simtime::to_fs(onset));
    EXPECT_EQ(marker[0].value, "1");  // 1 + fault_type::skew
    EXPECT_EQ(f.first.at(f.code_of.at("platform.faults.kind[7:0]")), "0");
}
