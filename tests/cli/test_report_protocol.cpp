// A firmware that leaves out a report the contract reads is not given the
// benefit of the doubt (docs/firmware-abi.md, "The reporting protocol"): the
// run breaks the contract with a violation naming the missing report.
//
// Two halves. The shipped firmware with one report filtered out
// (tests/firmware/plugins/omitting_firmware.c, its key `omit`) run as a
// user runs it, on a scenario where that report is due, next to the same
// run with nothing left out, which keeps the contract; and the check itself
// on hand-made sequences (tb/app/faults/report_protocol.h), for what no run
// of the reference reaches (a captured pair with a cause bit).
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <ostream>
#include <string>
#include <vector>

#include "tb/app/faults/report_protocol.h"
#include "tests/support/shell.h"

namespace {

using nlohmann::json;

struct omission {
    const char* omit;     // the omitting firmware's `omit`
    const char* run;      // stereosim run arguments where the report is due
    const char* expects;  // in one of the violations
};

// A drop-line detected by the card (re-armed by the card itself), an
// overflow the firmware re-arms on, both sensors dead under a short
// watchdog, a persistent dark leak the firmware gives up on.
const char* const drop_line = "--fault drop-line:sensor=L@frame=3";
const char* const overflow = "--fault emif-wait:cycles=40@frame=3";
const char* const silent =
    "--fault dead:sensor=L --fault dead:sensor=R --frames 10 --seed 2 "
    "--set firmware.watchdog_ms=50 --set firmware.card_start_timeout=65535";
const char* const give_up = "--fault dark-leak:sensor=L,level=80@frame=3 --frames 30";

const omission omissions[] = {
    {"oe_raised", drop_line, "rule 6: missing report OE_RAISED"},
    {"in_step", drop_line,
     "rule 6: 1 OE start(s) whose pairs the firmware used without "
     "reporting in_step"},
    {"sync_error", drop_line, "card SYNC_ERROR(s) the firmware never reported"},
    {"pair_captured", drop_line, "rule 7: missing report PAIR_CAPTURED"},
    {"pair_processed", drop_line, "rule 5: missing report PAIR_PROCESSED"},
    {"frames_used", drop_line, "rule 7: missing report FRAMES_USED"},
    {"result", drop_line, "rule 5: missing report result"},
    {"overflow", overflow, "card OVERFLOW(s) the firmware never reported"},
    {"card_rearmed", overflow, "rule 11: missing report CARD_REARMED"},
    {"pair_dropped", "--fault cpu-slow:factor=4@frame=3",
     "in-step pair(s) forwarded but neither processed nor reported dropped"},
    {"watchdog", silent, "rule 11: missing report WATCHDOG"},
    {"hard_error", silent, "rule 4: missing report HARD_ERROR"},
    {"hard_error", give_up, "rule 4: missing report HARD_ERROR"},
};

// The test's name in ctest: what is left out.
void PrintTo(const omission& o, std::ostream* os) {
    *os << o.omit;
}

struct run_outcome {
    int exit_code = -1;
    std::vector<std::string> violations;
    std::string output;
};

run_outcome run_omitting(const std::string& omit, const std::string& args) {
    const std::string dir = testsupport::temp_dir("omit_" + omit) + "/out";
    const auto r = testsupport::run_command(
        std::string(STEREOSIM_BINARY) + " run --quiet --firmware " + OMITTING_FIRMWARE +
        " --set firmware.omit=" + omit + " " + args + " --out " + dir);
    run_outcome out;
    out.exit_code = r.exit_code;
    out.output = r.output;
    const json report = json::parse(testsupport::read_text(dir + "/report.json"));
    for (const json& v : report["fault_run"]["violations"]) out.violations.push_back(v);
    return out;
}

std::string joined(const std::vector<std::string>& lines) {
    std::string text;
    for (const std::string& l : lines) text += l + "\n";
    return text;
}

class MissingReport : public ::testing::TestWithParam<omission> {};

TEST_P(MissingReport, IsAViolationNamingIt) {
    const omission& o = GetParam();
    const run_outcome missing = run_omitting(o.omit, o.run);
    EXPECT_EQ(missing.exit_code, 4) << missing.output;
    EXPECT_NE(joined(missing.violations).find(o.expects), std::string::npos)
        << "expected '" << o.expects << "' in:\n"
        << joined(missing.violations);
}

INSTANTIATE_TEST_SUITE_P(OmittingFirmware, MissingReport, ::testing::ValuesIn(omissions),
                         [](const ::testing::TestParamInfo<omission>& info) {
                             return std::string(info.param.omit) + "_" + std::to_string(info.index);
                         });

// The same scenarios with nothing left out keep the contract: each
// violation above is the omission's, not the scenario's.
TEST(MissingReport, NothingLeftOutKeepsTheContract) {
    for (const char* args : {drop_line, overflow, silent, give_up}) {
        const run_outcome whole = run_omitting("none", args);
        EXPECT_TRUE(whole.violations.empty()) << args << ":\n" << joined(whole.violations);
        EXPECT_NE(whole.exit_code, 4) << args << "\n" << whole.output;
    }
}

// ---- the check on hand-made sequences ----

platform::fw_event report(simtime::ticks tick, uint32_t kind, uint32_t pair = 0,
                          uint32_t value = 0) {
    platform::fw_event e;
    e.tick = tick;
    e.event.kind = kind;
    e.event.pair = pair;
    e.event.value = value;
    return e;
}

// Boot raise at 10, one pair captured in step, its frames named, processed
// with its result; a second raise at 100 reported as a re-arm.
faults::protocol_inputs complete_run() {
    faults::protocol_inputs in;
    in.window = 5;
    in.until = 1000;
    in.verdict_causes = 0xFFu;
    in.enable_writes = {{9, 1}, {95, 0}, {99, 1}};
    in.events = {report(10, STEREOSIM_EV_OE_RAISED, 0, 1),
                 report(20, STEREOSIM_EV_PAIR_CAPTURED, 1, 0),
                 report(21, STEREOSIM_EV_IN_STEP, 1),
                 report(22, STEREOSIM_EV_FRAMES_USED, 1),
                 report(30, STEREOSIM_EV_PAIR_PROCESSED, 1),
                 report(97, STEREOSIM_EV_CARD_REARMED, 0, STEREOSIM_REARM_OVERFLOW),
                 report(100, STEREOSIM_EV_OE_RAISED, 0, 2)};
    in.result_pairs = {1};
    return in;
}

std::string found(const faults::protocol_inputs& in) {
    std::string text;
    for (const faults::missing_report& m : faults::find_missing_reports(in))
        text += faults::violation_text(m) + "\n";
    return text;
}

TEST(ReportProtocol, ACompleteRunMissesNothing) {
    EXPECT_EQ(found(complete_run()), "");
    EXPECT_EQ(faults::in_step_unreported(complete_run()), 0);
}

TEST(ReportProtocol, ACapturedPairWithACauseBitMustBeRejected) {
    faults::protocol_inputs in = complete_run();
    in.events.push_back(report(40, STEREOSIM_EV_PAIR_CAPTURED, 2, 0x04u));  // L_DARK
    EXPECT_EQ(found(in),
              "rule 5: missing report PAIR_REJECTED: 1 captured pair(s) with a cause bit in "
              "VERDICT neither rejected nor processed (pairs 2)\n");
    in.events.push_back(report(41, STEREOSIM_EV_PAIR_REJECTED, 2, 0x04u));
    EXPECT_EQ(found(in), "");
}

TEST(ReportProtocol, AReArmOnTheBusNeedsItsReports) {
    faults::protocol_inputs in = complete_run();
    in.events.erase(in.events.begin() + 5, in.events.end());  // the re-arm's two reports
    EXPECT_EQ(found(in),
              "rule 6: missing report OE_RAISED: 1 raise(s) of ENABLE on the bus\n"
              "rule 11: missing report CARD_REARMED: 1 re-arm(s) (ENABLE 0 -> 1 after the "
              "first) on the bus\n");
    // A raise after `until` is not due yet.
    in.until = 98;
    EXPECT_EQ(found(in), "");
}

TEST(ReportProtocol, InStepIsJudgedByTheBusRaisesNotTheFirmwaresOwnReport) {
    faults::protocol_inputs in = complete_run();
    in.events.erase(in.events.begin() + 2);  // in_step
    EXPECT_EQ(faults::in_step_unreported(in), 1);
    in.events.erase(in.events.begin());  // oe_raised too: the raise is still on the bus
    EXPECT_EQ(faults::in_step_unreported(in), 1);
}

TEST(ReportProtocol, AWatchdogReArmNeedsTheWatchdogReport) {
    faults::protocol_inputs in = complete_run();
    in.events[5].event.value = STEREOSIM_REARM_WATCHDOG;
    EXPECT_EQ(found(in),
              "rule 11: missing report WATCHDOG: 1 re-arm(s) or give-up(s) for the watchdog\n");
    in.events.insert(in.events.begin() + 5, report(96, STEREOSIM_EV_WATCHDOG));
    EXPECT_EQ(found(in), "");
}

TEST(ReportProtocol, ALoopThatReturnsUnaskedSaysWhy) {
    faults::protocol_inputs in = complete_run();
    in.returned = 500;
    in.events.push_back(report(500, STEREOSIM_EV_STOPPED));
    EXPECT_EQ(found(in),
              "rule 4: missing report HARD_ERROR: 1 frame loop that returned unasked without "
              "saying why (no HARD_ERROR or CARD_MISSING)\n");
    in.events.push_back(report(499, STEREOSIM_EV_HARD_ERROR, 0, STEREOSIM_REARM_HARD_ERROR));
    EXPECT_EQ(found(in), "");
}

TEST(ReportProtocol, PairReportsComeTogether) {
    faults::protocol_inputs in = complete_run();
    in.result_pairs = {1, 2};
    in.unnamed_used_pairs = {3};
    in.events.push_back(report(50, STEREOSIM_EV_PAIR_PROCESSED, 4));
    EXPECT_EQ(found(in),
              "rule 7: missing report PAIR_CAPTURED: 1 pair(s) named by later reports but "
              "never reported captured (pairs 4)\n"
              "rule 7: missing report FRAMES_USED: 1 processed pair(s) whose frames were never "
              "named before pair_processed (pairs 3)\n"
              "rule 5: missing report PAIR_PROCESSED: 1 pair(s) with a result but no "
              "pair_processed (pairs 2)\n"
              "rule 5: missing report result: 1 pair(s) reported processed with no result "
              "(box, point, stage cycles) (pairs 4)\n");
}

}  // namespace
