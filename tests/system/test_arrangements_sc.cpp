// The fast arrangement is cycle-accurate (docs/design-brief.md "How it is clocked";
// docs/arrangements.md): the same run in the literal pin-level arrangement
// (sensor_sc, verilator --sc card, emif_pins_sc, wired with sc_signals)
// gives the same pins and the same report.
//
// Per run the comparison covers: the canonical pin hash over every sensor,
// EMIF and card pin change with its tick (tb/platform/island/pin_hash.h), every such
// change of a 1 ms window compared one by one (the per-signal-group change
// lists; the first difference is printed), the VCD of that window as --vcd
// writes it (tb/app/output's writer) parsed and compared signal by signal, the
// timeline (pins and firmware) hash, and the printed report except the
// run-speed line and the island's sync count (the pin-level arrangement does
// not sync: it is SystemC). Every case runs until at least 2 3D outputs.
//
// One simulation per process: each arrangement runs in a forked child that
// writes its digest to a pipe; the two children run at once (both cores).
// A negative control proves the comparison can fail: the pin-level
// arrangement with the right sensor's HREF inverted for one pixel clock in
// the window (a fault given to that run only, from the test side) must differ.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "model/c6416/dsk_profile.h"
#include "tb/app/output/waves_writer.h"
#include "tb/platform/budget.h"
#include "tb/platform/platform.h"
#include "tb/platform/report.h"
#include "tb/platform/scoreboard.h"
#include "tests/support/vcd_reader.h"

