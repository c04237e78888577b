// `stereosim run` (docs/cli.md): options -> config keys -> platform_config,
// one co-simulation, report.json / report.txt / frames.csv (and the extensions' files)
// staged and renamed into --out DIR, the summary on a terminal.
//
// Exit codes: 0 within budget, 1 over budget (a result, not an error),
// 2 bad input (nothing written), 3 the run failed (nothing written).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "tb/app/cli/run_outputs.h"

namespace CLI {
class App;
}

namespace cli {

enum exit_code : int {
    exit_within_budget = 0,
    exit_over_budget = 1,
    exit_bad_input = 2,
    exit_run_failed = 3,
    exit_contract_broken = 4  // a run with faults broke the fault contract: a result
};

struct run_options {
    std::string scenario;
    std::string config_file;
    std::string frames, seed, dsk, cpu_mhz, mode, replay, firmware;  // checked as config keys
    std::vector<std::string> sets;                                   // key=value
    std::string out_dir;
    bool quiet = false;
    bool force_progress = false;  // --progress: the progress line even off a terminal
    bool force_summary = false;   // --summary: the summary even off a terminal
};

class run_command {
  public:
    // Adds the `run` subcommand (and the extensions' options) to the app.
    // `extensions`: the run extensions in the order they run (run_outputs.h).
    run_command(CLI::App& app, std::vector<std::unique_ptr<run_extension>> extensions);
    CLI::App* subcommand() const { return m_run; }
    // Runs it after parsing; returns the exit code.
    int execute();
    // The run's setup and platform_config after parsing, the extensions
    // configured (faults added); false + *error (one line) for bad input.
    bool prepare(run_setup* setup, platform::platform_config* config, std::string* error);
    // Runs it after parsing as the continuation of `top`, a platform paused
    // at a fault campaign's snapshot that was built from the same options
    // without their faults (tb/app/faults/snapshots.h): the faults are added
    // to it, then the run goes on and reports exactly as execute() would.
    int execute_from_snapshot(platform::platform_top& top);

  private:
    // The run_setup of the options: config file or scenario, named options,
    // --set, then the checks across keys. false + *error is bad input.
    bool setup_from_options(run_setup* setup, std::string* error) const;
    // With --out: DIR and its staging folder, and the extensions' streams.
    bool open_out_dir(staged_files& files, std::string* error);
    // Builds and runs the platform (run_and_report); returns the exit code.
    int simulate(const run_setup& setup, const platform::platform_config& config,
                 staged_files& files);
    // Runs the built platform to its end, writes the outputs, prints the
    // summary; returns the exit code.
    int run_and_report(platform::platform_top& top, const run_setup& setup,
                       const platform::platform_config& config, staged_files& files);
    // Runs `body`; a std::exception (sc_report included) is "the simulation
    // failed", one line, exit 3.
    template <typename Body>
    int guarded(Body body);
    // frames.csv, report.txt, the extensions' files, report.json; then commit.
    bool write_outputs(const run_result& run, staged_files& files, std::string* error);

    CLI::App* m_run = nullptr;
    run_options m_options;
    std::vector<std::unique_ptr<run_extension>> m_extensions;
};

// Shown by `stereosim run` errors: "stereosim: error: <message>".
void print_error(const std::string& message);

}  // namespace cli
