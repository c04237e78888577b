// The seam where more outputs and options plug into `stereosim run`
// (docs/cli.md, "Extending run"): a waveform writer, the trajectory plot,
// the Chrome trace, fault injection. Each is a run_extension; the run command
// calls every extension of app::make_run_extensions() at these points, in order:
//
//   1. add_options(run)            while the command line is set up (CLI11)
//   2. configure(setup, config)    after parsing and the config keys, before the
//                                  platform is built: check the options (an error
//                                  is bad input: one line, exit 2, nothing
//                                  written) and change the platform_config
//                                  (attach a pin trace sink, add faults)
//   2b. open_outputs(files)        with --out DIR: DIR is opened (staging folder),
//                                  the platform not yet built (a streaming writer
//                                  such as the VCD opens its staged file here)
//   3. attach(top)                 the platform is built, not yet run
//   4. the simulation runs; score() and check_budget()
//   5. add_to_report(report, run)  add fields to report.json before it is written
//   6. write(run, files)           write files into the staging folder
//                                  (files.staged_path("waves/x.vcd")); all staged
//                                  files are renamed into --out DIR together only
//                                  when every writer succeeded, so a failed run
//                                  leaves nothing half written
//   7. summary_lines(run)          extra lines for the end summary (e.g. the
//                                  command that opens the waveform)
//   8. broken_verdict(run)         a verdict of the extension the run broke:
//                                  exit status 4 and one line on stderr
//
// Adding one: a class deriving from run_extension in your own file, and one
// line in app::make_run_extensions() (tb/app/run_extensions.cpp), which the
// program hands to run_command. Nothing registers itself statically (a
// static library would drop an unreferenced object).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "tb/app/cli/run_setup.h"
#include "tb/app/cli/staged_files.h"
#include "tb/platform/budget.h"
#include "tb/platform/platform.h"
#include "tb/platform/platform_config.h"
#include "tb/platform/scoreboard.h"

namespace CLI {
class App;
}

namespace cli {

// What a finished run gives the writers.
struct run_result {
    const run_setup& setup;
    const platform::platform_config& config;
    const platform::platform_top& top;
    const platform::scoreboard_report& score;
    const platform::budget_report& budget;
    const nlohmann::json& report;  // report.json as written (after add_to_report)
    std::string out_dir;           // --out DIR (final location), empty if none
};

class run_extension {
  public:
    virtual ~run_extension() = default;
    virtual void add_options(CLI::App& /*run*/) {}
    // Returns false and sets *error (one line) for bad input.
    virtual bool configure(const run_setup& /*setup*/, platform::platform_config& /*config*/,
                           std::string* /*error*/) {
        return true;
    }
    // Only called with --out DIR, after DIR was opened and before the
    // platform is built: a writer that streams during the run (the VCD)
    // takes its staged path here.
    virtual bool open_outputs(staged_files& /*files*/, std::string* /*error*/) { return true; }
    virtual void attach(platform::platform_top& /*top*/) {}
    virtual void add_to_report(nlohmann::json& /*report*/, const run_result& /*run*/) {}
    // Only called with --out DIR. Returns false and sets *error if a file
    // could not be written (the run then fails with exit 3, nothing renamed).
    virtual bool write(const run_result& /*run*/, staged_files& /*files*/, std::string* /*error*/) {
        return true;
    }
    virtual std::vector<std::string> summary_lines(const run_result& /*run*/) { return {}; }
    // A verdict of this extension the run broke (the fault contract), one
    // line; empty if none. The run then exits with exit_contract_broken and
    // says so on stderr, --quiet or not.
    virtual std::string broken_verdict(const run_result& /*run*/) { return ""; }
};

}  // namespace cli
