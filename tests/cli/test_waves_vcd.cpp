// `stereosim run --vcd` as a user runs it (docs/waveforms.md): the VCD parsed
// here by a plain parser, the GTKWave save file and translate filters beside
// it, and the option errors. The expected figures come from the sensor
// profile (docs/sensor.md), the DSK v1 CECTL value decoded here from the C64x
// field layout (docs/hardware-facts.md section 3) and the tick arithmetic of
// model/time/ticks.h, not from the writer.
#include <gtest/gtest.h>
#include <stdlib.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "dsp/card_regs.h"
#include "dsp/plugin/reference_firmware.h"
#include "model/sensor/profile.h"
#include "tb/app/output/gtkw_writer.h"
#include "tb/app/output/waves_writer.h"
#include "tb/platform/island/pin_trace.h"
#include "tests/support/shell.h"
#include "tests/support/vcd_reader.h"

namespace {

using simtime::ticks;

using testsupport::command_result;
using testsupport::read_text;

command_result run_stereosim(const std::string& args) {
    return testsupport::run_command("SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1 " STEREOSIM_BINARY " " +
                                    args);
}

std::string temp_dir() {
    return testsupport::temp_dir("stereosim-test-waves");
}

bool exists(const std::string& path) {
    return testsupport::file_exists(path);
}

using testsupport::vcd_change;
using testsupport::vcd_file;

vcd_file parse_vcd(const std::string& path) {
    return testsupport::read_vcd(path);
}

// 1 tick = 1/18 ns; the VCD holds each tick rounded to fs once.
ticks tick_of_fs(int64_t fs) {
    return (fs * simtime::ticks_per_ns + simtime::fs_per_ns / 2) / simtime::fs_per_ns;
}

std::string full_name(platform::trace_pin pin) {
    const platform::trace_signal& s = platform::trace_pin_signal(pin);
    std::string n = "platform." + s.scope + "." + s.name;
    if (s.width > 1) n += "[" + std::to_string(s.width - 1) + ":0]";
    return n;
}

// Low pulses of a 1-bit signal: (tick of the fall, width in ticks).
std::vector<std::pair<ticks, ticks>> low_pulses(const std::vector<vcd_change>& h) {
    std::vector<std::pair<ticks, ticks>> pulses;
    for (size_t i = 0; i + 1 < h.size(); ++i) {
        if (h[i].value == "0" && h[i + 1].value == "1")
            pulses.push_back({tick_of_fs(h[i].fs), tick_of_fs(h[i + 1].fs) - tick_of_fs(h[i].fs)});
    }
    return pulses;
}

std::vector<std::pair<ticks, ticks>> high_pulses(const std::vector<vcd_change>& h) {
    std::vector<std::pair<ticks, ticks>> pulses;
    for (size_t i = 0; i + 1 < h.size(); ++i) {
        if (h[i].value == "1" && h[i + 1].value == "0")
            pulses.push_back({tick_of_fs(h[i].fs), tick_of_fs(h[i + 1].fs) - tick_of_fs(h[i].fs)});
    }
    return pulses;
}

// The value of a signal at tick t (last change at or before it).
std::string value_at(const std::vector<vcd_change>& h, ticks t) {
    std::string v = "x";
    for (const vcd_change& c : h) {
        if (tick_of_fs(c.fs) > t) break;
        v = c.value;
    }
    return v;
}

// C64x EMIF CECTL fields (SPRU266, docs/hardware-facts.md section 3):
// WRSETUP 31:28, WRSTRB 27:22, WRHLD 21:20, RDSETUP 19:16, TA 15:14,
// RDSTRB 13:8, MTYPE 7:4, RDHLD 2:0 -- in ECLKOUT cycles.
struct cectl_fields {
    int ws, wst, wh, rs, rst, rh;
};
cectl_fields decode(uint32_t v) {
    return {static_cast<int>(v >> 28 & 0xF), static_cast<int>(v >> 22 & 0x3F),
            static_cast<int>(v >> 20 & 0x3), static_cast<int>(v >> 16 & 0xF),
            static_cast<int>(v >> 8 & 0x3F), static_cast<int>(v & 0x7)};
}

constexpr ticks eclk_v1 = simtime::emif_100mhz_period;  // DSK v1: 100 MHz ECLKOUT

// The gtkw's lines that name a signal (everything but directives and groups).
std::vector<std::string> gtkw_signals(const std::string& text) {
    std::vector<std::string> names;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty()) continue;
        const char c = line[0];
        if (c == '[' || c == '@' || c == '-' || c == '^' || c == '*') continue;
        names.push_back(line);
    }
    return names;
}

}  // namespace

