// `--scenario paper` (docs/paper.md): the default run with the cost model's
// compiled-C factor 7. Its compute cycles are 7x the default's, its memory
// stalls are not, so every stage takes between ~4x and 7x the default's
// time; the CPU cannot keep up with the 24.5 ms period and the run is over
// budget, as the closed form says.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/support/shell.h"

namespace {

using nlohmann::json;

json run(const std::string& dir, const std::string& scenario, int expected_exit) {
    const auto r =
        testsupport::run_command(std::string(STEREOSIM_BINARY) + " run --quiet --frames 9 " +
                                 "--scenario " + scenario + " --out " + dir);
    EXPECT_EQ(r.exit_code, expected_exit) << r.output;
    std::ifstream in(dir + "/report.json");
    return json::parse(in, nullptr, false);
}

TEST(PaperScenario, CompiledCCostsUpToSevenTimesAndDoesNotFit) {
    const std::string dir = testsupport::temp_dir("paper");
    const json base = run(dir + "/default", "default", 0);
    const json paper = run(dir + "/paper", "paper", 1);
    ASSERT_TRUE(paper.is_object());
    EXPECT_EQ(paper["config"]["firmware"]["compiled_c_factor"], 7.0);
    EXPECT_EQ(paper["verdict"], "over_budget");
    ASSERT_FALSE(paper["overruns"].empty());
    EXPECT_EQ(paper["overruns"][0]["resource"], "pair_buffers");
    EXPECT_GT(paper["summary"]["timing"]["processing_ms_max"].get<double>(), 24.5);
    // preprocess and detect run on every pair in both runs.
    for (const char* stage : {"preprocess", "detect"}) {
        const double ratio = paper["summary"]["timing"]["stage_ms"][stage]["max"].get<double>() /
                             base["summary"]["timing"]["stage_ms"][stage]["max"].get<double>();
        EXPECT_GT(ratio, 4.0) << stage;
        EXPECT_LE(ratio, 7.0 + 1e-6) << stage;
    }
}

}  // namespace
