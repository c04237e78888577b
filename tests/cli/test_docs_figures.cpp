// The figures the README and the docs quote from a run are that run's: the
// README's summary of `make demo` (the default scenario's 12 periods: capture
// per pair on the bus, the CPU's busiest period), and docs/waveforms.md's
// count of the signals in a waveform (the card's hierarchy, the pin trace,
// the fault marker) against a VCD a run writes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/shell.h"

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

std::string read_text(const std::string& path) {
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

// The text with every run of white space as one blank (quotes wrap lines).
std::string flat(const std::string& text) {
    return std::regex_replace(text, std::regex(R"(\s+)"), " ");
}

std::string one_decimal(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f", v);
    return text;
}

TEST(DocsFigures, TheReadmeQuotesTheDemo) {
    const std::string dir = testsupport::temp_dir("stereosim-test-readme");
    const testsupport::command_result r =
        testsupport::run_command("SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1 " STEREOSIM_BINARY
                                 " run --scenario default --quiet --out " +
                                 dir);
    ASSERT_LE(r.exit_code, 1) << r.output;
    const json timing = json::parse(read_text(dir + "/report.json"))["summary"]["timing"];
    const std::string readme = flat(read_text(std::string(STEREOSIM_SOURCE_DIR) + "/README.md"));
    std::smatch m;
    ASSERT_TRUE(std::regex_search(
        readme, m,
        std::regex(
            R"(capture ([0-9.]+) ms per pair on the bus, the CPU busy at most ([0-9.]+) ms)")))
        << "the README no longer quotes the demo's capture and CPU figures";
    EXPECT_EQ(m[1].str(), one_decimal(timing["capture_ms"]["max"].get<double>()))
        << "README.md: the demo's capture per pair";
    EXPECT_EQ(m[2].str(), one_decimal(timing["cpu_busy_ms_max"].get<double>()))
        << "README.md: the demo's busiest CPU period";
    fs::remove_all(dir);
}

// docs/faults.md: each sensor counts its own frames across OE restarts; with
// seed 3 the left sensor's frame 5 and the right one's start at the times it
// quotes (the timeline's VSYNC rises of each sensor, frame n the n-th after
// power-on, from 0).
TEST(DocsFigures, TheFaultsDocQuotesTheFrameNumbering) {
    const std::string dir = testsupport::temp_dir("stereosim-test-frames");
    const testsupport::command_result r =
        testsupport::run_command("SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1 " STEREOSIM_BINARY
                                 " run --frames 6 --seed 3 --quiet --out " +
                                 dir);
    ASSERT_LE(r.exit_code, 1) << r.output;
    const json timeline = json::parse(read_text(dir + "/timeline.json"));
    std::vector<double> vsync[2];
    for (const json& e : timeline["traceEvents"]) {
        const std::string name = e.value("name", "");
        if (name == "VSYNC L" || name == "VSYNC R")
            vsync[name == "VSYNC R"].push_back(e["ts"].get<double>() / 1000.0);
    }
    ASSERT_GT(vsync[0].size(), 5u);
    ASSERT_GT(vsync[1].size(), 5u);
    char quoted[160];
    std::snprintf(quoted, sizeof quoted,
                  "the left sensor's frame 5 starts at %.2f ms (the fifth after the restart), "
                  "the right one's at %.2f ms",
                  vsync[0][5], vsync[1][5]);
    const std::string doc = flat(read_text(std::string(STEREOSIM_SOURCE_DIR) + "/docs/faults.md"));
    EXPECT_NE(doc.find(quoted), std::string::npos) << "docs/faults.md should say: " << quoted;
    fs::remove_all(dir);
}

TEST(DocsFigures, TheWaveformDocCountsTheSignals) {
    const std::string dir = testsupport::temp_dir("stereosim-test-signals");
    const testsupport::command_result r = testsupport::run_command(
        "SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1 " STEREOSIM_BINARY
        " run --frames 1 --waves vcd --waves-from 0 --waves-to 0.1 --quiet --out " +
        dir);
    ASSERT_LE(r.exit_code, 1) << r.output;
    // Each $var of the file, by the scope it sits in.
    std::ifstream vcd(dir + "/waves/default.vcd");
    int card = 0, all = 0, marker = 0;
    std::vector<std::string> scopes;
    for (std::string line;
         std::getline(vcd, line) && line.find("$enddefinitions") == std::string::npos;) {
        std::istringstream words(line);
        std::string word, name;
        words >> word;
        if (word == "$scope") {
            words >> word >> name;
            scopes.push_back(name);
        } else if (word == "$upscope") {
            scopes.pop_back();
        } else if (word == "$var") {
            ++all;
            const bool in_card =
                std::find(scopes.begin(), scopes.end(), "card_top") != scopes.end();
            card += in_card;
            marker += !in_card && std::find(scopes.begin(), scopes.end(), "faults") != scopes.end();
        }
    }
    const std::string doc =
        flat(read_text(std::string(STEREOSIM_SOURCE_DIR) + "/docs/waveforms.md"));
    const std::string quoted = "(" + std::to_string(card) + " signals in the default build; " +
                               std::to_string(all) + " in the file with the pin trace's " +
                               std::to_string(all - card - marker) + " and the fault marker)";
    EXPECT_NE(doc.find(quoted), std::string::npos) << "docs/waveforms.md should say " << quoted;
    std::printf("waveform: %d signals, %d of the card, %d of the pin trace, %d marker\n", all, card,
                all - card - marker, marker);
    fs::remove_all(dir);
}

}  // namespace