// One run of three periods, the window 47.5..49.5 ms: the last active lines
// of the first in-step frame, its FRAME_READY (49.24 ms), the EDMA's first
// capture bursts on CE3 and a register read on CE2.
TEST(waves_vcd, window_around_first_frame_ready) {
    const std::string dir = temp_dir();
    ASSERT_FALSE(dir.empty());
    const command_result run =
        run_stereosim("run --frames 3 --vcd --vcd-from 47.5 --vcd-to 49.5 --quiet --out " + dir);
    ASSERT_LE(run.exit_code, 1) << run.output;  // 0 within budget, 1 over: both results
    const std::string vcd_path = dir + "/waves/default.vcd";
    ASSERT_TRUE(exists(vcd_path)) << run.output;
    const vcd_file v = parse_vcd(vcd_path);

    // ---- every signal, one timeline, the window's start dumped
    EXPECT_EQ(v.timescale, "1fs");
    for (int i = 0; i < platform::trace_pin_count; ++i) {
        const std::string name = full_name(static_cast<platform::trace_pin>(i));
        ASSERT_TRUE(v.code_of.count(name)) << name;
        EXPECT_TRUE(v.first.count(v.code_of.at(name))) << name << " not at the window start";
    }
    const ticks from = 47500000 * simtime::ticks_per_ns, to = 49500000 * simtime::ticks_per_ns;
    EXPECT_EQ(v.first_fs, simtime::to_fs(from));
    EXPECT_TRUE(v.times_increase);
    EXPECT_EQ(v.last_fs, simtime::to_fs(to));
    std::printf("VCD: %zu signals, %lld..%lld fs, %zu bytes\n", v.code_of.size(),
                static_cast<long long>(v.first_fs), static_cast<long long>(v.last_fs),
                read_text(vcd_path).size());

    // ---- sensor L: PCLK period and HREF width against the profile (docs/sensor.md)
    const sensor::sensor_profile profile = sensor::default_profile();
    const ticks pclk = profile.pclk_period().num / profile.pclk_period().den;
    ASSERT_EQ(profile.pclk_period().den, 1);
    const auto pclk_high = high_pulses(v.history("platform.sensor_L.PCLK"));
    ASSERT_GT(pclk_high.size(), 30000u);  // 2 ms at 17.14 MHz: 34,285 clocks
    std::set<ticks> periods;
    for (size_t i = 1; i < pclk_high.size(); ++i)
        periods.insert(pclk_high[i].first - pclk_high[i - 1].first);
    EXPECT_EQ(periods, std::set<ticks>{pclk});
    // Whole pulses only: one that is high at the window start is cut.
    std::vector<std::pair<ticks, ticks>> href;
    for (const auto& p : high_pulses(v.history("platform.sensor_L.HREF")))
        if (p.first > from) href.push_back(p);
    ASSERT_GE(href.size(), 20u);
    std::set<ticks> href_widths, line_periods;
    for (size_t i = 0; i < href.size(); ++i) {
        href_widths.insert(href[i].second);
        if (i > 0) line_periods.insert(href[i].first - href[i - 1].first);
    }
    EXPECT_EQ(href_widths, std::set<ticks>{profile.readout_cols() * pclk});
    EXPECT_EQ(line_periods, std::set<ticks>{profile.line_pclks * pclk});
    std::printf(
        "sensor L: %zu PCLK periods all %lld ticks (%.3f ns); %zu HREF pulses all %lld "
        "ticks = %d pclk; line %lld ticks\n",
        pclk_high.size() - 1, static_cast<long long>(*periods.begin()),
        static_cast<double>(*periods.begin()) / 18.0, href.size(),
        static_cast<long long>(*href_widths.begin()), profile.readout_cols(),
        static_cast<long long>(*line_periods.begin()));

    // ---- EMIF: ECLKOUT, and the read strobes on the card's CE spaces = CECTL
    const auto eclk_high = high_pulses(v.history("platform.emif.ECLKOUT"));
    std::set<ticks> eclk_periods;
    for (size_t i = 1; i < eclk_high.size(); ++i)
        eclk_periods.insert(eclk_high[i].first - eclk_high[i - 1].first);
    EXPECT_EQ(eclk_periods, std::set<ticks>{eclk_v1});
    const cectl_fields f = decode(dsp::card_regs::cectl_v1);
    ASSERT_EQ(f.rst, 10);  // 0x22A28A22: RS 2 RST 10 RH 2 (docs/emif.md)
    const auto& ce2 = v.history("platform.emif.CE2_n");
    const auto& ce3 = v.history("platform.emif.CE3_n");
    const auto are = low_pulses(v.history("platform.emif.ARE_n"));
    int on_ce2 = 0, on_ce3 = 0;
    std::set<ticks> are_widths;
    for (const auto& p : are) {
        const bool c2 = value_at(ce2, p.first) == "0", c3 = value_at(ce3, p.first) == "0";
        if (!c2 && !c3) continue;
        on_ce2 += c2;
        on_ce3 += c3;
        are_widths.insert(p.second);
    }
    EXPECT_GE(on_ce3, 100);
    EXPECT_GE(on_ce2, 1);
    EXPECT_EQ(are_widths, std::set<ticks>{f.rst * eclk_v1});
    // Setup: CE3 falls RS cycles before the first ARE of a burst; between the
    // words of a burst ARE stays high RH + RS cycles.
    const auto ce3_low = low_pulses(ce3);
    ASSERT_FALSE(ce3_low.empty());
    ticks first_are = -1;
    for (const auto& p : are)
        if (p.first >= ce3_low[0].first) {
            first_are = p.first;
            break;
        }
    EXPECT_EQ(first_are - ce3_low[0].first, f.rs * eclk_v1);
    // (Longer gaps: the bus served a higher-priority requester between words.)
    std::map<ticks, int> gaps;
    const auto are_high = high_pulses(v.history("platform.emif.ARE_n"));
    for (const auto& p : are_high)
        if (value_at(ce3, p.first) == "0" && value_at(ce3, p.first + p.second) == "0")
            ++gaps[p.second];
    ASSERT_FALSE(gaps.empty());
    EXPECT_EQ(gaps.begin()->first, (f.rh + f.rs) * eclk_v1);  // the shortest
    EXPECT_GT(gaps.begin()->second, on_ce3 * 9 / 10);         // and by far the most common
    std::printf("ARE high between CE3 words: %d x %lld ticks, %zu longer gaps\n",
                gaps.begin()->second, static_cast<long long>(gaps.begin()->first),
                static_cast<size_t>(on_ce3 - gaps.begin()->second));
    std::printf(
        "EMIF: ECLK %lld ticks; %d reads on CE3, %d on CE2, ARE low %lld ticks = %d ECLK "
        "(CECTL RST %d), setup %lld ticks, ARE high inside a burst %lld ticks\n",
        static_cast<long long>(eclk_v1), on_ce3, on_ce2,
        static_cast<long long>(*are_widths.begin()),
        static_cast<int>(*are_widths.begin() / eclk_v1), f.rst,
        static_cast<long long>(first_are - ce3_low[0].first),
        static_cast<long long>(gaps.begin()->first));

    // ---- the card and the firmware on the same timeline
    const auto int4 = high_pulses(v.history("platform.card.EXT_INT4"));
    ASSERT_EQ(int4.size(), 1u);                  // FRAME_READY of pair 1 at 49.24 ms
    EXPECT_LT(int4[0].first, ce3_low[0].first);  // the EDMA reads after it
    EXPECT_EQ(value_at(v.history("platform.card.sync_check.oe_state[2:0]"), int4[0].first),
              "11");  // RUN
    // A declared stage (the reference's 0..6) or idle.
    for (const vcd_change& c : v.history("platform.firmware.stage[3:0]")) {
        const int stage = std::stoi(c.value, nullptr, 2);
        EXPECT_TRUE(stage <= 6 || stage == static_cast<int>(platform::stage_idle)) << stage;
    }
    // ED on the bus is the card's while it drives a read (two-state: 0
    // while nobody drives it, waves_writer.h).
    const auto& ed = v.history("platform.emif.ED[31:0]");
    const auto& card_ed = v.history("platform.card.emif_slave.ED[31:0]");
    const auto& card_ed_oe = v.history("platform.card.emif_slave.ED_OE");
    EXPECT_EQ(value_at(card_ed_oe, from), "0");
    EXPECT_EQ(value_at(ed, from), "0");
    int reads_seen = 0;
    for (size_t i = are.size() / 2; i < are.size() / 2 + 20 && i < are.size(); ++i) {
        const ticks end_of_strobe = are[i].first + f.rst * eclk_v1 - 1;
        if (value_at(ce3, end_of_strobe) != "0") continue;
        EXPECT_EQ(value_at(card_ed_oe, end_of_strobe), "1");
        EXPECT_EQ(value_at(ed, end_of_strobe), value_at(card_ed, end_of_strobe));
        ++reads_seen;
    }
    EXPECT_GT(reads_seen, 10);

    // ---- the GTKWave save file names only signals of the VCD, in the nine groups
    const std::string gtkw = read_text(dir + "/waves/default.gtkw");
    ASSERT_FALSE(gtkw.empty());
    const std::vector<std::string> named = gtkw_signals(gtkw);
    // Every traced pin, the fault marker (waves_writer.h) and nine of the
    // card's RTL signals, in nine groups.
    EXPECT_EQ(named.size(), static_cast<size_t>(platform::trace_pin_count) + 1 + 9);
    for (const std::string& n : named) EXPECT_TRUE(v.code_of.count(n)) << n << " not in the VCD";
    for (const char* group : {"sensor L", "sensor R", "sync check", "FIFOs", "card RTL", "EMIF",
                              "interrupts", "firmware stage and state", "faults"})
        EXPECT_NE(gtkw.find(std::string("\n-") + group + "\n"), std::string::npos) << group;
    EXPECT_NE(gtkw.find("[dumpfile] \"default.vcd\""), std::string::npos);  // relative
    // Filters: relative names of files beside the VCD, "value name" lines.
    std::istringstream lines(gtkw);
    std::string line;
    int filters = 0;
    while (std::getline(lines, line)) {
        if (line[0] != '^') continue;
        const std::string file = line.substr(line.find(' ') + 1);
        EXPECT_EQ(file.find('/'), std::string::npos) << file;
        const std::string text = read_text(dir + "/waves/" + file);
        EXPECT_FALSE(text.empty()) << file;
        ++filters;
    }
    // oe_state (pin trace and RTL), causes, verdict, register, taken, stage, state, fault
    EXPECT_EQ(filters, 9);
    // The translate filters and the template in the repo's waves/ are what a run writes.
    for (const output::translate_filter& f :
         output::translate_filters(dsp::plugin::reference_firmware())) {
        EXPECT_EQ(read_text(dir + "/waves/" + f.file_name), f.text) << f.file_name;
        EXPECT_EQ(read_text(std::string(STEREOSIM_SOURCE_DIR) + "/waves/" + f.file_name), f.text)
            << "waves/" << f.file_name << " differs from what a run writes";
    }
    std::printf("gtkw: %zu signals, %d filtered traces, all in the VCD\n", named.size(), filters);
    // Register names come from the card's register map.
    const std::string regs = read_text(dir + "/waves/card_register.txt");
    EXPECT_NE(regs.find("\n" + std::to_string(dsp::card_regs::verdict / 4) + " VERDICT\n"),
              std::string::npos);
}

