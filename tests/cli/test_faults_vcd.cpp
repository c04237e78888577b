// Every injected fault as a marker in the waveform (issue 7, docs/faults.md,
// docs/waveforms.md): `stereosim run --fault ... --vcd` as a user runs it.
// The VCD declares platform.faults.kind[7:0] (0 at the window start); at each fault's
// onset inside the window it becomes 1 + faults::fault_type. Checked against
// report.json's faults[].onset_ms (the same onset, a different output) and
// against the faulted sensor's own pins in the same VCD: the onset is the
// PCLK rise that starts the sensor's frame, VSYNC rises within that clock.
#include <gtest/gtest.h>
#include <stdlib.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "model/sensor/profile.h"
#include "model/time/ticks.h"
#include "tb/app/faults/fault_spec.h"
#include "tests/support/shell.h"
#include "tests/support/vcd_reader.h"

namespace {

using simtime::ticks;

using testsupport::read_text;

std::string run_stereosim(const std::string& args, int* exit_code) {
    const testsupport::command_result r = testsupport::run_command(
        "SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1 " STEREOSIM_BINARY " " + args);
    *exit_code = r.exit_code;
    return r.output;
}

std::string temp_dir() {
    return testsupport::temp_dir("stereosim-test-faults-vcd");
}

using testsupport::vcd_change;
using testsupport::vcd_file;

// 1 tick = 1/18 ns; the VCD holds each tick rounded to fs once (waves_writer.h).
ticks tick_of_fs(int64_t fs) {
    return (fs * simtime::ticks_per_ns + simtime::fs_per_ns / 2) / simtime::fs_per_ns;
}
ticks tick_of_ms(double ms) {
    return static_cast<ticks>(std::llround(ms * 1e6 * simtime::ticks_per_ns));
}

const char* const marker = "platform.faults.kind[7:0]";
// skew is fault_type 0: its code is 1 (0 means no fault).
const std::string skew_code = "1";

struct fault_run {
    int exit_code = -1;
    std::string output;
    nlohmann::json report;
    vcd_file vcd;
    std::string dir;
};

fault_run run_with(const std::string& faults, const std::string& window) {
    fault_run r;
    r.dir = temp_dir();
    r.output = run_stereosim(
        "run --frames 4 " + faults + " --vcd " + window + " --quiet --out " + r.dir, &r.exit_code);
    r.report = nlohmann::json::parse(read_text(r.dir + "/report.json"), nullptr, false);
    r.vcd = testsupport::read_vcd(r.dir + "/waves/default.vcd");
    return r;
}

// The marker is declared in every VCD, 8 bits, a unique code, 0 or `initial`
// at the window start.
void expect_declared(const vcd_file& v, const std::string& initial) {
    ASSERT_TRUE(v.code_of.count(marker)) << "no " << marker;
    EXPECT_EQ(v.width_of.at(marker), 8);
    // Its code is its own (Verilator's writer shares one code among signals
    // that always hold the same value).
    size_t sharing = 0;
    for (const auto& named : v.code_of) sharing += named.second == v.code_of.at(marker);
    EXPECT_EQ(sharing, 1u);
    ASSERT_TRUE(v.first.count(v.code_of.at(marker))) << marker << " not at the window start";
    EXPECT_EQ(v.first.at(v.code_of.at(marker)), initial);
    EXPECT_TRUE(v.times_increase);
}

}  // namespace