namespace {

using platform::arrangement_kind;
using platform::pin_change;

constexpr simtime::ticks ticks_per_ms = 18000000;

struct digest {
    uint64_t pin_hash = 0;
    uint64_t pin_changes = 0;
    uint64_t timeline_hash = 0;
    uint64_t points_3d = 0;
    double wall_s = 0.0;
    std::string report;              // normalised (see normalise)
    std::vector<pin_change> window;  // the logged window's changes
};

// The report without what depends on the host or on how the arrangement
// syncs: the run-speed line and the island's sync counts.
std::string normalise(const std::string& report) {
    std::istringstream in(report);
    std::string line, out;
    const std::regex syncs("[0-9]+ syncs");
    while (std::getline(in, line)) {
        if (line.rfind("run:", 0) == 0) continue;
        out += std::regex_replace(line, syncs, "# syncs") + "\n";
    }
    return out;
}

// `vcd`: where the window's VCD goes (tb/app/output's writer, as --waves vcd writes it:
// the traced card's whole hierarchy and the pin trace).
digest simulate(platform::platform_config config, simtime::ticks window_from,
                simtime::ticks window_to, const std::string& vcd) {
    const platform::tick_window window{window_from, window_to};
    output::waves_writer writer(output::waves_format::vcd, window);
    if (!writer.open(vcd)) _exit(4);
    config.trace = &writer;
    config.trace_window = window;
    platform::platform_top top(config);
    top.cycle_island().log_pin_changes(window_from, window_to);
    const auto wall0 = std::chrono::steady_clock::now();
    top.run();
    // The writer saw every change in tick order (a source bug otherwise).
    if (writer.out_of_order() != 0 || !writer.ok()) _exit(5);
    digest d;
    d.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
    const platform::scoreboard_report score = platform::score(top);
    const platform::budget_report budget = platform::check_budget(top, score);
    std::FILE* f = std::tmpfile();
    platform::print_report(f, top, score, budget);
    std::fflush(f);
    std::rewind(f);
    char buffer[4096];
    std::string text;
    for (size_t n; (n = std::fread(buffer, 1, sizeof buffer, f)) > 0;) text.append(buffer, n);
    std::fclose(f);
    d.report = normalise(text);
    d.pin_hash = top.cycle_island().pin_hash();
    d.pin_changes = top.cycle_island().stats().pin_changes;
    d.timeline_hash = top.events().hash();
    for (const platform::fw_result& r : top.probe().results()) d.points_3d += r.out.has_point;
    d.window = top.cycle_island().logged_pin_changes();
    return d;
}

// ---- a digest through a pipe
// ---------------------------------------------------------------
void put(std::string& s, const void* p, size_t n) {
    s.append(static_cast<const char*>(p), n);
}
template <typename T>
void put(std::string& s, const T& v) {
    put(s, &v, sizeof v);
}

std::string serialise(const digest& d) {
    std::string s;
    put(s, d.pin_hash);
    put(s, d.pin_changes);
    put(s, d.timeline_hash);
    put(s, d.points_3d);
    put(s, d.wall_s);
    put(s, static_cast<uint64_t>(d.report.size()));
    s += d.report;
    put(s, static_cast<uint64_t>(d.window.size()));
    for (const pin_change& c : d.window) put(s, c);
    return s;
}

bool deserialise(const std::string& s, digest* d) {
    size_t at = 0;
    const auto get = [&](void* p, size_t n) {
        if (at + n > s.size()) return false;
        std::memcpy(p, s.data() + at, n);
        at += n;
        return true;
    };
    uint64_t n = 0;
    if (!get(&d->pin_hash, 8) || !get(&d->pin_changes, 8) || !get(&d->timeline_hash, 8) ||
        !get(&d->points_3d, 8) || !get(&d->wall_s, 8) || !get(&n, 8) || at + n > s.size())
        return false;
    d->report.assign(s, at, n);
    at += n;
    if (!get(&n, 8)) return false;
    d->window.resize(n);
    for (pin_change& c : d->window)
        if (!get(&c, sizeof c)) return false;
    return at == s.size();
}

struct child {
    pid_t pid = -1;
    int fd = -1;
};

child start(const platform::platform_config& config, simtime::ticks from, simtime::ticks to,
            const std::string& vcd) {
    int fd[2];
    if (pipe(fd) != 0) return {};
    std::fflush(stdout);
    const pid_t pid = fork();
    if (pid == 0) {
        close(fd[0]);
        const std::string s = serialise(simulate(config, from, to, vcd));
        size_t done = 0;
        while (done < s.size()) {
            const ssize_t w = write(fd[1], s.data() + done, s.size() - done);
            if (w <= 0) _exit(3);
            done += static_cast<size_t>(w);
        }
        close(fd[1]);
        _exit(0);
    }
    close(fd[1]);
    return {pid, fd[0]};
}

bool finish(child c, digest* d) {
    if (c.pid < 0) return false;
    std::string s;
    char buffer[65536];
    for (ssize_t n; (n = read(c.fd, buffer, sizeof buffer)) > 0;)
        s.append(buffer, static_cast<size_t>(n));
    close(c.fd);
    int status = 0;
    if (waitpid(c.pid, &status, 0) != c.pid || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
        return false;
    return deserialise(s, d);
}

// ---- the VCD of a window, signal by signal ----------------------------------------------
// Full signal name -> its values (time fs, value), the window start's
// included. Read rather than byte-compared: a writer may order a time
// step's values differently (Verilator's writes them by code).
struct vcd_changes {
    std::map<std::string, std::vector<testsupport::vcd_change>> signals;
    size_t changes = 0;
    bool ok = false;
};

vcd_changes parse_vcd(const std::string& path) {
    const testsupport::vcd_file v = testsupport::read_vcd(path);
    vcd_changes r;
    for (const auto& named : v.code_of) r.signals[named.first] = v.history(named.first);
    r.changes = v.value_count;
    r.ok = v.ok && v.times_increase;
    return r;
}

// Prints the first signal whose changes differ; true if the two are equal.
bool same_vcd(const vcd_changes& a, const vcd_changes& b) {
    if (a.signals.size() != b.signals.size()) {
        std::printf("VCD: %zu signals against %zu\n", a.signals.size(), b.signals.size());
        return false;
    }
    for (const auto& [name, changes] : a.signals) {
        const auto other = b.signals.find(name);
        if (other == b.signals.end()) {
            std::printf("VCD: signal %s only in the fast arrangement's\n", name.c_str());
            return false;
        }
        if (changes == other->second) continue;
        const auto& c = other->second;
        size_t i = 0;
        while (i < changes.size() && i < c.size() && changes[i] == c[i]) ++i;
        std::printf(
            "VCD: signal %s differs at change %zu: fast %s, pins %s\n", name.c_str(), i,
            i < changes.size() ? (std::to_string(changes[i].fs) + " fs " + changes[i].value).c_str()
                               : "none",
            i < c.size() ? (std::to_string(c[i].fs) + " fs " + c[i].value).c_str() : "none");
        return false;
    }
    return true;
}

struct pair_of_runs {
    digest fast, pins;
    vcd_changes fast_vcd, pins_vcd;
    bool vcd_bytes_equal = false;
};

bool same_bytes(const std::string& a, const std::string& b) {
    std::ifstream fa(a, std::ios::binary), fb(b, std::ios::binary);
    return fa && fb &&
           std::string(std::istreambuf_iterator<char>(fa), {}) ==
               std::string(std::istreambuf_iterator<char>(fb), {});
}

// Runs `config` in both arrangements at once (the pins one with
// `pins_right_faults` added to the right sensor's faults).
pair_of_runs run_both(platform::platform_config config, simtime::ticks from, simtime::ticks to,
                      const std::vector<sensor::fault>& pins_right_faults = {}) {
    char dir_template[] = "/tmp/arrangements_vcd_XXXXXX";
    const std::string dir = mkdtemp(dir_template) ? dir_template : "/tmp";
    const std::string fast_vcd = dir + "/fast.vcd", pins_vcd = dir + "/pins.vcd";
    config.arrangement = arrangement_kind::fast;
    const child fast = start(config, from, to, fast_vcd);
    config.arrangement = arrangement_kind::pins;
    config.right_faults.insert(config.right_faults.end(), pins_right_faults.begin(),
                               pins_right_faults.end());
    const child pins = start(config, from, to, pins_vcd);
    pair_of_runs r;
    EXPECT_TRUE(finish(fast, &r.fast)) << "the fast arrangement's child failed";
    EXPECT_TRUE(finish(pins, &r.pins)) << "the pin-level arrangement's child failed";
    r.fast_vcd = parse_vcd(fast_vcd);
    r.pins_vcd = parse_vcd(pins_vcd);
    r.vcd_bytes_equal = same_bytes(fast_vcd, pins_vcd);
    std::filesystem::remove_all(dir);
    return r;
}

// The first change where the two windows differ, printed.
size_t first_difference(const std::vector<pin_change>& a, const std::vector<pin_change>& b) {
    const size_t n = std::min(a.size(), b.size());
    for (size_t i = 0; i < n; ++i) {
        if (!(a[i] == b[i])) {
            std::printf(
                "first window difference at change %zu: fast tick %lld group "
                "%u value %llx"
                ", pins tick %lld group %u value %llx\n",
                i, static_cast<long long>(a[i].tick), a[i].group,
                static_cast<unsigned long long>(a[i].value), static_cast<long long>(b[i].tick),
                b[i].group, static_cast<unsigned long long>(b[i].value));
            return i;
        }
    }
    return a.size() == b.size() ? SIZE_MAX : n;
}

void print(const char* what, const pair_of_runs& r) {
    std::printf(
        "%s: pin hash fast %016llx pins %016llx over %llu / %llu "
        "changes; window %zu / %zu "
        "changes; timeline %016llx / %016llx; 3D points %llu / %llu; "
        "wall %.2f s / %.2f s "
        "(pins / fast %.2f)\n",
        what, static_cast<unsigned long long>(r.fast.pin_hash),
        static_cast<unsigned long long>(r.pins.pin_hash),
        static_cast<unsigned long long>(r.fast.pin_changes),
        static_cast<unsigned long long>(r.pins.pin_changes), r.fast.window.size(),
        r.pins.window.size(), static_cast<unsigned long long>(r.fast.timeline_hash),
        static_cast<unsigned long long>(r.pins.timeline_hash),
        static_cast<unsigned long long>(r.fast.points_3d),
        static_cast<unsigned long long>(r.pins.points_3d), r.fast.wall_s, r.pins.wall_s,
        r.pins.wall_s / std::max(1e-9, r.fast.wall_s));
    std::printf("%s: VCD of the window %zu / %zu signals, %zu / %zu changes, bytes %s\n", what,
                r.fast_vcd.signals.size(), r.pins_vcd.signals.size(), r.fast_vcd.changes,
                r.pins_vcd.changes,
                r.vcd_bytes_equal ? "identical" : "differ (order within a time step)");
    std::fflush(stdout);
}

// Both arrangements' runs alike: pins, window, waveform, timeline, report
// (the first difference named).
testing::AssertionResult identical(const pair_of_runs& r) {
    if (r.fast.pin_hash != r.pins.pin_hash || r.fast.pin_changes != r.pins.pin_changes)
        return testing::AssertionFailure() << "pin hash or pin change count differ";
    if (r.fast.window.size() <= 1000u)
        return testing::AssertionFailure() << "the window must see pin activity";
    if (first_difference(r.fast.window, r.pins.window) != SIZE_MAX)
        return testing::AssertionFailure() << "the window's pin changes differ";
    if (!r.fast_vcd.ok || !r.pins_vcd.ok) return testing::AssertionFailure() << "a VCD is missing";
    if (r.fast_vcd.changes <= 10000u)
        return testing::AssertionFailure() << "the VCD window must see activity";
    if (!same_vcd(r.fast_vcd, r.pins_vcd))
        return testing::AssertionFailure() << "the VCDs differ signal by signal";
    if (r.fast.timeline_hash != r.pins.timeline_hash)
        return testing::AssertionFailure() << "the timelines differ";
    if (r.fast.report != r.pins.report) {
        return testing::AssertionFailure() << "the reports differ:\n---- fast report\n"
                                           << r.fast.report << "---- pins report\n"
                                           << r.pins.report;
    }
    return testing::AssertionSuccess();
}

// Under AddressSanitizer (the Debug + ASan pass) every case runs 3 periods:
// that pass looks for memory errors in both arrangements and the VCD path;
// the 3D outputs are asserted by the full-length RelWithDebInfo runs.
#if defined(__SANITIZE_ADDRESS__)
constexpr bool sanitized = true;
#else
constexpr bool sanitized = false;
#endif
int periods(int full) {
    return sanitized ? 3 : full;
}
// The run reaches 3D outputs (asserted by the full-length runs only).
bool reaches_3d_outputs(const pair_of_runs& r) {
    return sanitized || r.fast.points_3d >= 2u;
}

// The window: 1 ms around the first in-step pair's FRAME_READY (49.2 ms):
// card registers, EDMA bursts, sensor lines of the next frame.
constexpr simtime::ticks window_from = 49 * ticks_per_ms;
constexpr simtime::ticks window_to = 50 * ticks_per_ms;

// The platform's defaults (the firmware's SDRAM traffic on EMIFA beside the
// capture, the memory plan of docs/firmware.md), `frames` periods.
platform::platform_config functional_run(int frames) {
    platform::platform_config config;
    config.frames = periods(frames);
    return config;
}

// The default scenario: within budget; the ball is detected in scene frame
// 4 and tracked from then on.
TEST(Arrangements, DefaultScenarioGivesIdenticalPinsAndReport) {
    platform::platform_config config = functional_run(10);
    const pair_of_runs r = run_both(config, window_from, window_to);
    print("default", r);
    EXPECT_TRUE(reaches_3d_outputs(r)) << "the run must reach 3D outputs";
    EXPECT_TRUE(identical(r));
    RecordProperty("pin_hash", std::to_string(r.fast.pin_hash));
    RecordProperty("wall_ratio_pins_over_fast", std::to_string(r.pins.wall_s / r.fast.wall_s));
}

// A 1-line start skew on the right sensor from its second frame on (the
// first after the start-up's restart at 24.6 ms): the card sees the dark
// rows out of place, reports SYNC_ERROR at 49.2 ms and restarts OE. The
// window runs on 2 ms into the restarted frames' lines.
TEST(Arrangements, StartSkewFaultGivesIdenticalPinsAndReport) {
    platform::platform_config config = functional_run(10);
    config.right_faults.push_back(sensor::fault::start_skew(sensor::fault_trigger::at_frame(1), 1,
                                                            0, config.profile.line_pclks));
    const pair_of_runs r = run_both(config, window_from, window_to + 2 * ticks_per_ms);
    print("start_skew", r);
    EXPECT_TRUE(reaches_3d_outputs(r)) << "the run must reach 3D outputs";
    EXPECT_TRUE(identical(r));
}

// DSK v3: 1 GHz CPU, 125 MHz ECLK (144 ticks against the pixel clock's
// 1050: edges meet every 504 ns, a different set of phases).
TEST(Arrangements, DskV3GivesIdenticalPinsAndReport) {
    platform::platform_config config = functional_run(9);
    config.dsk = c6416::dsk_v3();
    const pair_of_runs r = run_both(config, window_from, window_to);
    print("dsk_v3", r);
    EXPECT_TRUE(reaches_3d_outputs(r)) << "the run must reach 3D outputs";
    EXPECT_TRUE(identical(r));
}

// The comparison can fail: the right sensor's HREF inverted for one pixel
// clock inside the window, in the pin-level run only (a sensor fault given
// to that run from the test side).
TEST(Arrangements, OneCycleDifferenceIsSeen) {
    platform::platform_config config = functional_run(3);
    config.frames = 3;
    const sensor::fault one_clock_glitch = sensor::fault::href_glitch(
        sensor::fault_trigger::at_time((window_from + window_to) / 2), 1);
    const pair_of_runs r = run_both(config, window_from, window_to, {one_clock_glitch});
    print("one-cycle difference", r);
    EXPECT_NE(r.fast.pin_hash, r.pins.pin_hash);
    const size_t first = first_difference(r.fast.window, r.pins.window);
    EXPECT_NE(first, SIZE_MAX);
    EXPECT_FALSE(same_vcd(r.fast_vcd, r.pins_vcd)) << "the VCD comparison must see it too";
}

}  // namespace