// The committed template waves/stereosim.gtkw is the save file of a full
// run named "stereosim" (view from 0, 10 us), the fault marker included.
TEST(waves_vcd, committed_template_matches_the_writer) {
    output::waves_writer vcd(output::waves_format::vcd, platform::tick_window{0, 1});
    for (int i = 0; i < platform::trace_pin_count; ++i)
        vcd.declare(platform::trace_pin_signal(static_cast<platform::trace_pin>(i)));
    vcd.declare(output::fault_marker_signal());  // as the file does, last
    const std::string text = output::gtkw_text("stereosim.vcd", vcd.signals(), 0, 10 * 18000);
    EXPECT_EQ(read_text(std::string(STEREOSIM_SOURCE_DIR) + "/waves/stereosim.gtkw"), text);
}

// The boot window (first 50 us of a one-period run): the firmware configures
// the card with register writes on CE2; the write strobe is CECTL's WST.
TEST(waves_vcd, boot_window_register_writes) {
    const std::string dir = temp_dir();
    const command_result run = run_stereosim(
        "run --frames 1 --vcd --vcd-from 0 --vcd-to 0.05 --vcd-scope emif,card --quiet --out " +
        dir);
    ASSERT_LE(run.exit_code, 1) << run.output;
    const vcd_file v = parse_vcd(dir + "/waves/default.vcd");
    EXPECT_FALSE(v.code_of.count("platform.sensor_L.PCLK"));  // not in the scope
    EXPECT_FALSE(v.code_of.count("platform.firmware.stage[3:0]"));
    const cectl_fields f = decode(dsp::card_regs::cectl_v1);
    const auto& ce2 = v.history("platform.emif.CE2_n");
    const auto awe = low_pulses(v.history("platform.emif.AWE_n"));
    const auto& reg = v.history("platform.card.emif_slave.register[5:0]");
    std::set<ticks> widths;
    std::set<int> registers;
    for (const auto& p : awe) {
        if (value_at(ce2, p.first) != "0") continue;
        widths.insert(p.second);
        registers.insert(std::stoi(value_at(reg, p.first), nullptr, 2));
    }
    ASSERT_GE(registers.size(), 3u);
    EXPECT_EQ(widths, std::set<ticks>{f.wst * eclk_v1});
    EXPECT_TRUE(registers.count(dsp::card_regs::ctrl / 4));  // ENABLE
    const std::string names = read_text(dir + "/waves/card_register.txt");
    std::string written;
    for (int r : registers) {
        const size_t at = names.find("\n" + std::to_string(r) + " ");
        ASSERT_NE(at, std::string::npos) << r;
        written += names.substr(at + 1, names.find('\n', at + 1) - at - 1) + "; ";
    }
    std::printf("boot: %zu CE2 writes, AWE low %lld ticks = %d ECLK (WST %d): %s\n", awe.size(),
                static_cast<long long>(*widths.begin()),
                static_cast<int>(*widths.begin() / eclk_v1), f.wst, written.c_str());
}

