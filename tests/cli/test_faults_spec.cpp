// The fault spec grammar (docs/faults.md), its mapping onto the hooks, the
// contract table's thresholds (docs/fault-contract.md) and the campaign's
// plan and shards. No simulation: plain calls into stereosim_app.
#include <gtest/gtest.h>

#include <set>
#include <sstream>
#include <string>

#include "tb/app/faults/campaign.h"
#include "tb/app/faults/contract.h"
#include "tb/app/faults/fault_spec.h"

namespace {

using faults::fault_spec;
using faults::fault_type;

fault_spec parse_ok(const std::string& text) {
    std::string error;
    const std::optional<fault_spec> s = faults::parse_fault_spec(text, &error);
    EXPECT_TRUE(s.has_value()) << text << ": " << error;
    return s.value_or(fault_spec{});
}

std::string parse_error(const std::string& text) {
    std::string error;
    EXPECT_FALSE(faults::parse_fault_spec(text, &error).has_value()) << text;
    return error;
}

TEST(FaultSpec, EveryExampleOfTheIssueParsesToItsCanonicalForm) {
    const std::pair<const char*, const char*> cases[] = {
        {"skew:sensor=R,lines=3@frame=5", "skew:sensor=R,lines=3,pixels=0@frame=5"},
        {"skew:sensor=L,pixels=1@frame=2", "skew:sensor=L,lines=0,pixels=1@frame=2"},
        {"drop-line:sensor=L,line=100@frame=7", "drop-line:sensor=L,line=100@frame=7"},
        {"drop-frame:sensor=R@frame=4", "drop-frame:sensor=R@frame=4"},
        {"extra-frame:sensor=L@frame=4", "extra-frame:sensor=L@frame=4"},
        {"drift:sensor=R,ppm=200", "drift:sensor=R,ppm=200"},
        {"glitch:sensor=L,signal=href@ms=130.2", "glitch:sensor=L,signal=href,width=1@ms=130.2"},
        {"dark-leak:sensor=R,level=80@frame=4", "dark-leak:sensor=R,level=80@frame=4"},
        {"stuck-bit:sensor=L,bit=7", "stuck-bit:sensor=L,bit=7,value=1"},
        {"dead:sensor=R", "dead:sensor=R"},
        {"oe-stuck:sensor=L", "oe-stuck:sensor=L"},
        {"emif-wait:cycles=40@frame=3", "emif-wait:cycles=40,ce=3@frame=3"},
        {"cpu-slow:factor=3@frame=6", "cpu-slow:factor=3@frame=6"},
    };
    for (const auto& [text, canonical] : cases) {
        const fault_spec s = parse_ok(text);
        EXPECT_EQ(faults::canonical(s), canonical);
        // The canonical form parses back to itself.
        EXPECT_EQ(faults::canonical(parse_ok(faults::canonical(s))), canonical);
    }
}

TEST(FaultSpec, MalformedSpecsAreExactOneLineErrors) {
    EXPECT_EQ(parse_error("skw:sensor=R"),
              "bad fault spec 'skw:sensor=R': unknown fault kind 'skw' (kinds: skew, drop-line, "
              "drop-frame, extra-frame, drift, glitch, dark-leak, stuck-bit, dead, oe-stuck, "
              "emif-wait, cpu-slow)");
    EXPECT_EQ(parse_error("skew:sensor=R,line=3"),
              "bad fault spec 'skew:sensor=R,line=3': unknown parameter 'line' for skew "
              "(parameters: sensor, lines, pixels)");
    EXPECT_EQ(parse_error("dead:sensor=R,level=3"),
              "bad fault spec 'dead:sensor=R,level=3': unknown parameter 'level' for dead "
              "(parameters: sensor)");
    EXPECT_EQ(parse_error("skew:lines=3@frame=5"),
              "bad fault spec 'skew:lines=3@frame=5': missing parameter 'sensor'");
    EXPECT_EQ(parse_error("emif-wait@frame=3"),
              "bad fault spec 'emif-wait@frame=3': missing parameter 'cycles'");
    EXPECT_EQ(parse_error("skew:sensor=X,lines=3"),
              "bad fault spec 'skew:sensor=X,lines=3': bad value 'X' for sensor (one of L|R)");
    EXPECT_EQ(parse_error("stuck-bit:sensor=L,bit=8"),
              "bad fault spec 'stuck-bit:sensor=L,bit=8': bad value '8' for bit (an integer in "
              "0..7)");
    EXPECT_EQ(parse_error("skew:sensor=L,lines=2.5"),
              "bad fault spec 'skew:sensor=L,lines=2.5': bad value '2.5' for lines (an integer in "
              "0..524)");
    EXPECT_EQ(parse_error("cpu-slow:factor=1"),
              "bad fault spec 'cpu-slow:factor=1': bad value '1' for factor (a number in "
              "1.001..100)");
    EXPECT_EQ(parse_error("skew:sensor=R,lines=3@frm=5"),
              "bad fault spec 'skew:sensor=R,lines=3@frm=5': bad trigger '@frm=5' (expected "
              "@frame=N with N >= 0 or @ms=T with T >= 0)");
    EXPECT_EQ(parse_error("skew:sensor=R,lines=3@frame=-1"),
              "bad fault spec 'skew:sensor=R,lines=3@frame=-1': bad trigger '@frame=-1' (expected "
              "@frame=N with N >= 0 or @ms=T with T >= 0)");
    EXPECT_EQ(parse_error("skew:sensor=R,sensor=L,lines=1"),
              "bad fault spec 'skew:sensor=R,sensor=L,lines=1': parameter 'sensor' given twice");
    EXPECT_EQ(parse_error("skew:sensor=R"),
              "bad fault spec 'skew:sensor=R': skew needs lines or pixels > 0");
    EXPECT_EQ(parse_error("drift:sensor=R,ppm=0"),
              "bad fault spec 'drift:sensor=R,ppm=0': bad value '0' for ppm (not 0)");
    EXPECT_EQ(parse_error("drop-line:sensor=L,line=100@ms=3"),
              "bad fault spec 'drop-line:sensor=L,line=100@ms=3': parameter 'line' needs a "
              "@frame=N trigger");
    EXPECT_EQ(parse_error("skew:sensor"),
              "bad fault spec 'skew:sensor': expected key=value, got 'sensor'");
    for (const char* bad : {"skew:sensor=R,lines=3@frm=5", "skw", "dead:sensor=R,,"})
        EXPECT_EQ(parse_error(bad).find('\n'), std::string::npos);
}

TEST(FaultSpec, SensorFaultsMapOntoTheSensorsHooks) {
    platform::platform_config config;
    const int line = config.profile.line_pclks;
    faults::apply(parse_ok("skew:sensor=R,lines=3@frame=5"), config);
    faults::apply(parse_ok("skew:sensor=L,pixels=1@frame=2"), config);
    faults::apply(parse_ok("drop-line:sensor=L,line=100@frame=7"), config);
    faults::apply(parse_ok("glitch:sensor=L,signal=href@ms=130.2"), config);
    faults::apply(parse_ok("stuck-bit:sensor=L,bit=7"), config);
    faults::apply(parse_ok("drift:sensor=R,ppm=-200@ms=1"), config);
    faults::apply(parse_ok("dead:sensor=R"), config);
    ASSERT_EQ(config.right_faults.size(), 3u);
    ASSERT_EQ(config.left_faults.size(), 4u);

    const sensor::fault& skew_r = config.right_faults[0];
    EXPECT_EQ(skew_r.kind, sensor::fault_kind::start_skew);
    EXPECT_EQ(skew_r.skew_pclks, 3 * line);
    EXPECT_FALSE(skew_r.when.by_time);
    EXPECT_EQ(skew_r.when.frame, 5u);

    EXPECT_EQ(config.left_faults[0].skew_pclks, 1);
    EXPECT_EQ(config.left_faults[0].when.frame, 2u);

    const sensor::fault& drop = config.left_faults[1];
    EXPECT_EQ(drop.kind, sensor::fault_kind::dropped_line);
    EXPECT_EQ(drop.when.frame, 7u);
    EXPECT_EQ(drop.when.line, 100);

    // 130.2 ms = 130,200,000 ns x 18 ticks / ns, exactly.
    const sensor::fault& glitch = config.left_faults[2];
    EXPECT_EQ(glitch.kind, sensor::fault_kind::href_glitch);
    EXPECT_TRUE(glitch.when.by_time);
    EXPECT_EQ(glitch.when.tick, 2343600000);
    EXPECT_EQ(glitch.width_pclks, 1);

    const sensor::fault& stuck = config.left_faults[3];
    EXPECT_EQ(stuck.kind, sensor::fault_kind::stuck_data_bit);
    EXPECT_EQ(stuck.bit, 7);
    EXPECT_TRUE(stuck.stuck_value);
    EXPECT_TRUE(stuck.when.by_time);
    EXPECT_EQ(stuck.when.tick, 0);

    EXPECT_EQ(config.right_faults[1].kind, sensor::fault_kind::pclk_drift);
    EXPECT_EQ(config.right_faults[1].drift_ppm, -200);
    EXPECT_EQ(config.right_faults[1].when.tick, 18000000);
    EXPECT_EQ(config.right_faults[2].kind, sensor::fault_kind::never_start);
}

TEST(FaultSpec, BusAndCpuFaultsStartAtTheirSyncPeriod) {
    platform::platform_config config;
    faults::apply(parse_ok("emif-wait:cycles=40@frame=3"), config);
    faults::apply(parse_ok("cpu-slow:factor=2.5@frame=6"), config);
    ASSERT_EQ(config.ardy_faults.size(), 1u);
    EXPECT_EQ(config.ardy_faults[0].ce, 3);
    EXPECT_EQ(config.ardy_faults[0].extra_cycles, 40u);
    EXPECT_EQ(config.ardy_faults[0].from_tick, 3 * platform::period_24_5_ms);
    EXPECT_EQ(config.cpu_slow_num, 2500u);
    EXPECT_EQ(config.cpu_slow_den, 1000u);
    EXPECT_EQ(config.cpu_slow_from, 6 * platform::period_24_5_ms);
    EXPECT_TRUE(config.left_faults.empty() && config.right_faults.empty());
}

TEST(FaultSpec, ListNamesEveryKindAndParameter) {
    const std::string list = faults::kinds_listing();
    EXPECT_EQ(faults::fault_kinds().size(), static_cast<size_t>(faults::fault_type_count));
    for (const faults::kind_info& k : faults::fault_kinds()) {
        EXPECT_NE(list.find(std::string("  ") + k.name + "  ("), std::string::npos) << k.name;
        for (const faults::param_info& p : k.params)
            EXPECT_NE(list.find(std::string("      ") + p.name + " "), std::string::npos) << p.name;
    }
    EXPECT_NE(list.find("an integer in 0..7"), std::string::npos);
    EXPECT_NE(list.find("@frame=N"), std::string::npos);
}

// ---- the contract table (docs/fault-contract.md) --------------------------------------------

faults::outcome nominal(const std::string& spec, const faults::contract_params& p,
                        bool onset_start_out_of_step = false) {
    faults::fault_observation f;
    f.in_effect = true;
    f.onset_start_out_of_step = onset_start_out_of_step;
    return faults::expected_for(f, parse_ok(spec), p, {}).allowed.front();
}

TEST(FaultContract, ThresholdsFollowTheCardAndTheProfile) {
    const faults::contract_params p = faults::params_for(platform::platform_config{});
    EXPECT_EQ(p.dark_threshold, 32u);
    EXPECT_EQ(p.black_level, 16);
    EXPECT_EQ(p.words_per_pair, 153600);
    using faults::outcome;
    EXPECT_EQ(nominal("dark-leak:sensor=R,level=80", p), outcome::hard_error);
    EXPECT_EQ(nominal("dark-leak:sensor=R,level=8", p), outcome::harmless);
    // 6 sigma of dark-pixel noise = ceil(6 x 1.7) = 11 DN: 20 + 11 < 32 harmless;
    // 24 straddles the threshold (every outcome but a miss allowed).
    EXPECT_EQ(nominal("dark-leak:sensor=R,level=20", p), outcome::harmless);
    faults::fault_observation f;
    f.in_effect = true;
    EXPECT_EQ(
        faults::expected_for(f, parse_ok("dark-leak:sensor=R,level=24"), p, {}).allowed.size(), 3u);
    // 16 | 32 = 48 >= 32 on every dark pixel; 16 | 8 = 24 + noise stays below.
    EXPECT_EQ(nominal("stuck-bit:sensor=L,bit=5", p), outcome::hard_error);
    EXPECT_EQ(nominal("stuck-bit:sensor=L,bit=7", p), outcome::hard_error);
    EXPECT_EQ(nominal("stuck-bit:sensor=L,bit=3", p), outcome::harmless);
    EXPECT_EQ(nominal("stuck-bit:sensor=L,bit=7,value=0", p), outcome::harmless);
    // Drift: the slip over a frame's first clock to its last readout pixel
    // (line 27 + 488 - 1 = 514: 514 x 800 + 656 = 411,856 clocks); a slower
    // clock (ppm > 0) fails every start from 1 clock, a faster one from 0.5.
    EXPECT_EQ(p.checked_span_pclks, 411856);
    EXPECT_EQ(nominal("drift:sensor=R,ppm=200", p), outcome::hard_error);
    EXPECT_EQ(nominal("drift:sensor=R,ppm=-3", p), outcome::hard_error);
    EXPECT_EQ(nominal("drift:sensor=L,ppm=-2", p), outcome::hard_error);
    EXPECT_EQ(nominal("drift:sensor=R,ppm=1", p), outcome::resync);
    EXPECT_EQ(nominal("drift:sensor=R,ppm=2", p), outcome::resync);  // resync | hard_error
    // -1 ppm: 0.41 clock; only starts with phase <= 0.09 pass: either.
    EXPECT_EQ(nominal("drift:sensor=L,ppm=-1", p), outcome::resync);
    EXPECT_EQ(faults::expected_for(f, parse_ok("drift:sensor=L,ppm=-1"), p, {}).allowed.size(), 2u);
    // A pair's read: 153,600 words x (14 + c) ECLK x 10 ns against 24.5 ms:
    // c = 6 gives 30.7 ms > 1.2 periods (overflow), c = 2 24.58 ms (within 20 %:
    // either), c = 1 23.04 ms.
    EXPECT_EQ(nominal("emif-wait:cycles=6", p), outcome::overflow);
    EXPECT_EQ(nominal("emif-wait:cycles=5", p), outcome::harmless);  // harmless | overflow
    EXPECT_EQ(nominal("emif-wait:cycles=2", p), outcome::harmless);
    EXPECT_EQ(nominal("emif-wait:cycles=1", p), outcome::harmless);
    EXPECT_EQ(nominal("emif-wait:cycles=40,ce=2", p), outcome::harmless);
    EXPECT_EQ(nominal("skew:sensor=R,lines=3", p), outcome::resync);
    // The card's frame-identity check sees a repeat; the paper's card cannot.
    EXPECT_EQ(nominal("extra-frame:sensor=L", p), outcome::resync);
    faults::contract_params paper = p;
    paper.paper_card = true;
    EXPECT_EQ(nominal("extra-frame:sensor=L", paper), outcome::harmless);
    EXPECT_EQ(nominal("dead:sensor=R", p), outcome::hard_error);
    // oe-stuck: a hard error when the truth says a restart is due (the onset's
    // start was out of step), whatever the card chose to do.
    EXPECT_EQ(nominal("oe-stuck:sensor=L", p, false), outcome::harmless);
    EXPECT_EQ(nominal("oe-stuck:sensor=L", p, true), outcome::hard_error);
    EXPECT_EQ(nominal("dead:sensor=R@frame=3", p, false), outcome::harmless);
    EXPECT_EQ(nominal("dead:sensor=R@frame=3", p, true), outcome::hard_error);
    // (1 + 1) x (8 + 1) + 2 periods.
    EXPECT_EQ(faults::hard_error_bound_periods(p), 20);
}

TEST(FaultContract, ViolationsAreReported) {
    const faults::contract_params p = faults::params_for(platform::platform_config{});
    const fault_spec skew = parse_ok("skew:sensor=R,lines=3@frame=4");
    faults::run_observation run;
    run.end_ms = 196;
    run.firmware_sync_errors = 1;
    faults::fault_observation f;
    f.in_effect = true;
    f.onset_ms = 74;
    f.detected = true;
    f.detected_by = "sync_error";
    f.detect_ms = 98;
    f.frames_to_detect = 0;
    f.causes = 0x22;  // R_WINDOW | R_VSYNC
    f.reported = true;
    f.reported_by = "sync_error";
    f.report_ms = 98.1;
    f.recovered = true;
    f.recover_ms = 122;
    f.resumed_ms = 130;
    f.frames_to_recover = 1;
    EXPECT_TRUE(faults::check(f, skew, p, run).ok) << faults::check(f, skew, p, run).violations[0];
    EXPECT_EQ(faults::check(f, skew, p, run).actual, faults::outcome::resync);

    faults::run_observation unsynced = run;
    unsynced.unsynced_pairs_used = 1;
    const faults::verdict v = faults::check(f, skew, p, unsynced);
    EXPECT_FALSE(v.ok);
    EXPECT_EQ(v.violations.front(), "rule 1: 1 pair(s) out of step used");

    faults::fault_observation slow = f;
    slow.frames_to_detect = 2;
    EXPECT_FALSE(faults::check(slow, skew, p, run).ok);

    faults::fault_observation stuck = f;  // detected, never recovered, run long past due
    stuck.recovered = false;
    faults::run_observation long_run = run;
    long_run.end_ms = 400;
    EXPECT_EQ(faults::check(stuck, skew, p, long_run).actual, faults::outcome::no_recovery);
    EXPECT_FALSE(faults::check(stuck, skew, p, long_run).ok);

    faults::fault_observation silent = f;  // the card flagged it, the firmware said nothing
    silent.reported = false;
    EXPECT_FALSE(faults::check(silent, skew, p, run).ok);

    // A dead sensor with no hard error by the bound.
    const fault_spec dead = parse_ok("dead:sensor=R");
    faults::fault_observation d;
    d.in_effect = true;
    d.onset_ms = 0;
    d.detected = true;
    d.detected_by = "sync_error";
    d.detect_ms = 25;
    d.frames_to_detect = 1;
    d.causes = 0x02;  // R_WINDOW: the other sensor started the common frame
    d.reported = true;
    d.report_ms = 25.1;
    faults::run_observation hang = run;
    hang.end_ms = 600;
    EXPECT_EQ(faults::check(d, dead, p, hang).actual, faults::outcome::no_recovery);
    faults::run_observation reported = hang;
    reported.hard_error = true;
    reported.hard_error_ms = 460;
    EXPECT_TRUE(faults::check(d, dead, p, reported).ok);
    reported.hard_error_ms = 500;  // 20 periods = 490 ms
    EXPECT_FALSE(faults::check(d, dead, p, reported).ok);

    faults::run_observation clean;
    clean.frames = 8;
    clean.pairs_processed = 4;
    clean.points_scored = 2;
    EXPECT_TRUE(faults::check_clean(clean).ok);
    clean.false_alarms = 1;
    EXPECT_FALSE(faults::check_clean(clean).ok);
}

TEST(FaultCampaign, SmokeCoversEveryKindAndShardsPartitionThePlan) {
    const std::vector<faults::campaign_run> smoke = faults::campaign_plan("smoke", 1);
    std::set<std::string> kinds;
    std::set<std::pair<std::string, int>> kind_sensors;  // one-sensor kinds
    int clean = 0, soak_clean = 0, soak_faults = 0, soak_drift = 0, combined = 0;
    for (const faults::campaign_run& r : smoke) {
        if (r.fault.empty()) {
            ++clean;
            // Three default watchdog periods (500 ms) of a healthy run.
            soak_clean += r.frames * 24.5 >= 3 * 500;
            continue;
        }
        // A row may inject several faults, space-separated.
        std::istringstream specs(r.fault);
        int faults_in_row = 0;
        bool bus_or_cpu = false, sensor_fault = false;
        for (std::string spec; specs >> spec; ++faults_in_row) {
            const faults::fault_spec s = parse_ok(spec);
            kinds.insert(faults::fault_type_name(s.type));
            if (faults::is_sensor_fault(s.type)) {
                kind_sensors.insert({faults::fault_type_name(s.type), s.camera});
                sensor_fault = true;
            } else {
                bus_or_cpu = true;
            }
            soak_drift += s.type == faults::fault_type::drift && r.frames * 24.5 >= 1500;
        }
        combined += bus_or_cpu && sensor_fault;
        // More intermittent faults than RETRY_LIMIT, in one run.
        soak_faults += faults_in_row > r.retry_limit && r.retry_limit >= 8;
        if (faults_in_row == 1 && r.frames * 24.5 < 1500) {
            EXPECT_LE(r.frames, 14);  // a surely overrunning CPU needs 10 periods to show drops
        }
    }
    EXPECT_EQ(kinds.size(), static_cast<size_t>(faults::fault_type_count));
    for (const auto& [kind, camera] : kind_sensors)
        EXPECT_EQ(kind_sensors.count({kind, 1 - camera}), 1u) << kind << " on one sensor only";
    EXPECT_EQ(clean, 3);
    EXPECT_EQ(soak_clean, 1);
    EXPECT_GE(soak_faults, 1);
    EXPECT_GE(soak_drift, 1);
    EXPECT_GE(combined, 2);
    std::printf("smoke: %zu runs (%d clean)\n", smoke.size(), clean);

    const std::vector<faults::campaign_run> full = faults::campaign_plan("full", 3);
    int clean_frames = 0;
    for (const faults::campaign_run& r : full) clean_frames += r.fault.empty() ? r.frames : 0;
    EXPECT_GE(clean_frames, 1000);
    std::printf("full: %zu runs, %d clean frames\n", full.size(), clean_frames);

    std::multiset<int> seen;
    for (int k = 1; k <= 4; ++k)
        for (const faults::campaign_run& r : faults::shard_of(full, k, 4)) {
            EXPECT_EQ(r.index % 4, k - 1);
            seen.insert(r.index);
        }
    EXPECT_EQ(seen.size(), full.size());
    EXPECT_EQ(std::set<int>(seen.begin(), seen.end()).size(), full.size());
    EXPECT_TRUE(faults::campaign_plan("nightly", 1).empty());
}

}  // namespace
