// The scoreboard's capture checks (data integrity at capture, rule 7's pair
// identity at the point of use) name a pair's frames by the pair's
// FRAME_READY, however late the firmware takes the pair. A CPU slowed six
// times from 52 ms (seed 13) takes pair 3 at 99.748 ms, while the sensors
// are in the first active line of their frame 4; that frame, with no last
// active pixel yet, was taken for the frame before pair 3's FRAME_READY
// (73.6 ms), so two intact pairs read as corrupt and rule 7 broke (the full
// campaign's cpu-slow + emif-wait row, forked from a snapshot at 48 ms).
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/support/shell.h"

namespace {

using nlohmann::json;

TEST(CaptureChecks, APairTakenLateIsCheckedAgainstItsOwnFrames) {
    const std::string dir = testsupport::temp_dir("capture-checks");
    ASSERT_FALSE(dir.empty());
    const testsupport::command_result r = testsupport::run_command(
        std::string(STEREOSIM_BINARY) +
        " run --quiet --seed 13 --frames 10 --fault cpu-slow:factor=6@ms=52 --out " + dir);
    ASSERT_EQ(r.exit_code, 1) << r.output;  // over budget: a result, the contract kept
    const json report = json::parse(testsupport::read_text(dir + "/report.json"));
    const json& data = report["summary"]["data_path"];
    EXPECT_GE(data["pairs_checked"].get<int>(), 5);
    EXPECT_EQ(data["pairs_intact"], data["pairs_checked"]);
    EXPECT_EQ(report["fault_run"]["identity_mismatches"], 0);
    EXPECT_EQ(report["fault_run"]["contract_ok"], true);
    std::filesystem::remove_all(dir);
}

}  // namespace
