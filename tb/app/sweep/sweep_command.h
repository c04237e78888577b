// `stereosim sweep` (docs/sweep.md): a grid of config keys, every point a
// full co-simulation run in a child process (--jobs at a time), or with
// --screen the closed form over the whole grid and the co-simulation only
// near its boundary (and a sample of the rest). Writes sweep.json,
// sweep.csv, frontier.csv and fitmap.png into --out DIR; --shard K/M runs a
// deterministic slice, --emit-slurm writes a Slurm job array of the shards.
//
// Exit codes: 0 every point ran (over budget is a result), 2 bad input
// (nothing written), 3 a point's run failed.
#pragma once

#include <string>
#include <vector>

#include "tb/app/cli/slurm_job.h"

namespace CLI {
class App;
}

namespace sweep {

struct sweep_options {
    std::vector<std::string> grid;  // KEY=V1,V2,... | KEY=LO:HI:STEP
    std::string config_file;
    std::vector<std::string> sets;  // KEY=VALUE, under every point
    std::string firmware;           // the firmware under test (a plugin); empty: built in
    std::string frames;             // run.frames, empty: the config's
    int jobs = 2;
    std::string shard = "1/1";
    std::string out_dir;
    bool screen = false;
    int screen_sample = 10;          // co-simulate every Nth point away from the boundary
    double screen_margin_ms = 0.25;  // closed-form slack this close to 0 is "near"
    bool force = false;              // more than 10,000 points
    bool keep_runs = false;
    std::string resume;  // DIR of an interrupted sweep: run only the points it lacks
    cli::slurm_options slurm;
};

class sweep_command {
  public:
    explicit sweep_command(CLI::App& app);
    CLI::App* subcommand() const { return m_app; }
    int execute();

  private:
    CLI::App* m_app = nullptr;
    sweep_options m_options;
};

}  // namespace sweep