// Bad windows: one line, exit 2, nothing written.
TEST(waves_vcd, bad_window_is_a_one_line_error) {
    const struct {
        const char* args;
        const char* says;
    } cases[] = {
        {"--vcd --vcd-from 5 --vcd-to 5", "before"},
        {"--vcd --vcd-from 6 --vcd-to 5", "before"},
        {"--vcd --vcd-from -1 --vcd-to 5", "negative"},
        {"--vcd --vcd-from 20 --vcd-to 30", "beyond the run"},
        {"--vcd --vcd-scope sensors,pins", "unknown scope"},
        {"--vcd-from 1 --vcd-to 2", "need --waves (or --vcd)"},
        {"--waves gif", "unknown format 'gif'"},
        {"--waves fst --vcd", "--vcd is --waves vcd"},
        {"--waves fst --waves-from 20 --waves-to 30", "beyond the run"},
    };
    for (const auto& c : cases) {
        const std::string dir = temp_dir();
        const command_result r =
            run_stereosim(std::string("run --frames 1 ") + c.args + " --out " + dir + "/out");
        EXPECT_EQ(r.exit_code, 2) << c.args << ": " << r.output;
        EXPECT_NE(r.output.find(c.says), std::string::npos) << r.output;
        EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
        EXPECT_FALSE(exists(dir + "/out/report.json"));
        EXPECT_FALSE(exists(dir + "/out/waves"));
    }
    const command_result r = run_stereosim("run --frames 1 --vcd");
    EXPECT_EQ(r.exit_code, 2);
    EXPECT_NE(r.output.find("--out"), std::string::npos) << r.output;
}