// A skew of sensor R at frame 2 (onset near 2 x 24.5 ms + start-up) inside
// the window 24.3..25.5 ms, a dropped line of sensor L at frame 3 after it.
TEST(faults_vcd, onset_in_the_window_is_one_change_at_the_onset_tick) {
    const fault_run r = run_with(
        "--fault skew:sensor=R,lines=3@frame=2 --fault drop-line:sensor=L,line=100@frame=3",
        "--vcd-from 24.3 --vcd-to 25.5");
    // 0 within budget, 1 over, 4 the contract broken (these runs are too short
    // for the recovery to be due): all finished runs.
    ASSERT_TRUE(r.exit_code <= 1 || r.exit_code == 4) << r.output;
    ASSERT_TRUE(r.report.is_object()) << r.output;
    ASSERT_EQ(r.report["faults"].size(), 2u);
    const nlohmann::json& skew = r.report["faults"][0];
    const nlohmann::json& drop = r.report["faults"][1];
    ASSERT_TRUE(skew["onset_ms"].is_number()) << skew.dump();
    ASSERT_TRUE(drop["onset_ms"].is_number()) << drop.dump();
    const double onset_ms = skew["onset_ms"].get<double>();
    const double drop_ms = drop["onset_ms"].get<double>();
    // The window was chosen from the frame timing; say so if that moved.
    ASSERT_GT(onset_ms, 24.3);
    ASSERT_LT(onset_ms, 25.5);
    ASSERT_GE(drop_ms, 25.5);  // outside the window: no change for it

    const vcd_file& v = r.vcd;
    expect_declared(v, "0");
    const std::vector<vcd_change>& h = v.of(marker);
    ASSERT_EQ(h.size(), 1u) << "the marker must change exactly once";
    const ticks onset = tick_of_ms(onset_ms);
    EXPECT_EQ(tick_of_fs(h[0].fs), onset);
    EXPECT_EQ(h[0].fs, simtime::to_fs(onset));
    EXPECT_EQ(h[0].value, skew_code);
    EXPECT_EQ(static_cast<int>(faults::fault_type::skew) + 1, 1);

    // The marker is where the skew first acts on a pin: the frame of both
    // sensors was due at the onset, and sensor L's VSYNC rises within that
    // clock, while R's idle clocks (3 lines = 2,400 pclk) hold its VSYNC back.
    const sensor::sensor_profile profile = sensor::default_profile();
    const ticks pclk = profile.pclk_period().num / profile.pclk_period().den;
    const auto first_rise = [&](const std::string& signal) {
        for (const vcd_change& c : v.of(signal))
            if (c.value == "1" && tick_of_fs(c.fs) >= onset) return tick_of_fs(c.fs);
        return ticks{-1};
    };
    const ticks l_vsync = first_rise("platform.sensor_L.VSYNC");
    const ticks r_vsync = first_rise("platform.sensor_R.VSYNC");
    ASSERT_GE(l_vsync, onset);
    EXPECT_LT(l_vsync - onset, pclk);
    ASSERT_GE(r_vsync, onset);
    EXPECT_EQ((r_vsync - l_vsync + pclk / 2) / pclk, 3 * profile.line_pclks);

    // The save file shows it through the filter that names the kinds, and
    // opens 2 us before it.
    const std::string gtkw = read_text(r.dir + "/waves/default.gtkw");
    EXPECT_NE(gtkw.find("[timestart] " + std::to_string(simtime::to_fs(onset - 2 * 18000)) + "\n"),
              std::string::npos)
        << gtkw.substr(0, 400);
    EXPECT_NE(gtkw.find("\n-faults\n@2024\n^"), std::string::npos);
    EXPECT_NE(gtkw.find(" fault_kind.txt\nplatform.faults.kind[7:0]\n"), std::string::npos);
    const std::string kinds = read_text(r.dir + "/waves/fault_kind.txt");
    EXPECT_NE(kinds.find("\n0 none\n"), std::string::npos);
    EXPECT_NE(kinds.find("\n" + std::to_string(std::stoi(skew_code, nullptr, 2)) + " skew\n"),
              std::string::npos);
    EXPECT_NE(kinds.find("\n2 drop-line\n"), std::string::npos);
    EXPECT_EQ(kinds, read_text(std::string(STEREOSIM_SOURCE_DIR) + "/waves/fault_kind.txt"))
        << "waves/fault_kind.txt differs from what a run writes";
    std::printf(
        "skew onset %.6f ms (report) = tick %lld = %lld fs; VCD marker change at %lld fs to %s "
        "(1 change); sensor_L VSYNC %lld ticks after it, sensor_R's %lld (PCLK %lld ticks); "
        "drop-line onset %.6f ms outside the window: no change\n",
        onset_ms, static_cast<long long>(onset), static_cast<long long>(simtime::to_fs(onset)),
        static_cast<long long>(h[0].fs), h[0].value.c_str(),
        static_cast<long long>(l_vsync - onset), static_cast<long long>(r_vsync - onset),
        static_cast<long long>(pclk), drop_ms);
}

// Without --fault the marker is declared and stays 0.
TEST(faults_vcd, clean_run_marker_stays_zero) {
    const fault_run r = run_with("", "--vcd-from 24.5 --vcd-to 25.5");
    ASSERT_TRUE(r.exit_code <= 1 || r.exit_code == 4) << r.output;
    ASSERT_TRUE(r.report.is_object()) << r.output;
    EXPECT_TRUE(r.report["faults"].empty());
    expect_declared(r.vcd, "0");
    EXPECT_TRUE(r.vcd.of(marker).empty());
    std::printf("clean run: %s declared, 0 at the window start, %zu changes\n", marker,
                r.vcd.of(marker).size());
}

// A fault whose onset precedes the window: no change inside it; the window
// starts with the kind in effect (the latest fault to act).
TEST(faults_vcd, onset_before_the_window_is_no_change) {
    const fault_run r = run_with("--fault skew:sensor=R,lines=3@frame=2",
                                 "--vcd-from 30 --vcd-to 30.2 --vcd-scope card");
    ASSERT_TRUE(r.exit_code <= 1 || r.exit_code == 4) << r.output;
    ASSERT_TRUE(r.report.is_object()) << r.output;
    ASSERT_EQ(r.report["faults"].size(), 1u);
    const double onset_ms = r.report["faults"][0]["onset_ms"].get<double>();
    ASSERT_LT(onset_ms, 30.0);
    expect_declared(r.vcd, skew_code);  // also with a --vcd-scope without firmware
    EXPECT_TRUE(r.vcd.of(marker).empty());
    std::printf("onset %.6f ms before the window 30..30.2 ms: window start %s, %zu changes\n",
                onset_ms, r.vcd.first.at(r.vcd.code_of.at(marker)).c_str(),
                r.vcd.of(marker).size());
}
